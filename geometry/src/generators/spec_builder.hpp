#pragma once
// Internal helpers shared by the generators: parameter checks, and a builder that numbers
// actors and joints from 1 in the order they are added.
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "foldkit/geometry/generators.hpp"

namespace foldkit::geometry::generators::detail {

[[noreturn]] inline void reject(const char* generator, const std::string& why) {
  throw std::invalid_argument(std::string(generator) + ": " + why);
}

inline void require_count(const char* generator, const char* name, int value, int minimum) {
  if (value < minimum)
    reject(generator, std::string(name) + " must be at least " + std::to_string(minimum) + " (got " +
                          std::to_string(value) + ")");
}

// `!(value > 0)` also catches NaN, which every ordered comparison lets through otherwise.
inline void require_positive(const char* generator, const char* name, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    std::ostringstream out;
    out << name << " must be positive and finite (got " << value << ")";
    reject(generator, out.str());
  }
}

inline void require_joint_defaults(const char* generator, const JointDefaults& j) {
  if (!(j.spring >= 0.0) || !std::isfinite(j.spring) || !(j.damping >= 0.0) || !std::isfinite(j.damping))
    reject(generator, "spring and damping must be finite and non-negative");
}

inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

class SpecBuilder {
 public:
  SpecBuilder(std::string title, JointDefaults defaults) : defaults_(defaults) { spec_.title = std::move(title); }

  // Adds the next actor as the fan of triangles from corners[0]; every corner must be visible
  // from corners[0] (true of convex polygons and of sectors fanned from their apex). Each
  // triangle is turned counter-clockwise, so callers may list corners either way round.
  int add_fan_actor(const std::vector<Vec2>& corners) {
    ActorSpec actor;
    actor.id = static_cast<int>(spec_.actors.size()) + 1;
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
      TriangleSpec t{{corners[0], corners[k], corners[k + 1]}, 0};
      if (cross(t.corners[1] - t.corners[0], t.corners[2] - t.corners[0]) < 0.0) std::swap(t.corners[1], t.corners[2]);
      actor.triangles.push_back(t);
    }
    spec_.actors.push_back(std::move(actor));
    return spec_.actors.back().id;
  }

  // Adds the next actor as a convex quadrilateral (corners in cyclic order) cut along its
  // shorter diagonal: skewed cells (Miura-ori at small angles) then keep their best-shaped pair.
  int add_quad_actor(const Vec2& p0, const Vec2& p1, const Vec2& p2, const Vec2& p3) {
    if ((p2 - p0).squaredNorm() <= (p3 - p1).squaredNorm()) return add_fan_actor({p0, p1, p2, p3});
    return add_fan_actor({p1, p2, p3, p0});
  }

  int add_joint(const Vec2& from, const Vec2& to, int actor_a, int actor_b, Assignment assignment = Assignment::Unassigned) {
    JointSpec joint;
    joint.id = static_cast<int>(spec_.joints.size()) + 1;
    joint.coords = {from, to};
    joint.actor_ids = {actor_a, actor_b};
    joint.spring = defaults_.spring;
    joint.damping = defaults_.damping;
    joint.assignment = assignment;
    spec_.joints.push_back(joint);
    return joint.id;
  }

  PatternSpec finish() && { return std::move(spec_); }

 private:
  PatternSpec spec_;
  JointDefaults defaults_;
};

// rows × cols quadrilateral cells whose lattice points are corner(i, j), i = 0..cols along the
// first lattice direction, j = 0..rows along the second. Cell (i, j) becomes actor
// j·cols + i + 1. Joints come first between cells side by side in a row, row by row from j = 0
// (rows·(cols − 1), on lattice line i within row j: column_crease(i, j) gives the assignment),
// then between cells of consecutive rows (cols·(rows − 1), on lattice line j within column i:
// row_crease(i, j)).
template <class Corner, class ColumnCrease, class RowCrease>
void add_quad_lattice(SpecBuilder& builder, int rows, int cols, Corner corner, ColumnCrease column_crease,
                      RowCrease row_crease) {
  auto actor = [cols](int i, int j) { return j * cols + i + 1; };
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < cols; ++i)
      builder.add_quad_actor(corner(i, j), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1));
  for (int j = 0; j < rows; ++j)
    for (int i = 1; i < cols; ++i)
      builder.add_joint(corner(i, j), corner(i, j + 1), actor(i - 1, j), actor(i, j), column_crease(i, j));
  for (int j = 1; j < rows; ++j)
    for (int i = 0; i < cols; ++i)
      builder.add_joint(corner(i, j), corner(i + 1, j), actor(i, j - 1), actor(i, j), row_crease(i, j));
}

}  // namespace foldkit::geometry::generators::detail
