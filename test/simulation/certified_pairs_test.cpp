// Certified skips (CollisionOptions::certificates, detail::pair_budget) against oracles that share
// none of their code: the world that tests every pair at every check (the same crossings, points
// and depths along motions that cross, stack and fold closed), and each budget against the sides
// and triangle crossings recomputed directly after random motions within it.
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "../../simulation/src/facet_chain.hpp"
#include "../../simulation/src/pair_budget.hpp"
#include "../../simulation/src/triangle_crossing.hpp"
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

// Checks `path` with and without certificates; every check must find the same crossings.
std::size_t expect_same_checks(const CreasePattern& p, const std::vector<FoldState>& path, std::size_t* crossings) {
  const geometry::KinematicTree tree = geometry::make_tree(p);
  CollisionOptions every;
  every.margin = 0.05;
  every.certificates = false;
  CollisionOptions certified = every;
  certified.certificates = true;
  CollisionWorld slow(p, every), fast(p, certified);
  std::size_t skipped = 0;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const auto poses = geometry::facet_poses(p, tree, path[i]);
    const auto a = slow.check(poses, path[i]), b = fast.check(poses, path[i]);
    EXPECT_EQ(slow.certified_pairs(), 0u);
    skipped += fast.certified_pairs();
    EXPECT_EQ(slow.checked_pairs(), fast.checked_pairs()) << "step " << i;
    EXPECT_LE(fast.mesh_tests(), slow.mesh_tests()) << "step " << i;
    EXPECT_EQ(a.size(), b.size()) << "step " << i;
    if (a.size() != b.size()) return skipped;
    for (std::size_t c = 0; c < a.size(); ++c) {
      EXPECT_EQ(a[c].actors, b[c].actors) << "step " << i;
      EXPECT_EQ(a[c].kind, b[c].kind) << "step " << i;
      EXPECT_EQ(a[c].depth, b[c].depth) << "step " << i;
      EXPECT_EQ(a[c].point, b[c].point) << "step " << i;
    }
    *crossings += a.size();
  }
  return skipped;
}

std::vector<FoldState> straight(const FoldState& from, const FoldState& to, int steps) {
  std::vector<FoldState> path;
  for (int k = 0; k <= steps; ++k) path.push_back(FoldState{from.angles + (to.angles - from.angles) * (k / double(steps))});
  return path;
}

// Random motions of a grid (they cross) and of a degree-12 vertex (sectors pass through each
// other round their common vertex, where the budgets are angles).
TEST(CertifiedPairs, SameChecksOnRandomMotionsThatCross) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-3.0, 3.0);
  std::size_t crossings = 0, skipped = 0;
  const CreasePattern grid = build_or_throw(gen::grid(5, 5));
  const CreasePattern vertex = build_or_throw(gen::single_vertex(std::vector<double>(12, 2.0 * M_PI / 12.0)));
  for (const CreasePattern* p : {&grid, &vertex})
    for (int trial = 0; trial < 10; ++trial) {
      FoldState to = FoldState::flat(*p);
      for (Eigen::Index j = 0; j < to.angles.size(); ++j) to.angles[j] = angle(rng);
      skipped += expect_same_checks(*p, straight(FoldState::flat(*p), to, 60), &crossings);
    }
  EXPECT_GT(crossings, 50u);   // the motions do cross: the comparison is not vacuous
  EXPECT_GT(skipped, 1000u);   // and pairs were skipped
}

// A Miura-ori 12 × 12 along its closed motion to nearly flat (facets stack: the memory of sides),
// and a waterbomb 6 × 6 folded along its assignment until its bands cross (about 45°).
TEST(CertifiedPairs, SameChecksOnClosedFoldsAndAGenuineCrossing) {
  std::size_t crossings = 0, skipped = 0;
  const CreasePattern miura = build_or_throw(gen::miura(12, 12));
  const auto path = testing::closed_miura_path(miura, 0.02, 0.02, 3.1);
  skipped += expect_same_checks(miura, path, &crossings);
  EXPECT_EQ(crossings, 0u);
  const CreasePattern waterbomb = build_or_throw(gen::waterbomb(6, 6));
  FoldState to = FoldState::flat(waterbomb);
  for (std::size_t j = 0; j < waterbomb.joints().size(); ++j)
    to.angles[static_cast<Eigen::Index>(j)] = waterbomb.joints()[j].assignment == geometry::Assignment::Valley ? -1.2 : 1.2;
  skipped += expect_same_checks(waterbomb, straight(FoldState::flat(waterbomb), to, 120), &crossings);
  EXPECT_GT(crossings, 0u);
  EXPECT_GT(skipped, 10000u);
}

// Random motions between two random states (not from flat) on larger sheets, where the
// budgets' levers span several facets; states that are not finite in between, reset() and a
// recheck of one pair between checks must not leave a stale budget.
TEST(CertifiedPairs, SameChecksFromRandomStatesNaNsAndResets) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> angle(-3.0, 3.0);
  std::size_t crossings = 0, skipped = 0;
  const CreasePattern grid = build_or_throw(gen::grid(8, 8));
  const CreasePattern miura = build_or_throw(gen::miura(6, 6));
  for (const CreasePattern* p : {&grid, &miura})
    for (int trial = 0; trial < 60; ++trial) {
      FoldState from = FoldState::flat(*p), to = from;
      for (Eigen::Index j = 0; j < to.angles.size(); ++j) {
        from.angles[j] = angle(rng);
        to.angles[j] = angle(rng);
      }
      auto path = straight(from, to, 40);
      if (trial % 3 == 1) {  // a joint that is not a number at one state, then back
        FoldState broken = path[20];
        broken.angles[trial % broken.angles.size()] = std::numeric_limits<double>::quiet_NaN();
        path.insert(path.begin() + 21, broken);
      }
      skipped += expect_same_checks(*p, path, &crossings);
    }
  EXPECT_GT(crossings, 100u);
  EXPECT_GT(skipped, 10000u);
}

// With no touching distance, round-off at a shared corner (1e-16) decides: nothing is certified.
TEST(CertifiedPairs, NoCertificatesWithoutATolerance) {
  const CreasePattern miura = build_or_throw(gen::miura(6, 6));
  const auto path = testing::closed_miura_path(miura, 0.05, 0.05, 2.0);
  CollisionOptions o;
  o.tolerance = 0.0;
  o.margin = 0.05;
  CollisionWorld world(miura, o);
  const geometry::KinematicTree tree = geometry::make_tree(miura);
  for (const auto& s : path) {
    world.check(geometry::facet_poses(miura, tree, s), s);
    EXPECT_EQ(world.certified_pairs(), 0u);
  }
}

// A chain's levers bound how far each crease's turn moves the chain's last facet, seen from its
// first: on a strip (no loops, so the tree's poses are the chain's) turning one crease alone from a
// random state moves the last facet's corners by at most |Δθ| L_i.
TEST(PairBudget, LeversBoundEachCreasesTurn) {
  const CreasePattern strip = build_or_throw(gen::strip(9, 1.0, 0.6));
  const geometry::KinematicTree tree = geometry::make_tree(strip);
  std::vector<double> diameters;
  for (const auto& actor : strip.actors()) {
    double d = 0.0;
    for (const auto& t : actor.triangles)
      for (int u : t.v)
        for (const auto& t2 : actor.triangles)
          for (int w : t2.v) d = std::max(d, (strip.vertices()[u] - strip.vertices()[w]).norm());
    diameters.push_back(d);
  }
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> angle(-2.5, 2.5), small(-0.3, 0.3);
  double tightest = 0.0;
  for (int trial = 0; trial < 200; ++trial) {
    const int a = static_cast<int>(rng() % 9), b = static_cast<int>(rng() % 9);
    if (std::abs(a - b) < 2) continue;  // one crease apart: hinged, judged by its angle alone
    const std::vector<int> steps = detail::chain_steps(strip, a, b, 256);
    const detail::Levers levers = detail::chain_levers(strip, steps, diameters);
    ASSERT_EQ(levers.apex, -1);  // parallel creases share no vertex
    FoldState s = FoldState::flat(strip);
    for (Eigen::Index j = 0; j < s.angles.size(); ++j) s.angles[j] = angle(rng);
    const auto before = geometry::facet_poses(strip, tree, s);
    for (std::size_t i = 0; i < steps.size(); ++i) {
      FoldState t = s;
      const double turn = small(rng);
      t.angles[steps[i] >> 1] += turn;
      const auto after = geometry::facet_poses(strip, tree, t);
      const Eigen::Isometry3d r0 = before[a].inverse() * before[b], r1 = after[a].inverse() * after[b];
      for (const auto& tri : strip.actors()[b].triangles)
        for (int v : tri.v) {
          const Eigen::Vector3d p(strip.vertices()[v].x(), strip.vertices()[v].y(), 0.0);
          const double moved = (r1 * p - r0 * p).norm(), bound = std::abs(turn) * levers.weights[i];
          ASSERT_LE(moved, bound + 1e-12) << "pair " << a << "," << b << " step " << i;
          tightest = std::max(tightest, moved / bound);
        }
    }
  }
  EXPECT_GT(tightest, 0.5);  // the bound is not loose everywhere
}

// --- budgets against direct recomputation -------------------------------------------------------

int side_of(const std::vector<Eigen::Vector3d>& b, double tol) {
  double lo = 1e300, hi = -1e300;
  for (const auto& p : b) {
    lo = std::min(lo, p.z());
    hi = std::max(hi, p.z());
  }
  if (lo >= -tol && hi <= tol) return 0;
  if (lo >= -tol) return 1;
  if (hi <= tol) return -1;
  return 2;
}

Eigen::Vector3d random_unit(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
}

// Two triangles sharing a corner at the apex, b turned about it at random: any further turn about
// the apex by less than the budget leaves b on its side of a's plane and, across it, crossing none
// of a's triangles (triangles_cross); turns of 1.5 budgets change that for some pairs.
TEST(PairBudget, AngularBudgetsHoldAgainstRecomputedSidesAndCrossings) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0), c(-2.0, 2.0);
  const double tol = 1e-6;
  const Eigen::Vector3d apex(0.3, -0.2, 0.0);
  const std::vector<std::array<int, 3>> tri{{0, 1, 2}};
  int certified = 0, broken_beyond = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const std::vector<Eigen::Vector3d> a{apex, apex + Eigen::Vector3d(c(rng), c(rng), 0), apex + Eigen::Vector3d(c(rng), c(rng), 0)};
    const Eigen::Vector3d n = random_unit(rng), e1 = n.unitOrthogonal(), e2 = n.cross(e1);
    const std::vector<Eigen::Vector3d> b{apex, apex + c(rng) * e1 + c(rng) * e2, apex + c(rng) * e1 + c(rng) * e2};
    const int side = side_of(b, tol);
    if (side == 0) continue;
    detail::Heights ha, hb;
    const double budget = detail::pair_budget({a, tri, b, tri, n}, {&apex, tol}, side, ha, hb);
    if (side == 2 && detail::triangles_cross({a[0], a[1], a[2]}, {b[0], b[1], b[2]}, tol)) {
      EXPECT_EQ(budget, 0.0) << trial;
      continue;
    }
    if (budget <= 0.0) continue;
    ++certified;
    auto turned = [&](double angle) {
      const Eigen::AngleAxisd r(angle, random_unit(rng));
      std::vector<Eigen::Vector3d> moved;
      for (const auto& p : b) moved.push_back(apex + r * (p - apex));
      return moved;
    };
    for (int k = 0; k < 10; ++k) {
      const auto moved = turned(budget * u(rng) * 0.999);
      ASSERT_EQ(side_of(moved, tol), side) << trial;
      if (side == 2) {
        ASSERT_FALSE(detail::triangles_cross({a[0], a[1], a[2]}, {moved[0], moved[1], moved[2]}, tol)) << trial;
      }
    }
    for (int k = 0; k < 10; ++k) {
      const auto moved = turned(1.5 * budget + 0.01);
      if (side_of(moved, tol) != side || (side == 2 && detail::triangles_cross({a[0], a[1], a[2]}, {moved[0], moved[1], moved[2]}, tol))) {
        ++broken_beyond;
        break;
      }
    }
  }
  EXPECT_GT(certified, 1000);
  EXPECT_GT(broken_beyond, certified / 10);  // the budgets are not needlessly small
}

// Without an apex the budget is a length: moving b's points by less keeps its side; a pair across
// gets none (a's plane, seen from b, moves by a lever the budget does not know).
TEST(PairBudget, LinearBudgetsHoldAgainstRecomputedSides) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(0.0, 1.0), c(-2.0, 2.0);
  const double tol = 1e-6;
  const std::vector<std::array<int, 3>> tri{{0, 1, 2}};
  const std::vector<Eigen::Vector3d> a{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  int certified = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<Eigen::Vector3d> b{{c(rng), c(rng), c(rng)}, {c(rng), c(rng), c(rng)}, {c(rng), c(rng), c(rng)}};
    const Eigen::Vector3d n = (b[1] - b[0]).cross(b[2] - b[0]).normalized();
    const int side = side_of(b, tol);
    detail::Heights ha, hb;
    const double budget = detail::pair_budget({a, tri, b, tri, n}, {nullptr, tol}, side, ha, hb);
    if (side == 2 || side == 0) {
      EXPECT_EQ(budget, 0.0);
      continue;
    }
    ASSERT_GT(budget, 0.0);
    ++certified;
    for (int k = 0; k < 10; ++k) {
      std::vector<Eigen::Vector3d> moved = b;
      for (auto& p : moved) p += random_unit(rng) * budget * u(rng) * 0.999;
      ASSERT_EQ(side_of(moved, tol), side) << trial;
    }
  }
  EXPECT_GT(certified, 500);
}

}  // namespace
}  // namespace foldkit::simulation
