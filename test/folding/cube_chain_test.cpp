// The Fig. 8a sheet folded into a chain of cubes: the simulator (FCL self-collision) replays the
// CMML, and the final facet poses are checked against the unit cube, tile by tile.
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/folding/cube_chain.hpp"
#include "foldkit/simulation/simulate.hpp"

namespace {

using foldkit::geometry::build_or_throw;
using foldkit::geometry::CreasePattern;
using foldkit::folding::fold_cube_chain;

Eigen::Vector3d centre_of(const CreasePattern& p, int actor, const Eigen::Isometry3d& pose) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  int count = 0;
  for (const auto& t : p.actors()[static_cast<std::size_t>(actor)].triangles)
    for (int v : t.v) {
      const Eigen::Vector2d q = p.vertices()[static_cast<std::size_t>(v)];
      c += Eigen::Vector3d(q.x(), q.y(), 0.0);
      ++count;
    }
  return pose * (c / count);
}

void expect_chain_of_cubes(int cubes) {
  SCOPED_TRACE(std::to_string(cubes) + " cubes");
  const CreasePattern sheet = build_or_throw(foldkit::geometry::generators::cube_sheet(cubes));
  const auto sequence = fold_cube_chain(sheet, cubes);
  const auto report = foldkit::simulation::simulate(sheet, sequence);
  EXPECT_TRUE(report.status.ok()) << (report.problems.empty() ? std::string() : report.problems.front());
  EXPECT_EQ(report.collision_count, 0u);
  const auto poses = foldkit::geometry::facet_poses(sheet, foldkit::geometry::make_tree(sheet), report.final_state);
  std::vector<Eigen::Vector3d> centres;
  for (int n = 0; n < cubes; ++n) {
    // Six tiles round a unit cube: each tile's centre half a tile from the cube's centre along a
    // different signed axis, lying across that axis with its upper side toward the centre (the
    // net's hinges are valleys).
    std::array<Eigen::Vector3d, 6> c;
    Eigen::Vector3d mid = Eigen::Vector3d::Zero();
    for (int t = 0; t < 6; ++t) {
      c[static_cast<std::size_t>(t)] = centre_of(sheet, 6 * n + t, poses[static_cast<std::size_t>(6 * n + t)]);
      mid += c[static_cast<std::size_t>(t)] / 6.0;
    }
    std::array<bool, 6> seen{};
    for (int t = 0; t < 6; ++t) {
      const Eigen::Vector3d d = c[static_cast<std::size_t>(t)] - mid;
      Eigen::Index axis = 0;
      d.cwiseAbs().maxCoeff(&axis);
      EXPECT_NEAR(std::abs(d[axis]), 0.5, 1e-9);
      EXPECT_NEAR(d.norm(), 0.5, 1e-9);
      const std::size_t slot = static_cast<std::size_t>(2 * axis + (d[axis] > 0 ? 1 : 0));
      EXPECT_FALSE(seen[slot]) << "two tiles of net " << n << " on one face";
      seen[slot] = true;
      // The tile's normal lies along the axis of its offset (a face, not a fin), pointing in.
      const Eigen::Vector3d normal = poses[static_cast<std::size_t>(6 * n + t)].linear().col(2);
      EXPECT_NEAR(normal[axis] * (d[axis] > 0 ? -1.0 : 1.0), 1.0, 1e-9);
    }
    centres.push_back(mid);
  }
  // A straight line (Fig. 5a): cube k's centre is the first one's plus k unit steps along one
  // axis, so neighbours share a face and no two overlap.
  if (centres.size() < 2) return;
  const Eigen::Vector3d step = centres[1] - centres[0];
  EXPECT_NEAR(step.norm(), 1.0, 1e-9);
  EXPECT_NEAR(step.cwiseAbs().maxCoeff(), 1.0, 1e-9);
  for (std::size_t k = 0; k < centres.size(); ++k)
    EXPECT_LT((centres[k] - centres[0] - static_cast<double>(k) * step).norm(), 1e-9) << "cube " << k << " off the line";
}

TEST(CubeChain, TheSheetFoldsIntoAStraightLineOfClosedCubes) {
  for (int cubes : {1, 2, 3, 6}) expect_chain_of_cubes(cubes);
}

TEST(CubeChain, RefusesOtherSheetsCountsAndSpeeds) {
  const CreasePattern two = build_or_throw(foldkit::geometry::generators::cube_sheet(2));
  EXPECT_THROW(fold_cube_chain(two, 3), std::invalid_argument);
  EXPECT_THROW(fold_cube_chain(two, 2, 0.0), std::invalid_argument);
  EXPECT_THROW(fold_cube_chain(two, 0), std::invalid_argument);
  const CreasePattern strip = build_or_throw(foldkit::geometry::generators::strip(6));
  EXPECT_THROW(fold_cube_chain(strip, 1), std::invalid_argument);
}

}  // namespace
