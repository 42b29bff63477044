#include "foldkit/geometry/kinematics.hpp"

#include <deque>
#include <stdexcept>

#include "foldkit/geometry/so3.hpp"

namespace foldkit::geometry {
namespace {

Vec3 lift(const Vec2& p) { return Vec3(p.x(), p.y(), 0.0); }

}  // namespace

JointAxis joint_axis(const CreasePattern& pattern, int joint) {
  const Joint& j = pattern.joints()[joint];
  const Vec3 p = lift(pattern.vertices()[j.v[0]]);
  return {p, (lift(pattern.vertices()[j.v[1]]) - p).normalized()};
}

Eigen::Isometry3d joint_motion(const JointAxis& axis, double angle) {
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  m.linear() = so3::rotation(axis.direction, angle);
  m.translation() = axis.point - m.linear() * axis.point;
  return m;
}

double side_of(const CreasePattern& pattern, int joint, int actor) {
  const Joint& j = pattern.joints()[joint];
  const auto& V = pattern.vertices();
  const Vec2 a = V[j.v[0]];
  const Vec2 axis = V[j.v[1]] - a;
  const double length = axis.norm(), tol = 1e-9 * length;
  const Vec2 d = axis / length;
  auto across = [&](const Vec2& p) { return d.x() * (p - a).y() - d.y() * (p - a).x(); };  // > 0: left
  auto on_crease = [&](const Vec2& p) {
    const double along = d.dot(p - a);
    return std::abs(across(p)) <= tol && along >= -tol && along <= length + tol;
  };
  // The actor's triangle with an edge on the crease: its third corner tells the side, even for
  // an actor that reaches round to the other side of the crease line further away.
  for (const Triangle& t : pattern.actors()[actor].triangles)
    for (int k = 0; k < 3; ++k)
      if (on_crease(V[t.v[k]]) && on_crease(V[t.v[(k + 1) % 3]])) return across(V[t.v[(k + 2) % 3]]) > 0 ? -1.0 : 1.0;
  throw std::logic_error("side_of: actor " + std::to_string(pattern.actors()[actor].id) + " has no edge on joint " +
                         std::to_string(j.id));
}

KinematicTree make_tree(const CreasePattern& pattern, int root) {
  const int n = static_cast<int>(pattern.actors().size());
  if (root < 0 || root >= n) throw std::invalid_argument("make_tree: root actor index out of range");
  KinematicTree tree;
  tree.parent.assign(n, -1);
  tree.parent_joint.assign(n, -1);
  tree.side.assign(n, 1.0);
  tree.in_tree.assign(pattern.joints().size(), false);
  std::vector<bool> seen(n, false);
  const FacetGraph& g = pattern.facet_graph();
  const auto edge_index = boost::get(boost::edge_index, g);
  for (int start = -1; start < n; ++start) {
    const int r = start < 0 ? root : start;
    if (seen[r]) continue;
    seen[r] = true;
    std::deque<int> queue{r};
    while (!queue.empty()) {
      const int a = queue.front();
      queue.pop_front();
      tree.order.push_back(a);
      for (auto [e, end] = boost::out_edges(a, g); e != end; ++e) {
        const int b = static_cast<int>(boost::target(*e, g));
        if (seen[b]) continue;
        seen[b] = true;
        const int j = edge_index[*e];
        tree.parent[b] = a;
        tree.parent_joint[b] = j;
        tree.side[b] = side_of(pattern, j, b);
        tree.in_tree[j] = true;
        queue.push_back(b);
      }
    }
  }
  return tree;
}

std::vector<Eigen::Isometry3d> facet_poses(const CreasePattern& pattern, const KinematicTree& tree, const FoldState& state) {
  std::vector<Eigen::Isometry3d> pose(pattern.actors().size(), Eigen::Isometry3d::Identity());
  for (int a : tree.order) {
    const int j = tree.parent_joint[a];
    if (j < 0) continue;
    pose[a] = pose[tree.parent[a]] * joint_motion(joint_axis(pattern, j), tree.side[a] * state.angles[j]);
  }
  return pose;
}

}  // namespace foldkit::geometry
