// The straight plan followed while the planner searches (planners/src/straight_plan.hpp): when it
// is made, that a plan which uses it is the one the straight path's own waypoints give (computed
// here through the public pieces, path_waypoints on the two ends), with simulate()'s report of its
// sequence, and that a plan it does not match is dropped without a trace.
#include <cmath>
#include <functional>
#include <system_error>
#include <thread>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <ompl/base/ScopedState.h>

#include "../../planners/src/straight_plan.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/planners/plan.hpp"
#include "foldkit/planners/plan_setup.hpp"
#include "foldkit/simulation/simulate.hpp"
#include "folded_state.hpp"
#include "same_report.hpp"

namespace {

namespace gen = foldkit::geometry::generators;
namespace og = ompl::geometric;
namespace ob = ompl::base;
namespace sim = foldkit::simulation;
using foldkit::geometry::build_or_throw;
using foldkit::geometry::CreasePattern;
using foldkit::geometry::FoldState;
using foldkit::planners::PlanOptions;
using foldkit::planners::PlanResult;
using foldkit::planners::PlanSetup;
using foldkit::planners::detail::StraightPlan;

struct Miura {
  CreasePattern pattern = build_or_throw(gen::miura(6, 6));
  FoldState goal = foldkit::test::folded_along_assignment(pattern, 1.2);
};

// The path from the planner's start to the goal, as plan() gives them to the planner.
og::PathGeometric ends(const PlanSetup& setup, const FoldState* middle = nullptr) {
  ob::ScopedState<> a(setup.space), m(setup.space), b(setup.space);
  EXPECT_TRUE(setup.plan_space->write(setup.prefix.back(), a.get()));
  EXPECT_TRUE(setup.plan_space->write(setup.goal, b.get()));
  og::PathGeometric path(setup.si, a.get(), b.get());
  if (middle) {
    EXPECT_TRUE(setup.plan_space->write(*middle, m.get()));
    path = og::PathGeometric(setup.si);
    path.append(a.get());
    path.append(m.get());
    path.append(b.get());
  }
  return path;
}

TEST(StraightPlan, WantedOnlyForAStraightReplayedPlanFromAContinuingStart) {
  const Miura m;
  PlanOptions o;
  const PlanSetup setup = foldkit::planners::make_plan_setup(m.pattern, m.goal, o);
  ASSERT_TRUE(setup.continues_to_goal);
  EXPECT_TRUE(StraightPlan::wanted(setup, o, false, false));
  EXPECT_FALSE(StraightPlan::wanted(setup, o, true, false)) << "through flat";
  EXPECT_FALSE(StraightPlan::wanted(setup, o, false, true)) << "with experience";
  PlanOptions no_replay = o, raw = o, clearance = o, threshold = o, sequel = o;
  no_replay.replay = false;
  raw.simplify = false;
  clearance.objective = "clearance";
  threshold.cost_threshold = 100.0;
  sequel.start_sequence.events.push_back({1, {}});
  for (const PlanOptions* other : {&no_replay, &raw, &clearance, &threshold, &sequel})
    EXPECT_FALSE(StraightPlan::wanted(setup, *other, false, false));
  PlanOptions projected = o;
  projected.space = foldkit::planners::SpaceKind::Projected;
  const PlanSetup constrained = foldkit::planners::make_plan_setup(m.pattern, m.goal, projected);
  EXPECT_FALSE(StraightPlan::wanted(constrained, projected, false, false)) << "the projected space's paths are not straight";
}

// The plan of a Miura sheet from flat, whose planner's path runs straight in the driving crease:
// its waypoints are those of the straight path from the planner's start to the goal, its report
// simulate()'s, and both are the same on a second run.
TEST(StraightPlan, PlanIsTheStraightPathsWaypointsWithSimulatesReport) {
  const Miura m;
  for (unsigned int seed : {1u, 2u}) {
    PlanOptions o;
    o.time = 20.0;
    o.seed = seed;
    const PlanResult a = foldkit::planners::plan(m.pattern, m.goal, o);
    ASSERT_TRUE(a.status.ok()) << a.status.message;
    const PlanSetup setup = foldkit::planners::make_plan_setup(m.pattern, m.goal, o);
    std::string why;
    const auto oracle = foldkit::planners::path_waypoints(setup, ends(setup), o, true, &why);
    ASSERT_TRUE(oracle.has_value()) << why;
    ASSERT_EQ(a.waypoints.size(), oracle->size()) << "seed " << seed;
    for (std::size_t i = 0; i < oracle->size(); ++i) ASSERT_EQ(a.waypoints[i].angles, (*oracle)[i].angles) << i;
    ASSERT_TRUE(a.replay.has_value());
    foldkit::test::expect_same_report(*a.replay, sim::simulate(m.pattern, a.sequence, sim::SimulationOptions{}));
    const PlanResult b = foldkit::planners::plan(m.pattern, m.goal, o);
    ASSERT_TRUE(b.replay.has_value());
    foldkit::test::expect_same_report(*a.replay, *b.replay);
  }
}

TEST(StraightPlan, MatchesOnlyItsOwnEnds) {
  const Miura m;
  PlanOptions o;
  const PlanSetup setup = foldkit::planners::make_plan_setup(m.pattern, m.goal, o);
  StraightPlan straight(setup, o);
  EXPECT_TRUE(straight.matches(ends(setup)));
  const FoldState halfway = foldkit::test::folded_along_assignment(m.pattern, 0.6);
  EXPECT_FALSE(straight.matches(ends(setup, &halfway))) << "three states";
  PlanSetup reversed = setup;
  std::swap(reversed.prefix.back(), reversed.goal);
  EXPECT_FALSE(straight.matches(ends(reversed))) << "other ends";
  std::string why;
  const auto waypoints = straight.waypoints();
  ASSERT_TRUE(waypoints.has_value());
  const auto oracle = foldkit::planners::path_waypoints(setup, ends(setup), o, true, &why);
  ASSERT_TRUE(oracle.has_value());
  ASSERT_EQ(waypoints->size(), oracle->size());
  for (std::size_t i = 0; i < oracle->size(); ++i) EXPECT_EQ((*waypoints)[i].angles, (*oracle)[i].angles) << i;
}

// The continuation asks `stop` before each of its steps and ends at the first yes: a dropped
// straight plan does not follow the rest of the way.
TEST(StraightPlan, WaypointsStopAtTheNextStepWhenAsked) {
  const Miura m;
  PlanOptions o;
  const PlanSetup setup = foldkit::planners::make_plan_setup(m.pattern, m.goal, o);
  int asked = 0;
  std::string why;
  ASSERT_TRUE(foldkit::planners::path_waypoints(setup, ends(setup), o, true, &why, {}, [&] { return ++asked < 0; }).has_value());
  const int whole_way = asked;
  ASSERT_GT(whole_way, 20) << "a continuation of many steps, each asking";
  asked = 0;
  EXPECT_FALSE(foldkit::planners::path_waypoints(setup, ends(setup), o, true, &why, {}, [&] { return ++asked > 3; }).has_value());
  EXPECT_EQ(why, "the waypoints were stopped");
  // After the first yes (the 4th), only the way out asks again: the continuation's step, the
  // bisection's guard, the path's last state and the end (a step more would ask tens of times).
  EXPECT_LE(asked, 4 + 4) << "went on after the first yes";
}

// Dropped at once (the planner found another path, or none): its threads end and nothing hangs,
// however far they got.
TEST(StraightPlan, DroppedAtAnyPointEndsItsThreads) {
  const Miura m;
  PlanOptions o;
  const PlanSetup setup = foldkit::planners::make_plan_setup(m.pattern, m.goal, o);
  for (int i = 0; i < 5; ++i) StraightPlan straight(setup, o);
  StraightPlan kept(setup, o);
  EXPECT_TRUE(kept.waypoints().has_value());
}

// No second thread to be had: the straight plan does not run, and the plan is the same as with it.
TEST(StraightPlan, NoThreadLeavesThePlanToItself) {
  const Miura m;
  PlanOptions o;
  o.time = 20.0;
  const PlanSetup setup = foldkit::planners::make_plan_setup(m.pattern, m.goal, o);
  int asked = 0;
  const foldkit::simulation::ThreadStarter refuse = [&](std::function<void()>) -> std::thread {
    ++asked;
    throw std::system_error(std::make_error_code(std::errc::resource_unavailable_try_again));
  };
  StraightPlan none(setup, o, refuse);
  EXPECT_EQ(asked, 2) << "the replay's thread and the waypoints'";
  EXPECT_FALSE(none.matches(ends(setup)));
  EXPECT_FALSE(none.pipeline().active());
  EXPECT_FALSE(none.waypoints().has_value());
}

}  // namespace
