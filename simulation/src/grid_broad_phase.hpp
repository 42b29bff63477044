#pragma once
// The broad phase of CollisionWorld by a uniform grid over the facets' boxes (BroadPhase::Grid).
// Private to foldkit::simulation.
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace foldkit::simulation::detail {

/// Finds every pair of axis-aligned boxes that overlap, touching included (the comparison FCL's
/// AABB::overlap makes, so the pairs are exactly those FCL's dynamic AABB tree reports). The boxes
/// go into a dense 3D grid of cells about as wide as the mean box; a pair is reported from the one
/// cell that holds the low corner of the boxes' intersection, so each pair once.
///
/// Hand-written rather than FCL's DynamicAABBTreeCollisionManager: a folding sheet's facets are
/// boxes of one size that move a little between checks, and the tree's update (a removal and
/// reinsertion per moved leaf), its traversal callbacks and the sort its unordered reports needed
/// were a quarter of a collision check at Miura 40×40 (docs/SIMULATION.md, *Collision cost*).
class GridBroadPhase {
 public:
  /// The pairs (a < b, sorted) of the boxes [lo[i], hi[i]] that overlap. Reuses its buffers
  /// between calls; not thread-safe.
  void overlapping(const std::vector<Eigen::Vector3d>& lo, const std::vector<Eigen::Vector3d>& hi,
                   std::vector<std::pair<int, int>>& pairs);

 private:
  std::vector<int> cell_start_, cell_members_, cell_fill_;
  std::vector<Eigen::Vector3i> first_, last_;  // per box: its cell range
  std::vector<int> per_first_, order_;         // counting sort of the pairs by first box
  std::vector<std::pair<int, int>> found_;
};

}  // namespace foldkit::simulation::detail
