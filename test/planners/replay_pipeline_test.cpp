// The plan's replay pipeline (planners/src/replay_pipeline.hpp): the replay of waypoints handed
// over one at a time, on another thread, against simulate() of their whole sequence (the oracle),
// for plans the simulator accepts and waypoints it rejects; and plans that do not depend on the
// threads' timing.
#include <atomic>
#include <cmath>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "../../planners/src/replay_pipeline.hpp"
#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/planners/plan.hpp"
#include "foldkit/planners/plan_setup.hpp"
#include "foldkit/simulation/simulate.hpp"
#include "folded_state.hpp"
#include "same_report.hpp"

namespace {

namespace gen = foldkit::geometry::generators;
using foldkit::geometry::build_or_throw;
using foldkit::geometry::CreasePattern;
using foldkit::geometry::FoldState;
using foldkit::planners::PlanOptions;
using foldkit::planners::PlanResult;
using foldkit::planners::PlanSetup;
using foldkit::planners::detail::ReplayPipeline;
namespace sim = foldkit::simulation;

constexpr double kDeg = M_PI / 180.0;

// The pipeline's report for `waypoints` next to simulate() of plan_sequence's sequence of them.
void expect_pipeline_is_simulate(const CreasePattern& p, const std::vector<FoldState>& waypoints, const PlanOptions& options) {
  PlanSetup setup;
  setup.pattern = &p;
  ReplayPipeline pipeline(setup, options);
  ASSERT_TRUE(pipeline.active());
  for (const FoldState& w : waypoints) pipeline.push(w);
  const foldkit::geometry::FoldSequence seq = foldkit::planners::plan_sequence(setup, options, waypoints);
  EXPECT_EQ(pipeline.events(), seq.events.size());
  const auto piped = pipeline.finish();
  ASSERT_TRUE(piped.has_value());
  sim::SimulationOptions so;
  so.collisions = options.collisions;
  foldkit::test::expect_same_report(*piped, sim::simulate(p, seq, so));
}

FoldState strip_state(const CreasePattern& strip, double a, double b) {
  FoldState s = FoldState::flat(strip);
  s.angles << a, b;
  return s;
}

TEST(ReplayPipeline, AcceptedWaypointsSameReportAsSimulate) {
  const CreasePattern strip = build_or_throw(gen::strip(3));
  std::vector<FoldState> w;
  for (int k = 1; k <= 30; ++k) w.push_back(strip_state(strip, 5.0 * k * kDeg, -5.0 * k * kDeg));
  w.push_back(w.back());  // a waypoint equal to the one before adds no event
  expect_pipeline_is_simulate(strip, w, PlanOptions{});
}

TEST(ReplayPipeline, CollidingWaypointsSameReportAsSimulate) {
  const CreasePattern strip = build_or_throw(gen::strip(3));
  std::vector<FoldState> w;
  for (int k = 1; k <= 34; ++k) w.push_back(strip_state(strip, 5.0 * k * kDeg, 5.0 * k * kDeg));
  PlanOptions o;
  PlanSetup setup;
  setup.pattern = &strip;
  const auto seq = foldkit::planners::plan_sequence(setup, o, w);
  EXPECT_EQ(sim::simulate(strip, seq).status.code, foldkit::geometry::StatusCode::Collision);
  expect_pipeline_is_simulate(strip, w, o);
}

TEST(ReplayPipeline, UnclosedWaypointsSameReportAsSimulate) {
  const CreasePattern miura = build_or_throw(gen::miura(4, 4));
  const FoldState goal = foldkit::test::folded_along_assignment(miura, 1.0);
  std::vector<FoldState> w;  // straight in angle space from flat: the loops open on the way
  for (int k = 1; k <= 8; ++k) w.push_back(FoldState{goal.angles * (k / 8.0)});
  PlanSetup setup;
  setup.pattern = &miura;
  const auto seq = foldkit::planners::plan_sequence(setup, PlanOptions{}, w);
  EXPECT_EQ(sim::simulate(miura, seq).status.code, foldkit::geometry::StatusCode::ClosureViolated);
  expect_pipeline_is_simulate(miura, w, PlanOptions{});
}

TEST(ReplayPipeline, InactiveWithoutReplayOrWithAStartSequence) {
  const CreasePattern strip = build_or_throw(gen::strip(3));
  PlanSetup setup;
  setup.pattern = &strip;
  PlanOptions none;
  none.replay = false;
  ReplayPipeline off(setup, none);
  EXPECT_FALSE(off.active());
  off.push(strip_state(strip, 0.1, -0.1));
  EXPECT_EQ(off.events(), 0u);
  EXPECT_FALSE(off.finish().has_value());
  PlanOptions started;
  started.start_sequence.events.push_back({1, {{1, 0.1, 1.0, 0}}});
  EXPECT_FALSE(ReplayPipeline(setup, started).active());
}

TEST(ReplayPipeline, CancelledOrAbandonedEndsWithoutReport) {
  const CreasePattern strip = build_or_throw(gen::strip(3));
  PlanSetup setup;
  setup.pattern = &strip;
  const PlanOptions o;
  {
    ReplayPipeline abandoned(setup, o);  // the destructor stops and joins
    for (int k = 1; k <= 10; ++k) abandoned.push(strip_state(strip, 0.05 * k, -0.05 * k));
  }
  ReplayPipeline cancelled(setup, o);
  cancelled.push(strip_state(strip, 0.1, -0.1));
  cancelled.cancel();
  EXPECT_FALSE(cancelled.finish().has_value());
  // A finished pipeline gives its report once.
  ReplayPipeline once(setup, o);
  once.push(strip_state(strip, 0.1, -0.1));
  EXPECT_TRUE(once.finish().has_value());
  EXPECT_FALSE(once.finish().has_value());
}

// What the replay throws on its thread (an event too slow for the step limit) is what finish()
// throws, as simulate() of the same sequence throws it.
TEST(ReplayPipeline, ErrorOnTheReplayThreadIsRethrownByFinish) {
  const CreasePattern strip = build_or_throw(gen::strip(3));
  PlanSetup setup;
  setup.pattern = &strip;
  PlanOptions o;
  o.speed = 1e-9;  // rad/s: the first event would take 10⁸ s
  const std::vector<FoldState> w = {strip_state(strip, 0.1, -0.1), strip_state(strip, 0.2, -0.2)};
  ReplayPipeline pipeline(setup, o);
  for (const FoldState& s : w) pipeline.push(s);
  EXPECT_THROW(pipeline.finish(), sim::SequenceError);
  EXPECT_THROW(sim::simulate(strip, foldkit::planners::plan_sequence(setup, o, w), sim::SimulationOptions{}), sim::SequenceError);
}

// A plan's replay (through the pipeline: its progress comes from another thread) is simulate() of
// its sequence, and the same seed gives the same plan and report, whatever the threads' timing.
TEST(ReplayPipeline, PlansReplayedAsSimulateAndRepeatable) {
  const CreasePattern p = build_or_throw(gen::miura(6, 6));
  const FoldState goal = foldkit::test::folded_along_assignment(p, 1.2);
  PlanOptions o;
  o.time = 20.0;
  o.seed = 2;
  std::atomic<int> calls{0}, elsewhere{0};
  const std::thread::id caller = std::this_thread::get_id();
  o.progress = [&](const foldkit::geometry::Progress&) {
    ++calls;
    if (std::this_thread::get_id() != caller) ++elsewhere;
  };
  const PlanResult a = foldkit::planners::plan(p, goal, o), b = foldkit::planners::plan(p, goal, o);
  EXPECT_GT(calls.load(), 0);
  EXPECT_EQ(elsewhere.load(), calls.load()) << "the replay ran on the caller's thread, not the pipeline's";
  ASSERT_TRUE(a.status.ok()) << a.status.message;
  ASSERT_TRUE(a.replay.has_value());
  foldkit::test::expect_same_report(*a.replay, sim::simulate(p, a.sequence, sim::SimulationOptions{}));
  ASSERT_TRUE(b.replay.has_value());
  foldkit::test::expect_same_report(*a.replay, *b.replay);
  ASSERT_EQ(a.waypoints.size(), b.waypoints.size());
  for (std::size_t i = 0; i < a.waypoints.size(); ++i) EXPECT_EQ(a.waypoints[i].angles, b.waypoints[i].angles) << i;
}

}  // namespace
