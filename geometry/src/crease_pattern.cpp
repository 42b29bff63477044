#include "foldkit/geometry/crease_pattern.hpp"

#include <Eigen/Geometry>

#include <algorithm>

namespace foldkit::geometry {

double CreasePattern::diagonal() const {
  Eigen::AlignedBox2d box;
  for (const Vec2& v : vertices_) box.extend(v);
  return box.diagonal().norm();
}

std::size_t CreasePattern::boundary_vertex_count() const {
  return static_cast<std::size_t>(std::count(on_boundary_.begin(), on_boundary_.end(), true));
}

std::optional<int> CreasePattern::actor_index(int id) const {
  auto it = actor_by_id_.find(id);
  if (it == actor_by_id_.end()) return std::nullopt;
  return it->second;
}

std::optional<int> CreasePattern::joint_index(int id) const {
  // Most patterns number their joints 1…n in order (every generator and foldkit's files): that
  // guess, checked (ids are unique), saves the hash lookup the simulator makes per fold and event.
  if (id >= 1 && static_cast<std::size_t>(id) <= joints_.size() && joints_[static_cast<std::size_t>(id) - 1].id == id) return id - 1;
  auto it = joint_by_id_.find(id);
  if (it == joint_by_id_.end()) return std::nullopt;
  return it->second;
}

PatternSpec CreasePattern::to_spec() const {
  PatternSpec spec;
  spec.title = title_;
  for (const Actor& a : actors_) {
    ActorSpec as{a.id, {}, a.line};
    for (const Triangle& t : a.triangles)
      as.triangles.push_back({{vertices_[t.v[0]], vertices_[t.v[1]], vertices_[t.v[2]]}, t.line});
    spec.actors.push_back(std::move(as));
  }
  for (const Joint& j : joints_)
    spec.joints.push_back({j.id,
                           {vertices_[j.v[0]], vertices_[j.v[1]]},
                           {actors_[j.actors[0]].id, actors_[j.actors[1]].id},
                           j.spring,
                           j.damping,
                           j.assignment,
                           j.line,
                           j.max_torque});
  spec.physics = physics_;
  return spec;
}

}  // namespace foldkit::geometry
