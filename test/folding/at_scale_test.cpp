// Verdicts at the sizes users run (issue 15): the uniformly folded Miura-ori neither crosses
// itself nor bifurcates, whatever its size, its actors' numbering or the tree's root; genuine
// crossings are still found in sheets whose spanning tree is a thousand facets deep. Suites named
// AtScale run in the Release suite only (scripts/test-sanitizers.sh leaves them out).
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/geometry/mobility.hpp"
#include "foldkit/geometry/null_space.hpp"
#include "foldkit/geometry/projection.hpp"
#include "carpenter_inputs.hpp"
#include "foldkit/folding/carpenter.hpp"
#include "foldkit/folding/cube_chain.hpp"
#include "foldkit/folding/projected_folding.hpp"
#include "foldkit/simulation/collision_world.hpp"
#include "foldkit/simulation/simulate.hpp"

namespace foldkit {
namespace {

namespace gen = geometry::generators;
using geometry::CreasePattern;
using geometry::FoldState;

constexpr double kPi = 3.14159265358979323846;
constexpr double kSector = kPi / 3.0;  // the Miura generator's default parallelogram angle

CreasePattern miura(int n) { return geometry::build_or_throw(gen::miura(n, n)); }

// The uniform fold in closed form (NOTES.md): with the zig-zag creases at ρ_z, the straight ones
// at ρ_s, tan(ρ_s/2) = cos φ · tan(ρ_z/2). The generator's straight creases are the vertical
// lines x = i·a; signs from the assignment.
FoldState uniform_miura(const CreasePattern& p, double zigzag) {
  const double straight = 2.0 * std::atan(std::cos(kSector) * std::tan(zigzag / 2.0));
  FoldState s = FoldState::flat(p);
  for (std::size_t j = 0; j < p.joints().size(); ++j) {
    const auto& joint = p.joints()[j];
    const geometry::Vec2 d = p.vertices()[joint.v[1]] - p.vertices()[joint.v[0]];
    const bool vertical = std::abs(d.x()) < 1e-9 * d.norm();
    const double sign = joint.assignment == geometry::Assignment::Mountain ? 1.0 : -1.0;
    s.angles[static_cast<Eigen::Index>(j)] = sign * (vertical ? straight : zigzag);
  }
  return s;
}

// The closed form closes every vertex; the tests below rely on it.
TEST(AtScale, ClosedFormMiuraClosesEveryVertex) {
  const CreasePattern p = miura(12);
  const geometry::ClosureSystem sys(p);
  for (double deg : {10.0, 90.0, 170.0}) EXPECT_LT(sys.max_error(uniform_miura(p, deg * kPi / 180.0)), 1e-12) << deg;
}

std::vector<simulation::Crossing> crossings(const CreasePattern& p, const FoldState& s, int root = 0) {
  simulation::CollisionWorld world(p);
  return world.check(geometry::facet_poses(p, geometry::make_tree(p, root), s), s);
}

// Closed states and states between two of them (linear in the angles, as the simulator moves
// between events): about 1e-5 rad off closure, which a tree 200 facets deep opens into
// hundredths of a unit at its far end. Neither is a crossing, from either root.
TEST(AtScale, UniformMiura100x100NeverCrosses) {
  const CreasePattern p = miura(100);
  const geometry::ClosureSystem sys(p);
  const int far_corner = static_cast<int>(p.actors().size()) - 1;
  for (double deg : {60.0, 150.0, 171.0}) {
    const FoldState a = uniform_miura(p, deg * kPi / 180.0), b = uniform_miura(p, (deg + 1.8) * kPi / 180.0);
    const FoldState between{0.5 * (a.angles + b.angles)};
    EXPECT_GT(sys.max_error(between), 1e-7) << deg;
    for (int root : {0, far_corner}) {
      EXPECT_TRUE(crossings(p, a, root).empty()) << deg << " root " << root;
      EXPECT_TRUE(crossings(p, between, root).empty()) << deg << " between, root " << root;
    }
  }
}

// One degree of freedom once folded: creases − rank = 1 by singular values, at 40×40 and
// 100×100 (19,800 creases), with a clear gap. Both sparse methods give it (SuiteSparse QR with
// its certificate, the default, and the subspace iteration that decided it before); at 10×10 the
// subspace method agrees with the dense SVD.
TEST(AtScale, FoldedMiuraHasOneDegreeOfFreedom) {
  for (int n : {10, 40, 100}) {
    const CreasePattern p = miura(n);
    const geometry::ClosureSystem sys(p);
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> J;
    sys.evaluate(uniform_miura(p, 100.0 * kPi / 180.0), r, J);
    geometry::LeastNormSolver solver;
    const geometry::RankDecision qr = solver.decide_rank(J, 1e-4, 0);
    const geometry::RankDecision d =
        solver.decide_rank(J, 1e-4, 0, 0.0, geometry::SparseRankMethod::InverseSubspace);
    EXPECT_EQ(qr.method, "sparse-qr") << n;
    EXPECT_EQ(d.method, "inverse-subspace");
    EXPECT_EQ(qr.rank, d.rank) << n;
    EXPECT_EQ(d.nullity, 1) << n;
    EXPECT_EQ(d.rank, static_cast<int>(p.joints().size()) - 1) << n;
    EXPECT_GT(d.gap(), 1e3) << n << ": largest zero " << d.largest_zero << ", smallest kept " << d.smallest_kept;
    EXPECT_GT(qr.gap(), 1e3) << n;
    if (n == 10) {
      const geometry::RankDecision dense = solver.decide_rank(J, 1e-4, 1'000'000);
      EXPECT_EQ(dense.method, "dense-svd");
      EXPECT_EQ(dense.rank, d.rank);
      EXPECT_NEAR(dense.smallest_kept, d.smallest_kept, 1e-6 * dense.sigma_max);
    }
  }
}

// Flat, the Miura has many degrees of freedom: 2(n − 1) for n × n, one per crease line, which the
// dense SVD counts at 8 × 8 and 20 × 20 (checked here) and which holds at every size measured.
// `foldkit dof`'s sparse QR (the default) gives it up to 100 × 100 with a wide gap, and the
// subspace iteration (its block grows until it holds them all) agrees where it is quick.
TEST(AtScale, FlatMiuraNullityMatchesTheClosedForm) {
  for (int n : {8, 20, 40, 100}) {
    const CreasePattern p = miura(n);
    const geometry::ClosureSystem sys(p);
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> J;
    sys.evaluate(FoldState::flat(p), r, J);
    geometry::LeastNormSolver solver;
    const geometry::RankDecision qr = solver.decide_rank(J, 1e-8, 0);
    EXPECT_EQ(qr.method, "sparse-qr") << n;
    EXPECT_EQ(qr.nullity, 2 * (n - 1)) << n;
    EXPECT_GT(qr.gap(), 1e6) << n;
    if (n <= 40) {
      const geometry::RankDecision sparse =
          solver.decide_rank(J, 1e-8, 0, 0.0, geometry::SparseRankMethod::InverseSubspace);
      EXPECT_EQ(sparse.nullity, 2 * (n - 1)) << n;
    }
    if (n <= 20) {
      EXPECT_EQ(solver.decide_rank(J, 1e-8, 1'000'000).nullity, 2 * (n - 1)) << n;
    }
  }
}

// A 1,000-panel strip: a spanning tree 1,000 facets deep. Curled the same way at every crease,
// it runs into itself after four panels; as an accordion it never does.
TEST(AtScale, ThousandPanelStripCurledCrossesAccordionDoesNot) {
  const CreasePattern p = geometry::build_or_throw(gen::strip(1000));
  FoldState curled = FoldState::flat(p), accordion = FoldState::flat(p);
  for (Eigen::Index j = 0; j < curled.angles.size(); ++j) {
    curled.angles[j] = 100.0 * kPi / 180.0;
    accordion.angles[j] = (j % 2 ? 1.0 : -1.0) * 170.0 * kPi / 180.0;
  }
  const auto found = crossings(p, curled, 500);
  ASSERT_FALSE(found.empty());
  EXPECT_EQ(found.front().kind, simulation::CrossingKind::Mesh);
  EXPECT_GT(found.front().depth, 0.01);
  EXPECT_TRUE(crossings(p, accordion).empty());
  EXPECT_TRUE(crossings(p, accordion, 999).empty());
}

// The same sheet with its actors listed in another order (so other indices and another root of
// the simulator's tree) folds as far and replays with the same verdict.
TEST(AtScale, RenumberedActorsGiveTheSameVerdicts) {
  geometry::PatternSpec spec = gen::miura(14, 14);
  const CreasePattern p = geometry::build_or_throw(spec);
  std::mt19937 rng(7);
  std::shuffle(spec.actors.begin(), spec.actors.end(), rng);
  const CreasePattern q = geometry::build_or_throw(spec);
  ASSERT_NE(p.actors().front().id, q.actors().front().id);
  folding::ProjectedFoldingOptions o;
  o.target_fraction = 0.95;
  const auto a = folding::fold_projected(p, o), b = folding::fold_projected(q, o);
  EXPECT_EQ(a.status.code, geometry::StatusCode::Success) << a.status.message;
  EXPECT_EQ(b.status.code, a.status.code) << b.status.message;
  EXPECT_EQ(a.steps, b.steps);
  ASSERT_TRUE(a.replay && b.replay);
  EXPECT_TRUE(a.replay->status.ok());
  EXPECT_EQ(b.replay->status.ok(), a.replay->status.ok());
  EXPECT_EQ(b.replay->collision_count, a.replay->collision_count);
}

// `foldkit fold` of an n×n Miura to 0.95 with collisions on: reached, closed to 1e-10 at every
// step, one DOF with a clear singular-value gap, and the sequence replays valid with no collision.
// 40×40 stopped at 0.61 on a false crossing, 50×50 at 0.27 on a false rank drop, 60×60 at 0.52,
// and the 60×60 replay reported 161,124 collisions (issue 15).
void folds_to_095_and_replays_valid(int n) {
  const CreasePattern p = miura(n);
  folding::ProjectedFoldingOptions o;
  o.target_fraction = 0.95;
  const auto r = folding::fold_projected(p, o);
  EXPECT_EQ(r.status.code, geometry::StatusCode::Success) << n << ": " << r.status.message;
  EXPECT_NEAR(r.fraction, 0.95, 1e-9);
  EXPECT_LE(r.max_closure_error, 1e-10);
  EXPECT_EQ(r.dof, 1) << n;
  EXPECT_GT(r.min_rank_gap, 1e3) << n;
  ASSERT_TRUE(r.replay);
  EXPECT_TRUE(r.replay->status.ok()) << n << ": " << (r.replay->problems.empty() ? "" : r.replay->problems.front());
  EXPECT_EQ(r.replay->collision_count, 0u) << n;
}

TEST(AtScale, Miura40FoldsTo095AndReplaysValid) { folds_to_095_and_replays_valid(40); }
TEST(AtScale, Miura60FoldsTo095AndReplaysValid) { folds_to_095_and_replays_valid(60); }
TEST(AtScale, Miura100FoldsTo095AndReplaysValid) { folds_to_095_and_replays_valid(100); }

// An oracle that shares nothing with the collision world: two triangles, separating axes (both
// normals and the nine edge-by-edge directions). The smallest overlap over the axes is how far
// they interpenetrate; along a normal that is the smaller reach of the other triangle through the
// plane, the depth the simulator reports. ≤ 0: apart or touching.
double sat_overlap(const std::array<Eigen::Vector3d, 3>& a, const std::array<Eigen::Vector3d, 3>& b) {
  std::vector<Eigen::Vector3d> axes{(a[1] - a[0]).cross(a[2] - a[0]), (b[1] - b[0]).cross(b[2] - b[0])};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) axes.push_back((a[(i + 1) % 3] - a[i]).cross(b[(k + 1) % 3] - b[k]));
  double overlap = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& axis : axes) {
    if (axis.norm() < 1e-9) continue;
    const Eigen::Vector3d n = axis.normalized();
    double a_lo = 1e300, a_hi = -1e300, b_lo = 1e300, b_hi = -1e300;
    for (const auto& v : a) a_lo = std::min(a_lo, n.dot(v)), a_hi = std::max(a_hi, n.dot(v));
    for (const auto& v : b) b_lo = std::min(b_lo, n.dot(v)), b_hi = std::max(b_hi, n.dot(v));
    overlap = std::min(overlap, std::min(a_hi - b_lo, b_hi - a_lo));
  }
  return overlap;
}

// The deepest interpenetration of two actors' triangles at `s`, by forward kinematics and SAT.
double actor_overlap(const CreasePattern& p, const FoldState& s, int a, int b) {
  const auto poses = geometry::facet_poses(p, geometry::make_tree(p), s);
  auto corners = [&](int actor, const geometry::Triangle& t) {
    std::array<Eigen::Vector3d, 3> c;
    for (int i = 0; i < 3; ++i) {
      const geometry::Vec2 v = p.vertices()[t.v[i]];
      c[i] = poses[actor] * Eigen::Vector3d(v.x(), v.y(), 0.0);
    }
    return c;
  };
  double deepest = -std::numeric_limits<double>::infinity();
  for (const auto& ta : p.actors()[a].triangles)
    for (const auto& tb : p.actors()[b].triangles) deepest = std::max(deepest, sat_overlap(corners(a, ta), corners(b, tb)));
  return deepest;
}

// Waterbomb 20×20 (820 actors, 77 DOF): folding every crease along its assignment curls each band
// of triangles into a tube (40 diagonal creases of a band turn it by about 40·ρ·cos 45°), whose
// ends meet near 13°, every band's right end on the next band's left end. That is a genuine crossing: the next state, closed by projection,
// has the two ends of a band interpenetrating by the SAT oracle, and the path up to the stop
// replays valid (no false crossing on the way there).
TEST(AtScale, Waterbomb20CurlsIntoATubeWhoseEndsMeet) {
  const CreasePattern p = geometry::build_or_throw(gen::waterbomb(20, 20));
  folding::ProjectedFoldingOptions o;
  o.target_fraction = 0.95;
  const auto r = folding::fold_projected(p, o);
  ASSERT_EQ(r.status.code, geometry::StatusCode::Collision) << r.status.message;
  EXPECT_GT(r.fraction, 0.05);
  EXPECT_LT(r.fraction, 0.1);
  EXPECT_LE(r.max_closure_error, 1e-10);
  ASSERT_TRUE(r.replay);
  EXPECT_TRUE(r.replay->status.ok()) << (r.replay->problems.empty() ? "" : r.replay->problems.front());
  EXPECT_EQ(r.replay->collision_count, 0u);

  // One more step along the last one, as long as the lead-in's (0.01 rad: the steps a collision
  // is approached with), closed again.
  ASSERT_GE(r.states.size(), 2u);
  const FoldState& last = r.states.back();
  const Eigen::VectorXd along = last.angles - r.states[r.states.size() - 2].angles;
  const FoldState next{last.angles + (0.01 / along.cwiseAbs().maxCoeff()) * along};
  const geometry::ClosureSystem sys(p);
  const geometry::ProjectionResult closed = geometry::project(sys, next);
  ASSERT_TRUE(closed.status.ok()) << closed.status.message;
  simulation::CollisionWorld world(p);
  const auto found = world.check(geometry::facet_poses(p, geometry::make_tree(p), closed.state), closed.state);
  ASSERT_FALSE(found.empty());
  const int per_band = 41;
  for (const auto& c : found) {
    // The tube's seam: an end triangle of one band against the other end of the same band or
    // of the next (bands alternate, so the seam runs on a slant).
    const int t0 = c.actors[0] % per_band, t1 = c.actors[1] % per_band;
    EXPECT_LE(c.actors[1] / per_band - c.actors[0] / per_band, 1) << c.actors[0] << " " << c.actors[1];
    EXPECT_TRUE((t0 <= 2 && t1 >= 38) || (t0 >= 38 && t1 <= 2)) << c.actors[0] << " " << c.actors[1];
    EXPECT_GT(actor_overlap(p, closed.state, c.actors[0], c.actors[1]), 1e-5) << c.actors[0] << " " << c.actors[1];
  }
  // The last accepted state: the same ends are apart.
  for (const auto& c : found) EXPECT_LE(actor_overlap(p, last, c.actors[0], c.actors[1]), 1e-9);
}

// The cube sheet with 60 cubes (360 tiles, a tree 360 facets long): fold_cube_chain's CMML closes
// all 60 cubes in a line and replays valid with collisions on. Folding every crease at once along
// the assignment instead bends the 180-tile row until tiles far apart along it meet, at a few
// degrees: genuine, by the SAT oracle.
// The star-shaped 400-gon of microbench/bench_carpenter.cpp's Convexify/400 (carpenter_inputs.hpp)
// convexifies. It used to stall in one LP: Clp's warm-started primal simplex ran for over ten
// minutes on a degenerate basis; past twice the LP's size in iterations it now gives way to a
// fresh dual simplex (about a minute in all here).
TEST(AtScale, StarPolygonOfFourHundredVerticesConvexifies) {
  const int n = 400;
  const folding::Frame2 polygon = foldkit::microbench::random_star(n, 1);
  folding::CarpenterPlanarOptions options;
  options.frame_stride = 50;
  const auto r = folding::carpenter_planar({polygon, true}, options);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_LE(r.max_length_error, 1e-9);
  EXPECT_GE(r.min_distance_growth, -1e-8);  // the layouts' rounding (docs/CARPENTER.md), over 50 steps
  int left = 0, right = 0;
  const auto& last = r.frames.back();
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d d0 = last[static_cast<std::size_t>(i)] - last[static_cast<std::size_t>((i + n - 1) % n)];
    const Eigen::Vector2d d1 = last[static_cast<std::size_t>((i + 1) % n)] - last[static_cast<std::size_t>(i)];
    const double turn = d0.x() * d1.y() - d0.y() * d1.x();
    left += turn > 1e-9 * d0.norm() * d1.norm(), right += turn < -1e-9 * d0.norm() * d1.norm();
  }
  EXPECT_TRUE(left == 0 || right == 0) << left << " left turns, " << right << " right turns";
}

// The 1,000-link chain of bench_carpenter's Straighten/1000 (carpenter_inputs.hpp) straightens:
// bar lengths kept, no distance between any two vertices shrinking between recorded frames
// (check_motion recomputes both from the frames alone), straight at the end (about half a minute).
TEST(AtScale, ThousandLinkChainStraightensExpansively) {
  const folding::PlanarChain chain{foldkit::microbench::random_chain(1000, 1), false};
  folding::CarpenterPlanarOptions options;
  options.frame_stride = 50;
  const auto r = folding::carpenter_planar(chain, options);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_TRUE(folding::is_straight(r.frames.back()));
  const folding::MotionCheck check = folding::check_motion(r.frames, false);
  EXPECT_LE(check.max_length_error, 1e-9);
  EXPECT_GE(check.min_distance_growth, -1e-9);
  EXPECT_EQ(check.min_distance_growth, r.min_distance_growth);
  RecordProperty("steps", static_cast<int>(r.steps));
}

TEST(AtScale, CubeSheet60FoldsIntoALineOfCubesAndReplaysValid) {
  const int cubes = 60;
  const CreasePattern p = geometry::build_or_throw(gen::cube_sheet(cubes));
  const geometry::FoldSequence chain = folding::fold_cube_chain(p, cubes);
  const simulation::SimulationReport report = simulation::simulate(p, chain);
  EXPECT_TRUE(report.status.ok()) << (report.problems.empty() ? "" : report.problems.front());
  EXPECT_EQ(report.collision_count, 0u);
  EXPECT_EQ(report.events.size(), static_cast<std::size_t>(3 * cubes));

  folding::ProjectedFoldingOptions o;
  o.target_fraction = 0.95;
  const auto r = folding::fold_projected(p, o);
  ASSERT_EQ(r.status.code, geometry::StatusCode::Collision) << r.status.message;
  EXPECT_LT(r.fraction, 0.05);
  ASSERT_TRUE(r.replay);
  EXPECT_TRUE(r.replay->status.ok());
  const FoldState& last = r.states.back();
  const FoldState next{2.0 * last.angles - r.states[r.states.size() - 2].angles};
  simulation::CollisionWorld world(p);
  const auto found = world.check(geometry::facet_poses(p, geometry::make_tree(p), next), next);
  ASSERT_FALSE(found.empty());
  for (const auto& c : found) {
    EXPECT_GT(actor_overlap(p, next, c.actors[0], c.actors[1]), 1e-6) << c.actors[0] << " " << c.actors[1];
    EXPECT_LE(actor_overlap(p, last, c.actors[0], c.actors[1]), 1e-9) << c.actors[0] << " " << c.actors[1];
  }
}

// A 60×60 Miura with one row of panels folded the wrong way (the straight creases inside row 30
// turned to the other side): no rigid state of the sheet looks like that, since every vertex on
// the row's two zig-zag lines would have to open. The sequence that folds the uniform Miura to 60°
// (closed states 2° apart) replays valid; the same with a last event that turns that row the
// wrong way is invalid for closure, at that event.
TEST(AtScale, Miura60WithOneRowFoldedTheWrongWayIsInvalid) {
  const int n = 60, row = 30;
  const CreasePattern p = miura(n);
  std::vector<FoldState> path;
  for (int deg = 2; deg <= 60; deg += 2) path.push_back(uniform_miura(p, deg * kPi / 180.0));
  FoldState wrong = path.back();
  int flipped = 0;
  for (std::size_t j = 0; j < p.joints().size(); ++j) {
    const auto& a = p.joints()[j].actors;
    if (a[0] / n == row && a[1] / n == row) {
      wrong.angles[static_cast<Eigen::Index>(j)] *= -1.0;
      ++flipped;
    }
  }
  ASSERT_EQ(flipped, n - 1);
  const simulation::SimulationReport good = simulation::simulate(p, geometry::path_sequence(p, path, 1.0));
  EXPECT_TRUE(good.status.ok()) << (good.problems.empty() ? "" : good.problems.front());
  EXPECT_EQ(good.collision_count, 0u);
  EXPECT_LT(good.max_closure_error, 1e-3);
  path.push_back(wrong);
  const simulation::SimulationReport bad = simulation::simulate(p, geometry::path_sequence(p, path, 1.0));
  EXPECT_FALSE(bad.status.ok());
  ASSERT_EQ(bad.events.size(), path.size());
  EXPECT_LT(bad.events[path.size() - 2].max_closure_error, 1e-3);
  EXPECT_GT(bad.events.back().max_closure_error, 0.1);
  ASSERT_FALSE(bad.problems.empty());
  EXPECT_EQ(bad.problems.front().find("event " + std::to_string(path.size()) + ": closure error"), 0u) << bad.problems.front();
}

}  // namespace
}  // namespace foldkit
