// Plans end to end: every accepted plan is replayed by the simulator (the oracle), and its
// waypoints are closed by geometry::ClosureSystem.
#include <cmath>
#include <optional>
#include <random>

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>
#include <ompl/util/RandomNumbers.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/closure_path.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/geometry/mobility.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/planners/plan.hpp"
#include "foldkit/planners/plan_setup.hpp"
#include "foldkit/planners/planner_factory.hpp"
#include "foldkit/simulation/collision_world.hpp"
#include "foldkit/statespaces/single_vertex_space.hpp"
#include "foldkit/statespaces/validity.hpp"
#include "folded_state.hpp"
#include "spec_helpers.hpp"

namespace {

namespace ob = ompl::base;
namespace gen = foldkit::geometry::generators;
using foldkit::geometry::build_or_throw;
using foldkit::geometry::ClosureSystem;
using foldkit::geometry::CreasePattern;
using foldkit::geometry::FoldState;
using foldkit::planners::plan;
using foldkit::planners::PlanOptions;
using foldkit::planners::PlanResult;
using foldkit::planners::SpaceKind;
using foldkit::test::folded_along_assignment;

// A random closed folded goal (active angles within `max_angle` of flat) that is reachable: the
// straight way from flat in the active angles is closed and, when asked, collision-free.
FoldState random_goal(const CreasePattern& p, unsigned seed, bool collision_free, double max_angle = 2.0) {
  using namespace foldkit::statespaces;
  ompl::RNG::setSeed(seed);
  auto space = std::make_shared<SingleVertexStateSpace>(std::make_shared<SingleVertexChain>(p), AngleBounds::of(p, false));
  auto sampler = space->allocDefaultStateSampler();
  auto si = std::make_shared<ob::SpaceInformation>(space);
  auto validity = std::make_shared<FoldValidity>(p, AngleBounds::of(p, false), collision_free);
  si->setStateValidityChecker(std::make_shared<FoldValidityChecker>(si, validity, single_vertex_reader(space)));
  FoldMotionValidator motion(si, validity, single_vertex_reader(space));
  ob::ScopedState<> s(space), flat(space);
  space->from_fold_state(FoldState::flat(p), flat.get());
  foldkit::simulation::CollisionWorld world(p);
  const auto tree = foldkit::geometry::make_tree(p);
  for (int k = 0; k < 10000; ++k) {
    sampler->sampleUniformNear(s.get(), flat.get(), max_angle);
    if (!s->as<SingleVertexStateSpace::StateType>()->closed) continue;
    const FoldState f = space->to_fold_state(s.get());
    if (f.angles.cwiseAbs().maxCoeff() > max_angle || f.angles.cwiseAbs().maxCoeff() < 0.5) continue;
    world.reset();
    if (collision_free && !world.check(foldkit::geometry::facet_poses(p, tree, f), f).empty()) continue;
    if (!motion.checkMotion(flat.get(), s.get())) continue;  // reachable: the straight way is free
    return f;
  }
  throw std::runtime_error("no goal");
}

void expect_valid_plan(const CreasePattern& p, const FoldState& goal, const PlanResult& r) {
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_TRUE(r.replay.has_value());
  EXPECT_TRUE(r.replay->status.ok());
  EXPECT_LT(r.replay->max_closure_error, 1e-3);
  EXPECT_TRUE(r.replay->collisions.empty());
  const ClosureSystem sys(p);
  for (const FoldState& w : r.waypoints) EXPECT_LT(sys.max_error(w), 1e-6);
  EXPECT_LT((r.waypoints.back().angles - goal.angles).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LT(r.waypoints.front().angles.cwiseAbs().maxCoeff(), 1e-12);  // flat start
}

TEST(Plan, SingleVerticesOfDegree4To12FromFlatWithAndWithoutCollision) {
  std::mt19937 rng(2024);
  for (int n = 4; n <= 12; ++n) {
    const CreasePattern p = build_or_throw(gen::single_vertex(foldkit::test::random_sectors(n, rng, 0.2)));
    for (bool collisions : {false, true}) {
      PlanOptions req;
      FoldState goal = random_goal(p, static_cast<unsigned>(100 + n), collisions);
      req.space = SpaceKind::SingleVertex;
      req.time = 2.0;
      req.seed = static_cast<unsigned>(n);
      req.collisions = collisions;
      const PlanResult r = plan(p, goal, req);
      SCOPED_TRACE("degree " + std::to_string(n) + (collisions ? " with collision" : ""));
      expect_valid_plan(p, goal, r);
    }
  }
}

// PRM and PRM* grow their roadmap in a second thread and check states from both at once; with
// collisions on, every check shares one FoldValidity (scripts/test-tsan.sh runs this under
// ThreadSanitizer).
TEST(Plan, ThreadedPlannersWithCollisions) {
  std::mt19937 rng(7);
  const CreasePattern p = build_or_throw(gen::single_vertex(foldkit::test::random_sectors(6, rng, 0.2)));
  for (const char* planner : {"PRM", "PRMstar"}) {
    PlanOptions req;
    FoldState goal = random_goal(p, 11, true);
    req.space = SpaceKind::SingleVertex;
    req.planner = planner;
    req.time = 1.0;
    req.seed = 5;
    req.collisions = true;
    const PlanResult r = plan(p, goal, req);
    SCOPED_TRACE(planner);
    expect_valid_plan(p, goal, r);
  }
}

}  // namespace

namespace {

FoldState projected_goal(const CreasePattern& p, const Eigen::VectorXd& guess) {
  foldkit::geometry::ProjectionOptions po;
  po.tolerance = 1e-12;
  const auto r = foldkit::geometry::project(ClosureSystem(p), FoldState{guess}, po);
  EXPECT_TRUE(r.status.ok());
  return r.state;
}

FoldState boat_goal(const CreasePattern& p) {
  // Keel folded (mountain), bow and stern diagonals valley: the boat of Fig. 3b, a little open.
  Eigen::VectorXd g(10);
  g << 0.9, 0.9, 0.9, 0.9, -0.5, 0.5, 0.0, 0.0, 0.5, -0.5;
  return projected_goal(p, g);
}

void plan_and_check(const CreasePattern& p, const FoldState& goal, SpaceKind kind, bool collisions, double time = 2.0,
                      unsigned int seed = 3) {
  PlanOptions req;
  req.space = kind;
  req.time = time;
  req.seed = seed;
  req.collisions = collisions;
  req.use_assignment = false;
  const PlanResult r = plan(p, goal, req);
  SCOPED_TRACE(std::string("space ") + foldkit::planners::to_string(kind));
  expect_valid_plan(p, goal, r);
}

TEST(Plan, BoatThroughTheConstrainedSpaces) {
  const CreasePattern p = build_or_throw(gen::boat());
  const FoldState goal = boat_goal(p);
  ASSERT_LT(ClosureSystem(p).max_error(goal), 1e-10);
  for (SpaceKind kind : {SpaceKind::Projected, SpaceKind::Atlas, SpaceKind::TangentBundle}) plan_and_check(p, goal, kind, true);
}

// 1 DOF in 24 creases: uniform samples of the whole [0, π] / [−π, 0] box project onto the many
// other branches of the closure variety through flat, and RRTConnect on the Projected space then
// never heads for the goal (no plan in 5 s); sampling the box around start and goal widened by
// 0.2 rad (PlanOptions::search_margin) solves in well under a second. Atlas samples near its
// charts and solves either way; TangentBundle fails now and then without the margin. The goal is on the rigid-folding mode: the
// assignment's direction projected onto closure.
TEST(Plan, Miura4x4ThroughTheConstrainedSpaces) {
  const CreasePattern p = build_or_throw(gen::miura(4, 4));
  Eigen::VectorXd g(static_cast<Eigen::Index>(p.joints().size()));
  for (std::size_t j = 0; j < p.joints().size(); ++j)
    g[static_cast<Eigen::Index>(j)] = p.joints()[j].assignment == foldkit::geometry::Assignment::Mountain ? 0.6 : -0.6;
  const FoldState goal = projected_goal(p, g);
  ASSERT_LT(ClosureSystem(p).max_error(goal), 1e-10);
  for (SpaceKind kind : {SpaceKind::Projected, SpaceKind::Atlas, SpaceKind::TangentBundle}) {
    PlanOptions req;
    req.space = kind;
    req.time = 10.0;  // generous for sanitizer builds; a plan takes well under a second in Release
    req.seed = 3;
    req.collisions = true;
    req.use_assignment = true;  // the generator's M/V become bounds
    req.search_margin = 0.2;
    const PlanResult r = plan(p, goal, req);
    SCOPED_TRACE(std::string("space ") + foldkit::planners::to_string(kind));
    expect_valid_plan(p, goal, r);
    // Every waypoint keeps the assignment (the bounds), as the oracle reads it off the pattern.
    for (const FoldState& w : r.waypoints)
      for (std::size_t j = 0; j < p.joints().size(); ++j) {
        const double a = w.angles[static_cast<Eigen::Index>(j)];
        if (p.joints()[j].assignment == foldkit::geometry::Assignment::Mountain) {
          EXPECT_GE(a, -1e-9);
        }
        if (p.joints()[j].assignment == foldkit::geometry::Assignment::Valley) {
          EXPECT_LE(a, 1e-9);
        }
      }
  }
}

}  // namespace

namespace {

// The corner cube (paper Fig. 4): a degree-5 vertex with sectors 90°, 90°, 90°, 45°, 45°. Its
// three quadrants close into a cube corner (creases 2 and 3 at −90°) while the fourth quadrant,
// split by its diagonal, folds shut into a flap (creases 1 and 4 at ≈ 45°, the diagonal at ≈ −180°).
// The exact corner is singular (the flap shut: creases 1 and 4 then only fix their sum), so the goal
// stops 0.01 rad short of it, approached from the side where no facets cross.
TEST(Plan, CornerCubeFromFlatInTheSingleVertexAndProjectedSpaces) {
  const double h = M_PI / 2, q = M_PI / 4;
  const CreasePattern p = build_or_throw(gen::single_vertex({h, h, h, q, q}));
  Eigen::VectorXd guess(5);
  guess << 0.778, -h + 0.01, -h + 0.01, 0.778, -M_PI + 0.02;
  const FoldState goal = projected_goal(p, guess);
  ASSERT_LT(ClosureSystem(p).max_error(goal), 1e-10);
  // The goal is a cube corner to within a degree: quadrant normals pairwise perpendicular, the
  // flap's two halves facing each other.
  const auto poses = foldkit::geometry::facet_poses(p, foldkit::geometry::make_tree(p), goal);
  ASSERT_EQ(poses.size(), 5u);
  const auto normal = [&](int a) -> Eigen::Vector3d { return poses[static_cast<std::size_t>(a)].rotation().col(2); };
  EXPECT_LT(std::abs(normal(0).dot(normal(1))), 0.02);
  EXPECT_LT(std::abs(normal(1).dot(normal(2))), 0.02);
  EXPECT_LT(std::abs(normal(0).dot(normal(2))), 0.02);
  EXPECT_LT(normal(3).dot(normal(4)), -0.99);
  for (SpaceKind kind : {SpaceKind::SingleVertex, SpaceKind::Projected}) plan_and_check(p, goal, kind, true, 5.0, 4);
}

}  // namespace

namespace {

// Issue 16's failure: Miura sheets from flat to a folded goal, default options (no search
// margin), were not planned in 120 s in the Projected space. The auto space is now the
// driving-crease one (1 coordinate): every waypoint closed to 1e-10, the replay valid with
// collisions on, the assignment kept.
TEST(Plan, MiuraSheetsInTheDrivingSpaceWithDefaultOptions) {
  for (int n : {4, 6, 10}) {
    SCOPED_TRACE("Miura " + std::to_string(n));
    const CreasePattern p = build_or_throw(gen::miura(n, n));
    PlanOptions req;
    FoldState goal = folded_along_assignment(p, 1.2);
    req.time = 20.0;  // generous for sanitizer builds; well under a second in Release
    req.seed = 3;
    const PlanResult r = plan(p, goal, req);
    EXPECT_EQ(r.space, "driving");
    expect_valid_plan(p, goal, r);
    const ClosureSystem sys(p);
    for (const FoldState& w : r.waypoints) EXPECT_LE(sys.max_error(w), 1e-10);
    const auto bounds = foldkit::statespaces::AngleBounds::of(p, true);
    for (const FoldState& w : r.waypoints) EXPECT_TRUE(bounds.contains(w, 1e-9));
  }
}

// Planner parameters through OMPL's ParamSet: applied (a tiny range means many more states),
// and an unknown one refused with the names the planner has.
TEST(Plan, PlannerParametersByName) {
  const CreasePattern p = build_or_throw(gen::miura(4, 4));
  PlanOptions req;
  FoldState goal = folded_along_assignment(p, 1.0);
  req.time = 20.0;
  req.replay = false;
  req.simplify = false;
  req.params = {{"range", "0.01"}};
  const PlanResult small = plan(p, goal, req);
  ASSERT_TRUE(small.status.ok()) << small.status.message;
  req.params = {{"nonsense", "1"}};
  try {
    plan(p, goal, req);
    ADD_FAILURE() << "an unknown parameter was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("range"), std::string::npos) << e.what();
  }
  EXPECT_THROW(foldkit::planners::parse_planner_param("range"), std::invalid_argument);
  EXPECT_THROW(foldkit::planners::parse_planner_param("=0.3"), std::invalid_argument);
  EXPECT_EQ(foldkit::planners::parse_planner_param("range=0.3"), std::make_pair(std::string("range"), std::string("0.3")));
  EXPECT_THROW(foldkit::planners::check_planner_params("RRTConnect", {{"range", "fast"}}), std::invalid_argument);
  EXPECT_NO_THROW(foldkit::planners::check_planner_params("KPIECE1", {{"range", "0.2"}, {"border_fraction", "0.8"}}));
}

}  // namespace

namespace {

// Start anywhere (issue 16, item 2) in the driving space: flat → A, then A → B (folded further)
// and B → C (unfolded part way), each plan continuing the previous one's CMML; every replay valid,
// every waypoint closed.
TEST(Plan, DrivingSpaceFromOneFoldedStateToAnother) {
  const CreasePattern p = build_or_throw(gen::miura(6, 6));
  const ClosureSystem sys(p);
  PlanOptions req;
  req.time = 20.0;
  req.seed = 2;
  FoldState goal = folded_along_assignment(p, 0.6);
  const PlanResult first = plan(p, goal, req);
  ASSERT_TRUE(first.status.ok()) << first.status.message;
  foldkit::geometry::FoldSequence so_far = first.sequence;
  FoldState at = first.waypoints.back();
  for (double next : {1.4, 0.3}) {
    SCOPED_TRACE(next);
    req.start = at;
    req.start_sequence = so_far;
    goal = folded_along_assignment(p, next);
    // Along the start's own branch: a direct path exists, so the planner keeps all of its time
    // (no way through flat after a quarter of it).
    EXPECT_TRUE(foldkit::planners::make_plan_setup(p, goal, req).continues_to_goal);
    const PlanResult r = plan(p, goal, req);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    EXPECT_FALSE(r.via_flat);
    EXPECT_EQ(r.space, "driving");
    ASSERT_TRUE(r.replay && r.replay->status.ok());
    EXPECT_LT((r.waypoints.front().angles - at.angles).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_LT((r.waypoints.back().angles - goal.angles).cwiseAbs().maxCoeff(), 1e-6);
    for (const FoldState& w : r.waypoints) EXPECT_LE(sys.max_error(w), 1e-10);
    so_far = r.sequence;
    at = r.waypoints.back();
  }
}

}  // namespace

namespace {

// Issue 16, item 2: a 1-DOF Miura sheet folded along its assignment (branch A) and a goal on
// another branch B through flat (another mode of folding). No motion of the driving space joins
// them (each is a continuation along the start's curve), so plan() says why at once instead of
// running out its 30 s. B is found by leaving flat towards random sign patterns
// (geometry::lead_in) and folding on by projection; the oracle for "another branch" is the signs:
// along the branch of A every crease keeps its sign (or all flip: the mirror), so a crease whose
// sign relative to the others differs puts B elsewhere.
TEST(Plan, GoalOnAnotherBranchIsNamedNotSearched) {
  const CreasePattern p = build_or_throw(gen::miura(3, 3));
  const ClosureSystem sys(p);
  const FoldState a = folded_along_assignment(p, 0.5);
  const foldkit::statespaces::FoldValidity validity(p, foldkit::statespaces::AngleBounds::of(p, false), true);
  const Eigen::Index rank = foldkit::geometry::mobility(sys, a).rank;
  const auto other_branch = [&](const FoldState& b) {
    bool same = true, mirror = true;
    for (Eigen::Index j = 0; j < b.angles.size(); ++j) {
      if (std::abs(b.angles[j]) < 1e-3) continue;
      same = same && b.angles[j] * a.angles[j] > 0.0;
      mirror = mirror && b.angles[j] * a.angles[j] < 0.0;
    }
    return !same && !mirror;
  };
  std::mt19937 rng(11);
  std::optional<FoldState> b;
  foldkit::geometry::ProjectionOptions po;
  po.tolerance = 1e-12;
  for (int k = 0; k < 200 && !b; ++k) {
    Eigen::VectorXd s(a.angles.size());
    for (Eigen::Index j = 0; j < s.size(); ++j) s[j] = std::uniform_real_distribution<double>(-1.0, 1.0)(rng);
    const auto way = foldkit::geometry::lead_in(sys, FoldState::flat(p), FoldState{s}, rank, 0.02);
    if (way.empty()) continue;
    const FoldState& out = way.back();
    const auto r = foldkit::geometry::project(sys, FoldState{Eigen::VectorXd(out.angles * (0.5 / out.angles.cwiseAbs().maxCoeff()))}, po);
    if (!r.status.ok() || !other_branch(r.state) || !other_branch(out)) continue;
    if (foldkit::geometry::mobility(sys, r.state).dof != 1 || !validity.valid(r.state)) continue;
    b = r.state;
  }
  ASSERT_TRUE(b.has_value()) << "no closed state on another branch found";
  PlanOptions req;
  req.start = a;
  FoldState goal = *b;
  req.use_assignment = false;
  req.time = 30.0;
  req.fallback = false;
  const PlanResult r = plan(p, goal, req);
  EXPECT_EQ(r.status.code, foldkit::geometry::StatusCode::NoProgress) << r.status.message;
  EXPECT_NE(r.status.message.find("another branch"), std::string::npos) << r.status.message;
  EXPECT_EQ(r.seconds, 0.0);  // decided before the planner ran, not at the 30 s limit
  RecordProperty("message", r.status.message);
  // With the fallback the plan goes start → flat → goal at once: two plans from flat, well
  // within the time, every waypoint closed, through the flat sheet.
  req.fallback = true;
  req.replay = false;  // the start has no sequence from flat here; the waypoints are checked instead
  const PlanResult via = plan(p, goal, req);
  ASSERT_TRUE(via.status.ok()) << via.status.message;
  EXPECT_TRUE(via.via_flat);
  EXPECT_NE(via.status.message.find("another branch"), std::string::npos) << via.status.message;
  EXPECT_LT(via.seconds, 0.5 * req.time);
  double nearest_flat = 1.0;
  for (const FoldState& w : via.waypoints) {
    EXPECT_LE(sys.max_error(w), 1e-10);
    nearest_flat = std::min(nearest_flat, w.angles.cwiseAbs().maxCoeff());
  }
  EXPECT_EQ(nearest_flat, 0.0);
  EXPECT_LT((via.waypoints.front().angles - a.angles).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((via.waypoints.back().angles - b->angles).cwiseAbs().maxCoeff(), 1e-6);
  // The same start to a goal on its own branch is planned as before.
  goal = folded_along_assignment(p, 1.0);
  const PlanResult same = plan(p, goal, req);
  for (const FoldState& w : same.waypoints) EXPECT_LE(sys.max_error(w), 1e-10);
  EXPECT_TRUE(same.status.ok()) << same.status.message;
  EXPECT_FALSE(same.via_flat);
}

// Property test (issue 16): Miura sheets of random size and parallelogram angle, each flat to a
// random fold along its assignment, with default options: planned in the driving space, every
// waypoint closed to 1e-10 rad, ending at the goal, replayed valid with collisions on.
TEST(Plan, RandomMiuraSheetsAndGoalsInTheDrivingSpace) {
  std::mt19937 rng(2026);
  std::uniform_int_distribution<int> size(3, 8);
  std::uniform_real_distribution<double> angle(0.8, 1.3), fold(0.3, 1.5);
  for (int k = 0; k < 6; ++k) {
    const int rows = size(rng), cols = size(rng);
    const double a = angle(rng), f = fold(rng);
    SCOPED_TRACE(std::to_string(rows) + "x" + std::to_string(cols) + " angle " + std::to_string(a) + " fold " + std::to_string(f));
    const CreasePattern p = build_or_throw(gen::miura(rows, cols, 1.0, 1.0, a));
    PlanOptions req;
    FoldState goal = folded_along_assignment(p, f);
    req.seed = static_cast<unsigned>(k + 1);
    req.time = 20.0;
    const PlanResult r = plan(p, goal, req);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    EXPECT_EQ(r.space, "driving");
    ASSERT_TRUE(r.replay && r.replay->status.ok() && r.replay->collisions.empty());
    const ClosureSystem sys(p);
    for (const FoldState& w : r.waypoints) EXPECT_LE(sys.max_error(w), 1e-10);
    EXPECT_LT((r.waypoints.back().angles - goal.angles).cwiseAbs().maxCoeff(), 1e-6);
  }
}

// PRM and PRM* check and interpolate from several threads: the driving space hands each thread a
// solver of its own (scripts/test-tsan.sh runs this under ThreadSanitizer).
TEST(Plan, ThreadedPlannersInTheDrivingSpace) {
  const CreasePattern p = build_or_throw(gen::miura(4, 4));
  for (const char* planner : {"PRM", "PRMstar"}) {
    PlanOptions req;
    FoldState goal = folded_along_assignment(p, 1.0);
    req.space = SpaceKind::Driving;
    req.planner = planner;
    req.time = 2.0;
    req.seed = 5;
    const PlanResult r = plan(p, goal, req);
    SCOPED_TRACE(planner);
    expect_valid_plan(p, goal, r);
  }
}

}  // namespace
