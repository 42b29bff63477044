// The single-vertex fallback (issue 16, item 4): goals drawn with no reachability filter are all
// planned, and the fallback's path is checked against oracles that do not share its code —
// closure by geometry::ClosureSystem, the plan replayed by the simulator (FCL collisions on).
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/planners/carpenter_fallback.hpp"
#include "foldkit/planners/plan.hpp"
#include "foldkit/planners/planner_factory.hpp"
#include "random_vertex_state.hpp"
#include "spec_helpers.hpp"
#include "test_time.hpp"

namespace {

namespace gen = foldkit::geometry::generators;
using foldkit::geometry::build_or_throw;
using foldkit::geometry::ClosureSystem;
using foldkit::geometry::CreasePattern;
using foldkit::geometry::FoldState;
using foldkit::planners::plan;
using foldkit::planners::PlanOptions;
using foldkit::planners::PlanResult;
using foldkit::test::random_vertex_state;

CreasePattern random_vertex(int degree, unsigned seed) {
  std::mt19937 rng(seed);
  return build_or_throw(gen::single_vertex(foldkit::test::random_sectors(degree, rng, 0.2)));
}

PlanOptions fallback_options() {
  PlanOptions req;
  req.use_assignment = false;
  req.time = foldkit::test::scaled_seconds(1.0);
  return req;
}

// A valid plan: solved, replayed without a collision or a closure violation, every waypoint
// closed to 1e-10 rad, ending at the goal.
void expect_valid(const CreasePattern& p, const FoldState& goal, const PlanResult& r) {
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_TRUE(r.replay.has_value());
  EXPECT_TRUE(r.replay->status.ok()) << r.replay->status.message;
  EXPECT_TRUE(r.replay->collisions.empty());
  const ClosureSystem sys(p);
  double worst = 0.0;
  for (const FoldState& w : r.waypoints) worst = std::max(worst, sys.max_error(w));
  EXPECT_LT(worst, 1e-10);
  EXPECT_LT((r.waypoints.back().angles - goal.angles).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(CarpenterFallback, PathGoesFromStartThroughFlatToGoal) {
  const CreasePattern p = random_vertex(8, 31);
  const FoldState a = random_vertex_state(p, 1), b = random_vertex_state(p, 2);
  std::string why;
  const std::vector<FoldState> way = foldkit::planners::carpenter_path(p, a, b, 0.02, &why);
  ASSERT_FALSE(way.empty()) << why;
  EXPECT_LT((way.front().angles - a.angles).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((way.back().angles - b.angles).cwiseAbs().maxCoeff(), 1e-12);
  const ClosureSystem sys(p);
  int flat = 0;
  for (std::size_t i = 0; i < way.size(); ++i) {
    EXPECT_LT(sys.max_error(way[i]), 1e-9) << "frame " << i;
    if (i > 0) {
      EXPECT_LE((way[i].angles - way[i - 1].angles).cwiseAbs().maxCoeff(), 0.02 + 1e-9) << "frame " << i;
    }
    flat += way[i].angles.cwiseAbs().maxCoeff() == 0.0;
  }
  EXPECT_EQ(flat, 1);
  // A flat end is one frame, not a flattening.
  const auto from_flat = foldkit::planners::carpenter_path(p, FoldState::flat(p), b, 0.02, &why);
  ASSERT_FALSE(from_flat.empty());
  EXPECT_EQ(from_flat.front().angles.cwiseAbs().maxCoeff(), 0.0);
}

TEST(CarpenterFallback, RefusesWhatCarpenterCannotFlatten) {
  const CreasePattern p = random_vertex(6, 5);
  FoldState open = random_vertex_state(p, 3);
  open.angles[0] += 0.1;  // no longer closed
  std::string why;
  EXPECT_TRUE(foldkit::planners::carpenter_path(p, FoldState::flat(p), open, 0.02, &why).empty());
  EXPECT_NE(why.find("does not take the goal"), std::string::npos) << why;
}

// Issue 16's completeness target, at test size: random sectors, random collision-free goals with
// no reachability filter, degrees 6, 8 and 12; every one planned from flat with a limit of 1 s
// (the times are measured by the vertex-complete bench suite, not here).
TEST(CarpenterFallback, UnfilteredRandomGoalsAreAllPlanned) {
  int fallbacks = 0;
  for (int degree : {6, 8, 12}) {
    for (unsigned k = 0; k < 4; ++k) {
      const CreasePattern p = random_vertex(degree, 100u * static_cast<unsigned>(degree) + k);
      const FoldState goal = random_vertex_state(p, 7u + k, degree <= 8 ? 2.5 : 1.5, 0.5);
      PlanOptions req = fallback_options();
      req.seed = k + 1;
      SCOPED_TRACE("degree " + std::to_string(degree) + " goal " + std::to_string(k));
      const PlanResult r = plan(p, goal, req);
      expect_valid(p, goal, r);
      fallbacks += r.fallback;
    }
  }
  RecordProperty("fallbacks", fallbacks);
}

// A planner that cannot get anywhere in its time (RRT with steps of 1e-7 rad; not RRTConnect,
// whose connect loop does not look at the clock): the fallback's path is the plan, through flat
// when the ends are on different branches; without the fallback, no plan.
TEST(CarpenterFallback, TakesOverWhenThePlannerCannot) {
  const CreasePattern p = random_vertex(8, 77);
  const FoldState start = random_vertex_state(p, 11), goal = random_vertex_state(p, 12);
  PlanOptions req = fallback_options();
  req.start = start;
  // The replay starts from flat: the start's own CMML (flat → start, Carpenter's frames) comes first.
  req.start_sequence = foldkit::geometry::path_sequence(
      p, foldkit::planners::carpenter_path(p, FoldState::flat(p), start, 0.02, nullptr), 1.0, "start");
  req.time = foldkit::test::scaled_seconds(0.4);
  req.planner = "RRT";
  req.params = {{"range", "1e-7"}};
  const PlanResult r = plan(p, goal, req);
  expect_valid(p, goal, r);
  EXPECT_TRUE(r.fallback);
  EXPECT_NE(r.status.message.find("Carpenter"), std::string::npos) << r.status.message;
  bool through_flat = false;
  for (const FoldState& w : r.waypoints) through_flat = through_flat || w.angles.cwiseAbs().maxCoeff() < 1e-9;
  EXPECT_TRUE(through_flat);

  req.fallback = false;
  const PlanResult none = plan(p, goal, req);
  EXPECT_FALSE(none.status.ok());
  EXPECT_FALSE(none.fallback);
  EXPECT_EQ(none.status.code, foldkit::geometry::StatusCode::LimitReached);
}

// Issue 32: `time` bounds the whole search, the Carpenter fallback included. At degree 32 the
// fallback needs far more than 0.05 s (≈ 0.6 s of LPs and checks), so with a planner that cannot
// get anywhere the search ends at the limit, out of time; with time enough the same problem is
// planned by the fallback.
TEST(CarpenterFallback, TimeBoundsTheFallbackToo) {
  std::mt19937 rng(3232);
  const CreasePattern p = build_or_throw(gen::single_vertex(foldkit::test::random_sectors(32, rng, 0.1)));
  const FoldState goal = random_vertex_state(p, 5, 0.8, 0.4);
  PlanOptions req = fallback_options();
  req.planner = "RRT";
  req.params = {{"range", "1e-7"}};
  req.time = 0.05;
  const PlanResult r = plan(p, goal, req);
  EXPECT_EQ(r.status.code, foldkit::geometry::StatusCode::LimitReached) << r.status.message;
  EXPECT_NE(r.status.message.find("time ran out"), std::string::npos) << r.status.message;
  // One Carpenter step or one state check past the limit at most.
  EXPECT_LT(r.seconds, req.time + foldkit::test::scaled_seconds(0.1));
  EXPECT_FALSE(r.fallback);

  // With time enough (the planner spins for a quarter of it; the fallback needs ≈ 0.6 s of the
  // rest in Release) the same problem is planned, by the fallback.
  req.time = foldkit::test::scaled_seconds(3.0);
  const PlanResult slow = plan(p, goal, req);
  expect_valid(p, goal, slow);
  EXPECT_TRUE(slow.fallback);
  RecordProperty("fallback_seconds", std::to_string(slow.seconds));
}

TEST(CarpenterFallback, RefusesBadSettings) {
  const CreasePattern p = random_vertex(6, 9);
  auto chain = std::make_shared<foldkit::statespaces::SingleVertexChain>(p);
  auto space = std::make_shared<foldkit::statespaces::SingleVertexStateSpace>(
      chain, foldkit::statespaces::AngleBounds::of(p, false));
  auto si = std::make_shared<ompl::base::SpaceInformation>(space);
  auto inner = foldkit::planners::make_planner("RRTConnect", si);
  auto validity = std::make_shared<foldkit::statespaces::FoldValidity>(p, foldkit::statespaces::AngleBounds::of(p, false), true);
  using foldkit::planners::CarpenterFallbackPlanner;
  EXPECT_THROW(CarpenterFallbackPlanner(si, nullptr, 1.0, p, space, validity), std::invalid_argument);
  EXPECT_THROW(CarpenterFallbackPlanner(si, inner, 1.0, p, space, nullptr), std::invalid_argument);
  EXPECT_THROW(CarpenterFallbackPlanner(si, inner, 0.0, p, space, validity), std::invalid_argument);
  EXPECT_THROW(CarpenterFallbackPlanner(si, inner, 1.0, p, space, validity, -0.02), std::invalid_argument);
  EXPECT_EQ(CarpenterFallbackPlanner(si, inner, 1.0, p, space, validity).getName(), "RRTConnect+Carpenter");
}

}  // namespace
