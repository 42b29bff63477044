#pragma once
#include <array>
#include <optional>

#include <Eigen/Core>

namespace foldkit::simulation::detail {

using Tri3 = std::array<Eigen::Vector3d, 3>;

struct TriangleCrossing {
  Eigen::Vector3d point;  // midpoint of the segment along which the triangles cut each other
  // How far the triangles interpenetrate: the smaller, over both triangles, of the shorter
  // distance by which its corners reach through the other's plane (the least push along one
  // normal that would leave it on one side).
  double depth = 0.0;
};

// Where two triangles truly cross: each has points strictly on both sides of the other's plane
// (farther than `tolerance`) and their cuts along the planes' common line overlap by more than
// `tolerance`. Triangles that only touch — at a shared corner, along a shared edge, an edge
// resting on a face, or coplanar (stacked flat) — do not cross. FCL 0.7 reports all of those as
// collisions (fcl#502) and gives no reliable contact for them (fcl#375), hence this test on the
// triangle pairs its narrow phase returns.
std::optional<TriangleCrossing> triangles_cross(const Tri3& a, const Tri3& b, double tolerance);

}  // namespace foldkit::simulation::detail
