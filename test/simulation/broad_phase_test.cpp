// The grid broad phase (BroadPhase::Grid, the default) against two oracles that share none of its
// code: every pair compared directly (boxes), and FCL's dynamic AABB tree (whole collision
// checks along motions, memory of sides included).
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "../../simulation/src/grid_broad_phase.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/simulation/collision_world.hpp"
#include "closed_miura_path.hpp"

namespace foldkit::simulation {
namespace {

namespace gen = geometry::generators;
using geometry::build_or_throw;
using geometry::CreasePattern;
using geometry::FoldState;

std::vector<std::pair<int, int>> every_overlapping_pair(const std::vector<Eigen::Vector3d>& lo,
                                                        const std::vector<Eigen::Vector3d>& hi) {
  std::vector<std::pair<int, int>> pairs;
  for (std::size_t a = 0; a < lo.size(); ++a)
    for (std::size_t b = a + 1; b < lo.size(); ++b) {
      bool apart = false;
      for (int k = 0; k < 3; ++k) apart = apart || lo[a][k] > hi[b][k] || lo[b][k] > hi[a][k];
      if (!apart) pairs.emplace_back(static_cast<int>(a), static_cast<int>(b));
    }
  return pairs;
}

// Boxes of mixed sizes (a few a hundred times the rest, some flat, some points), boxes that only
// touch, and boxes repeated exactly: the grid finds exactly the overlapping pairs, each once, sorted.
TEST(GridBroadPhase, FindsExactlyTheOverlappingPairs) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> where(-10.0, 10.0), size(0.0, 1.0);
  detail::GridBroadPhase grid;
  std::size_t total = 0;
  for (int trial = 0; trial < 30; ++trial) {
    const int n = 20 + 40 * trial;
    std::vector<Eigen::Vector3d> lo(n), hi(n);
    for (int i = 0; i < n; ++i) {
      lo[i] = Eigen::Vector3d(where(rng), where(rng), trial % 3 == 0 ? 0.0 : where(rng));
      Eigen::Vector3d extent(size(rng), size(rng), trial % 3 == 0 ? 0.0 : size(rng));
      if (i % 17 == 0) extent *= 100.0;
      if (i % 23 == 0) extent.setZero();
      hi[i] = lo[i] + extent;
      if (i % 19 == 1) {  // a copy of the previous box, or touching it face to face
        lo[i] = lo[i - 1];
        hi[i] = hi[i - 1];
        if (i % 2) {
          lo[i].x() = hi[i - 1].x();
          hi[i].x() = lo[i].x() + 1.0;
        }
      }
    }
    std::vector<std::pair<int, int>> found;
    grid.overlapping(lo, hi, found);
    const auto expected = every_overlapping_pair(lo, hi);
    ASSERT_EQ(found, expected) << "trial " << trial << ", " << n << " boxes";
    total += found.size();
  }
  EXPECT_GT(total, 1000u);  // not vacuous
}

// Along a motion, a world with the grid and one with FCL's tree keep the same pairs and find the
// same crossings, with the same points and depths, step after step (the memory of stacked pairs
// depends on which pairs each check sees, so equal candidate sets are what keeps it equal).
void expect_same_worlds_along(const CreasePattern& p, const std::vector<FoldState>& path, std::size_t* crossings) {
  const geometry::KinematicTree tree = geometry::make_tree(p);
  CollisionOptions tree_options;
  tree_options.broad_phase = BroadPhase::DynamicAabbTree;
  tree_options.margin = 0.05;
  CollisionOptions grid_options = tree_options;
  grid_options.broad_phase = BroadPhase::Grid;
  CollisionWorld by_grid(p, grid_options), by_tree(p, tree_options);
  for (std::size_t i = 0; i < path.size(); ++i) {
    const auto poses = geometry::facet_poses(p, tree, path[i]);
    const auto a = by_grid.check(poses, path[i]), b = by_tree.check(poses, path[i]);
    ASSERT_EQ(by_grid.checked_pairs(), by_tree.checked_pairs()) << "step " << i;
    ASSERT_EQ(a.size(), b.size()) << "step " << i;
    for (std::size_t c = 0; c < a.size(); ++c) {
      EXPECT_EQ(a[c].actors, b[c].actors);
      EXPECT_EQ(a[c].kind, b[c].kind);
      EXPECT_EQ(a[c].depth, b[c].depth);
      EXPECT_EQ(a[c].point, b[c].point);
    }
    *crossings += a.size();
  }
}

TEST(GridBroadPhase, SameChecksAsTheTreeOnRandomMotions) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> angle(-3.0, 3.0);
  const CreasePattern grid = build_or_throw(gen::grid(5, 5));
  std::size_t crossings = 0;
  for (int trial = 0; trial < 10; ++trial) {
    FoldState from = FoldState::flat(grid), to = FoldState::flat(grid);
    for (Eigen::Index j = 0; j < to.angles.size(); ++j) to.angles[j] = angle(rng);
    std::vector<FoldState> path;
    for (int k = 0; k <= 30; ++k) path.push_back(FoldState{from.angles + (to.angles - from.angles) * (k / 30.0)});
    expect_same_worlds_along(grid, path, &crossings);
  }
  EXPECT_GT(crossings, 50u);  // random motions of a grid do cross: the comparison is not vacuous
}

// A Miura-ori 12 × 12 folded along its closed one-DOF motion to nearly flat, where its facets
// stack: the broad phase keeps many pairs and the memory of sides is exercised.
TEST(GridBroadPhase, SameChecksAsTheTreeOnAClosedFold) {
  const CreasePattern miura = build_or_throw(gen::miura(12, 12));
  const auto path = testing::closed_miura_path(miura, 0.1, 0.05, 3.05);
  std::size_t crossings = 0;
  expect_same_worlds_along(miura, path, &crossings);
  EXPECT_EQ(crossings, 0u);
}

}  // namespace
}  // namespace foldkit::simulation
