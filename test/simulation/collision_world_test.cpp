#include <cmath>
#include <iostream>
#include <random>

#include <gtest/gtest.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/simulation/collision_world.hpp"
#include "spec_helpers.hpp"

namespace foldkit::simulation {
namespace {

namespace gen = geometry::generators;
using geometry::build_or_throw;
using geometry::CreasePattern;
using geometry::FoldState;
using Eigen::Isometry3d;
using Eigen::Vector3d;

// Two unit squares far apart and unconnected: actor 1 at the origin, actor 2 at x = 3. Poses put
// the second anywhere relative to the first.
CreasePattern two_loose_squares() {
  geometry::PatternSpec s;
  s.title = "loose";
  s.actors = {test::square_actor(1, 0, 0), test::square_actor(2, 3, 0)};
  return build_or_throw(s);
}

std::vector<Isometry3d> second_at(const Isometry3d& motion) {
  Isometry3d back = Isometry3d::Identity();
  back.translation() = Vector3d(-3, 0, 0);
  return {Isometry3d::Identity(), motion * back};
}

Isometry3d shift(double x, double y, double z) {
  Isometry3d m = Isometry3d::Identity();
  m.translation() = Vector3d(x, y, z);
  return m;
}

TEST(CollisionWorld, PassingStraightThroughIsAMeshCrossing) {
  const CreasePattern p = two_loose_squares();
  CollisionWorld world(p);
  const FoldState flat = FoldState::flat(p);
  // The second square stood upright (turned 90° about x) and pushed half-way through the first.
  Isometry3d upright = Isometry3d::Identity();
  upright.rotate(Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitX()));
  upright.pretranslate(Vector3d(0, 0.5, -0.5));
  const auto found = world.check(second_at(upright), flat);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].kind, CrossingKind::Mesh);
  EXPECT_EQ(found[0].actors, (std::array<int, 2>{0, 1}));
  EXPECT_NEAR(found[0].point.y(), 0.5, 1e-12);
  EXPECT_NEAR(found[0].point.z(), 0.0, 1e-12);
  // Half of each square reaches through the other's plane.
  EXPECT_NEAR(found[0].depth, 0.5, 1e-12);
  EXPECT_NEAR(world.mesh_crossing(1, 0, second_at(upright), flat)->depth, 0.5, 1e-12);
  // Standing on the face (its edge resting on it) is touching.
  upright.translation() = Vector3d(0, 0.5, 0);
  EXPECT_TRUE(world.check(second_at(upright), flat).empty());
  // Lying flat on it (coplanar, overlapping) is touching too.
  EXPECT_TRUE(world.check(second_at(shift(0.3, 0.2, 0)), flat).empty());
}

TEST(CollisionWorld, StackedFacetsChangingSidesCross) {
  const CreasePattern p = two_loose_squares();
  CollisionOptions o;
  o.margin = 0.05;
  CollisionWorld world(p, o);
  const FoldState flat = FoldState::flat(p);
  EXPECT_TRUE(world.check(second_at(shift(0.2, 0.1, 0.01)), flat).empty());
  const auto found = world.check(second_at(shift(0.2, 0.1, -0.01)), flat);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].kind, CrossingKind::Stacked);
  // Through an exactly coplanar check in between: still a crossing.
  world.reset();
  world.check(second_at(shift(0.2, 0.1, 0.01)), flat);
  EXPECT_TRUE(world.check(second_at(shift(0.2, 0.1, 0.0)), flat).empty());
  EXPECT_EQ(world.check(second_at(shift(0.2, 0.1, -0.01)), flat).size(), 1u);
  // Above, then beside (out of the other's shadow), then below: it went round, no crossing.
  world.reset();
  world.check(second_at(shift(0.2, 0.1, 0.01)), flat);
  EXPECT_TRUE(world.check(second_at(shift(1.02, 0.1, 0.0)), flat).empty());
  EXPECT_TRUE(world.check(second_at(shift(1.02, 0.1, -0.01)), flat).empty());
  EXPECT_TRUE(world.check(second_at(shift(0.2, 0.1, -0.01)), flat).empty());
}

TEST(CollisionWorld, CreaseTurnedPast180IsACrossing) {
  const CreasePattern strip = build_or_throw(gen::strip(2));
  CollisionWorld world(strip);
  const geometry::KinematicTree tree = geometry::make_tree(strip);
  FoldState s = FoldState::flat(strip);
  s.angles[0] = M_PI;
  EXPECT_TRUE(world.check(geometry::facet_poses(strip, tree, s), s).empty());
  s.angles[0] = M_PI + 0.01;
  const auto found = world.check(geometry::facet_poses(strip, tree, s), s);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].kind, CrossingKind::Crease);
  EXPECT_NEAR(found[0].point.x(), 1.0, 1e-12);
  EXPECT_EQ(world.skipped_pairs(), 1u);
}

// Facets around one vertex share it: they touch there always, and cross only where they overlap
// away from it. A degree-4 vertex folded along its mode never crosses; pushed one sector
// through its neighbour's neighbour, it does.
TEST(CollisionWorld, SharedVertexTouchesButDoesNotCross) {
  const double alpha = M_PI / 2, beta = M_PI / 2;
  const CreasePattern p = build_or_throw(gen::single_vertex({alpha, beta, M_PI - alpha, M_PI - beta}));
  CollisionWorld world(p);
  const geometry::KinematicTree tree = geometry::make_tree(p);
  for (double t : {0.5, 1.5, 3.0, M_PI}) {
    FoldState s = FoldState::flat(p);
    s.angles << t, 0, -t, 0;  // a plain cross folded along one line: two halves closing like a book
    EXPECT_TRUE(world.check(geometry::facet_poses(p, tree, s), s).empty()) << t;
  }
  // Fold all four creases the same way: opposite quadrants are pushed through each other.
  FoldState bad = FoldState::flat(p);
  bad.angles << 2.0, 2.0, 2.0, 2.0;
  world.reset();
  EXPECT_FALSE(world.check(geometry::facet_poses(p, tree, bad), bad).empty());
}

// The broad phase only prunes: the dynamic AABB tree and all pairs find the same crossings.
TEST(CollisionWorld, TreeAndAllPairsAgree) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-2.5, 2.5);
  const CreasePattern grid = build_or_throw(gen::grid(4, 4));
  const geometry::KinematicTree tree = geometry::make_tree(grid);
  CollisionOptions all;
  all.broad_phase = BroadPhase::AllPairs;
  CollisionWorld fast(grid), slow(grid, all);
  std::size_t crossings = 0;
  for (int trial = 0; trial < 40; ++trial) {
    FoldState s = FoldState::flat(grid);
    for (Eigen::Index j = 0; j < s.angles.size(); ++j) s.angles[j] = angle(rng);
    const auto poses = geometry::facet_poses(grid, tree, s);
    fast.reset();
    slow.reset();
    const auto a = fast.check(poses, s), b = slow.check(poses, s);
    ASSERT_EQ(a.size(), b.size()) << trial;
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].actors, b[i].actors);
      EXPECT_EQ(a[i].kind, b[i].kind);
    }
    crossings += a.size();
    EXPECT_LE(fast.checked_pairs(), slow.checked_pairs());
  }
  EXPECT_GT(crossings, 20u);  // random states of a grid do cross: the comparison is not vacuous
}

// A Miura-ori folded along its one-DOF mode (projected onto closure at each fraction) stays free
// of crossings all the way to nearly flat.
TEST(CollisionWorld, MiuraFoldsWithoutCrossing) {
  const CreasePattern miura = build_or_throw(gen::miura(5, 5));
  const geometry::ClosureSystem sys(miura);
  const geometry::KinematicTree tree = geometry::make_tree(miura);
  CollisionOptions o;
  o.margin = 0.05;
  CollisionWorld world(miura, o);
  FoldState s = FoldState::flat(miura);
  std::size_t pairs = 0, mesh = 0;
  for (double m = 0.1; m <= 2.9; m += 0.1) {
    FoldState rough = s;
    for (std::size_t j = 0; j < miura.joints().size(); ++j)
      rough.angles[static_cast<Eigen::Index>(j)] = miura.joints()[j].assignment == geometry::Assignment::Mountain ? m : -m;
    const auto r = geometry::project(sys, rough);
    ASSERT_TRUE(r.status.ok()) << m;
    s = r.state;
    const auto found = world.check(geometry::facet_poses(miura, tree, s), s);
    EXPECT_TRUE(found.empty()) << "fold " << m << ": actors " << (found.empty() ? 0 : found[0].actors[0]) << ","
                               << (found.empty() ? 0 : found[0].actors[1]);
    pairs += world.checked_pairs();
    mesh += world.mesh_tests();
  }
  // Not vacuous: neighbours were compared, and some of them went through the mesh test.
  EXPECT_GT(pairs, 1000u);
  EXPECT_GT(mesh, 0u);
  std::cout << "compared " << pairs << " pairs, " << mesh << " mesh tests\n";
}

TEST(CollisionWorld, RefusesMismatchedInput) {
  const CreasePattern strip = build_or_throw(gen::strip(2));
  CollisionWorld world(strip);
  EXPECT_THROW(world.check({Isometry3d::Identity()}, FoldState::flat(strip)), std::invalid_argument);
  CollisionOptions bad;
  bad.tolerance = -1;
  EXPECT_THROW(CollisionWorld(strip, bad), std::invalid_argument);
}

}  // namespace
}  // namespace foldkit::simulation
