#pragma once
// One facet of a CollisionWorld and the tests on a pair of them, in the first one's coordinates.
// Private to foldkit::simulation.
#include <array>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Geometry>
#include <fcl/narrowphase/collision_object.h>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/triangle_overlap.hpp"
#include "triangle_crossing.hpp"

namespace foldkit::simulation::detail {

/// FCL bounds a rotated object by the cube around its bounding sphere; a facet's own corners give
/// a much tighter box, which keeps the broad phase from pairing every neighbour of a folded sheet.
class FacetObject : public fcl::CollisionObjectd {
 public:
  using fcl::CollisionObjectd::CollisionObjectd;
  void set_box(const fcl::AABBd& box) { aabb = box; }  ///< the box the broad phase sees
};

/// An actor as the world tests it.
struct Facet {
  std::vector<Eigen::Vector3d> points;          ///< flat position (z = 0), the facet's own coordinates
  std::vector<std::array<int, 3>> triangles;    ///< into points
  std::vector<geometry::Tri2> flat;             ///< the triangles in the plane
  std::unique_ptr<FacetObject> object;          ///< for FCL's broad and narrow phases; user data: the actor
};

/// Builds actor `actor`'s facet.
Facet make_facet(const geometry::CreasePattern& pattern, int actor);

/// Where a facet lies relative to another's plane: wholly below or above it (touching within the
/// tolerance allowed), within the tolerance of it, or across it.
enum Side : int { Below = -1, On = 0, Above = 1, Across = 2 };

/// Where b lies relative to a's plane (z = 0); `rel` maps b's coordinates into a's.
Side side_of(const Facet& b, const Eigen::Isometry3d& rel, double tolerance);

/// Whether b's shadow on a's plane overlaps a by more than the tolerance.
bool overlap_in_plane(const Facet& a, const Facet& b, const Eigen::Isometry3d& rel, double tolerance);

/// Most triangle pairs deepest_crossing tests one by one rather than through FCL's BVH.
inline constexpr std::size_t kDirectTrianglePairs = 16;

/// The deepest crossing of a's and b's triangles, with b placed by `rel`, in a's coordinates.
/// Every crossing triangles_cross finds is one FCL reports (FCL reports touching pairs too:
/// fcl#502), so both ways find the same crossings; for small facets (a Miura parallelogram is two
/// triangles) every pair is tested directly, because FCL's collide() on two BVH models cost more in
/// setting up its traversal than the triangle tests themselves (a quarter of a check at Miura 40×40).
std::optional<TriangleCrossing> deepest_crossing(const Facet& a, const Facet& b, const Eigen::Isometry3d& rel, double tolerance);

}  // namespace foldkit::simulation::detail
