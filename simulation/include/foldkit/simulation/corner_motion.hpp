#pragma once
/// @file
/// How far a folding sheet's facets move between two checks, up to a rigid motion of the whole.
#include <vector>

#include <Eigen/Geometry>

#include "foldkit/geometry/crease_pattern.hpp"

namespace foldkit::simulation {

/// The largest distance a facet corner moves between two placements of a sheet, measured in the
/// frame where it is (nearly) smallest. The simulator and the folder split a step into sub-steps
/// until this is at most their sweep bound (docs/SIMULATION.md, *What is checked, and when*).
///
/// Why another frame than the poses': what a check can miss depends only on how the facets move
/// relative to each other (a pair's distance changes by at most the sum of its two facets'
/// displacements, in any common frame), so a rigid motion of the whole sheet must not count. The
/// poses hang from one root facet, and folding a large sheet moves its far side round that root:
/// a Miura-ori 60×60 folding in place moved a corner up to 0.3 units per step in the root's frame
/// and 0.03–0.14 after aligning the sheet, so half of the simulator's checks were sub-steps that
/// only followed the root.
class CornerMotion {
 public:
  /// Collects every actor's corners (its triangles' vertices, flat, z = 0). Keeps no reference
  /// to `pattern`.
  explicit CornerMotion(const geometry::CreasePattern& pattern);

  /// The largest displacement of any corner from `from` to `to` (one pose per actor, as from
  /// geometry::facet_poses), in pattern units, after the rigid motion that best aligns the
  /// corners of `from` onto those of `to` (least squares, Kabsch); never more than the largest
  /// displacement between the poses as given.
  /// @throws std::invalid_argument when `from` or `to` does not hold one pose per actor
  double largest(const std::vector<Eigen::Isometry3d>& from, const std::vector<Eigen::Isometry3d>& to) const;

 private:
  // Every actor's corners in one array (flat), actor a's from first_[a] to first_[a + 1]: the
  // simulator asks at every step, over thousands of actors.
  std::vector<Eigen::Vector3d> corners_;
  std::vector<std::size_t> first_;
};

}  // namespace foldkit::simulation
