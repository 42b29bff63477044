// Plans end to end: every accepted plan is replayed by the simulator (the oracle), and its
// waypoints are closed by geometry::ClosureSystem.
#include <cmath>
#include <random>

#include <gtest/gtest.h>
#include <ompl/base/ScopedState.h>
#include <ompl/util/RandomNumbers.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/planners/plan.hpp"
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
using foldkit::planners::PlanRequest;
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

void expect_valid_plan(const CreasePattern& p, const PlanRequest& req, const PlanResult& r) {
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_TRUE(r.replay.has_value());
  EXPECT_TRUE(r.replay->status.ok());
  EXPECT_LT(r.replay->max_closure_error, 1e-3);
  EXPECT_TRUE(r.replay->collisions.empty());
  const ClosureSystem sys(p);
  for (const FoldState& w : r.waypoints) EXPECT_LT(sys.max_error(w), 1e-6);
  EXPECT_LT((r.waypoints.back().angles - req.goal.angles).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LT(r.waypoints.front().angles.cwiseAbs().maxCoeff(), 1e-12);  // flat start
}

TEST(Plan, SingleVerticesOfDegree4To12FromFlatWithAndWithoutCollision) {
  std::mt19937 rng(2024);
  for (int n = 4; n <= 12; ++n) {
    const CreasePattern p = build_or_throw(gen::single_vertex(foldkit::test::random_sectors(n, rng, 0.2)));
    for (bool collisions : {false, true}) {
      PlanRequest req;
      req.pattern = &p;
      req.goal = random_goal(p, static_cast<unsigned>(100 + n), collisions);
      req.space = SpaceKind::SingleVertex;
      req.time = 2.0;
      req.seed = static_cast<unsigned>(n);
      req.collisions = collisions;
      const PlanResult r = plan(req);
      SCOPED_TRACE("degree " + std::to_string(n) + (collisions ? " with collision" : ""));
      expect_valid_plan(p, req, r);
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
    PlanRequest req;
    req.pattern = &p;
    req.goal = random_goal(p, 11, true);
    req.space = SpaceKind::SingleVertex;
    req.planner = planner;
    req.time = 1.0;
    req.seed = 5;
    req.collisions = true;
    const PlanResult r = plan(req);
    SCOPED_TRACE(planner);
    expect_valid_plan(p, req, r);
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
  PlanRequest req;
  req.pattern = &p;
  req.goal = goal;
  req.space = kind;
  req.time = time;
  req.seed = seed;
  req.collisions = collisions;
  req.use_assignment = false;
  const PlanResult r = plan(req);
  SCOPED_TRACE(std::string("space ") + foldkit::planners::to_string(kind));
  expect_valid_plan(p, req, r);
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
// 0.2 rad (PlanRequest::search_margin) solves in well under a second. Atlas samples near its
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
    PlanRequest req;
    req.pattern = &p;
    req.goal = goal;
    req.space = kind;
    req.time = 10.0;  // generous for sanitizer builds; a plan takes well under a second in Release
    req.seed = 3;
    req.collisions = true;
    req.use_assignment = true;  // the generator's M/V become bounds
    req.search_margin = 0.2;
    const PlanResult r = plan(req);
    SCOPED_TRACE(std::string("space ") + foldkit::planners::to_string(kind));
    expect_valid_plan(p, req, r);
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
    PlanRequest req;
    req.pattern = &p;
    req.goal = folded_along_assignment(p, 1.2);
    req.time = 20.0;  // generous for sanitizer builds; well under a second in Release
    req.seed = 3;
    const PlanResult r = plan(req);
    EXPECT_EQ(r.space, "driving");
    expect_valid_plan(p, req, r);
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
  PlanRequest req;
  req.pattern = &p;
  req.goal = folded_along_assignment(p, 1.0);
  req.time = 20.0;
  req.replay = false;
  req.simplify = false;
  req.params = {{"range", "0.01"}};
  const PlanResult small = plan(req);
  ASSERT_TRUE(small.status.ok()) << small.status.message;
  req.params = {{"nonsense", "1"}};
  try {
    plan(req);
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
  PlanRequest req;
  req.pattern = &p;
  req.time = 20.0;
  req.seed = 2;
  req.goal = folded_along_assignment(p, 0.6);
  const PlanResult first = plan(req);
  ASSERT_TRUE(first.status.ok()) << first.status.message;
  foldkit::geometry::FoldSequence so_far = first.sequence;
  FoldState at = first.waypoints.back();
  for (double next : {1.4, 0.3}) {
    SCOPED_TRACE(next);
    req.start = at;
    req.start_sequence = so_far;
    req.goal = folded_along_assignment(p, next);
    const PlanResult r = plan(req);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    EXPECT_EQ(r.space, "driving");
    ASSERT_TRUE(r.replay && r.replay->status.ok());
    EXPECT_LT((r.waypoints.front().angles - at.angles).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_LT((r.waypoints.back().angles - req.goal.angles).cwiseAbs().maxCoeff(), 1e-6);
    for (const FoldState& w : r.waypoints) EXPECT_LE(sys.max_error(w), 1e-10);
    so_far = r.sequence;
    at = r.waypoints.back();
  }
}

}  // namespace

namespace {

// PRM and PRM* check and interpolate from several threads: the driving space hands each thread a
// solver of its own (scripts/test-tsan.sh runs this under ThreadSanitizer).
TEST(Plan, ThreadedPlannersInTheDrivingSpace) {
  const CreasePattern p = build_or_throw(gen::miura(4, 4));
  for (const char* planner : {"PRM", "PRMstar"}) {
    PlanRequest req;
    req.pattern = &p;
    req.goal = folded_along_assignment(p, 1.0);
    req.space = SpaceKind::Driving;
    req.planner = planner;
    req.time = 2.0;
    req.seed = 5;
    const PlanResult r = plan(req);
    SCOPED_TRACE(planner);
    expect_valid_plan(p, req, r);
  }
}

}  // namespace
