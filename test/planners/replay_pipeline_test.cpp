// The plan's replay pipeline (planners/src/replay_pipeline.hpp): the replay of waypoints handed
// over one at a time, on another thread, against simulate() of their whole sequence (the oracle),
// for plans the simulator accepts and waypoints it rejects; plans that do not depend on the
// threads' timing; its report used only for exactly the events it replayed; and no thread to be
// had.
#include <atomic>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "../../planners/src/plan_finish.hpp"
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
  const auto piped = pipeline.finish(seq);
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

// A square twist folded along a straight line in angle space: the states between the waypoints do
// not close, and crossings that the nearest closed state lacks are listed as numerical ones.
TEST(ReplayPipeline, NumericalCrossingsSameReportAsSimulate) {
  const CreasePattern twist = build_or_throw(gen::square_twist());
  const FoldState goal = foldkit::test::folded_along_assignment(twist, 1.5);
  std::vector<FoldState> w;
  for (int k = 1; k <= 8; ++k) w.push_back(FoldState{goal.angles * (k / 8.0)});
  PlanSetup setup;
  setup.pattern = &twist;
  EXPECT_FALSE(sim::simulate(twist, foldkit::planners::plan_sequence(setup, PlanOptions{}, w)).numerical.empty());
  expect_pipeline_is_simulate(twist, w, PlanOptions{});
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
  EXPECT_FALSE(off.finish(foldkit::planners::plan_sequence(setup, none, {strip_state(strip, 0.1, -0.1)})).has_value());
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
  const std::vector<FoldState> w = {strip_state(strip, 0.1, -0.1)};
  const auto seq = foldkit::planners::plan_sequence(setup, o, w);
  ReplayPipeline cancelled(setup, o);
  cancelled.push(w[0]);
  cancelled.cancel();
  EXPECT_FALSE(cancelled.finish(seq).has_value());
  // A finished pipeline gives its report once.
  ReplayPipeline once(setup, o);
  once.push(w[0]);
  EXPECT_TRUE(once.finish(seq).has_value());
  EXPECT_FALSE(once.finish(seq).has_value());
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
  const auto seq = foldkit::planners::plan_sequence(setup, o, w);
  EXPECT_THROW(pipeline.finish(seq), sim::SequenceError);
  EXPECT_THROW(sim::simulate(strip, seq, sim::SimulationOptions{}), sim::SequenceError);
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

// Pushes `waypoints` into a pipeline and returns what finish() gives for `sequence`.
std::optional<sim::SimulationReport> finish_with(const PlanSetup& setup, const PlanOptions& o, const std::vector<FoldState>& waypoints,
                                                 const foldkit::geometry::FoldSequence& sequence) {
  ReplayPipeline pipeline(setup, o);
  for (const FoldState& s : waypoints) pipeline.push(s);
  return pipeline.finish(sequence);
}

// finish() gives a report only for exactly the events it replayed: any change of a number, a
// joint, a line, or of an angle or a speed in its last bit (also 0.0 to -0.0) is another sequence.
TEST(ReplayPipeline, ReportOnlyForExactlyTheEventsReplayed) {
  const CreasePattern strip = build_or_throw(gen::strip(3));
  PlanSetup setup;
  setup.pattern = &strip;
  const PlanOptions o;
  std::vector<FoldState> w;
  // Joint 2 back to 0.0 in the second event, at rest in the last two.
  for (int k = 1; k <= 4; ++k) w.push_back(strip_state(strip, 0.1 * k, k == 1 ? -0.1 : 0.0));
  const foldkit::geometry::FoldSequence seq = foldkit::planners::plan_sequence(setup, o, w);
  ASSERT_EQ(seq.events.size(), 4u);
  ASSERT_EQ(seq.events[1].folds.size(), 2u);
  ASSERT_FALSE(std::signbit(seq.events[1].folds[1].angle));
  ASSERT_EQ(seq.events[1].folds[1].angle, 0.0);
  ASSERT_EQ(seq.events[3].folds.size(), 1u);
  EXPECT_TRUE(finish_with(setup, o, w, seq).has_value());
  using Change = std::function<void(foldkit::geometry::FoldSequence&)>;
  const std::vector<std::pair<std::string, Change>> changes = {
      {"number", [](auto& q) { ++q.events[2].number; }},
      {"joint", [](auto& q) { q.events[3].folds[0].joint_id = 2; }},
      {"line", [](auto& q) { q.events[1].folds[1].line = 9; }},
      {"angle", [](auto& q) { q.events[1].folds[0].angle = std::nextafter(q.events[1].folds[0].angle, 1.0); }},
      {"speed", [](auto& q) { q.events[1].folds[1].speed = std::nextafter(q.events[1].folds[1].speed, 0.0); }},
      {"-0.0", [](auto& q) { q.events[1].folds[1].angle = -0.0; }},  // == 0.0, not the same bits
      {"a fold fewer", [](auto& q) { q.events[0].folds.pop_back(); }},
      {"an event fewer", [](auto& q) { q.events.pop_back(); }},
      {"an event more", [](auto& q) { q.events.push_back(q.events.back()); }},
  };
  for (const auto& [what, change] : changes) {
    foldkit::geometry::FoldSequence other = seq;
    change(other);
    EXPECT_FALSE(finish_with(setup, o, w, other).has_value()) << what;
  }
}

// What finish_plan makes of `waypoints` with `pipeline` (the strip has no loops: every state closes).
PlanResult finished(const PlanSetup& setup, const PlanOptions& o, const std::vector<FoldState>& waypoints, ReplayPipeline& pipeline) {
  PlanResult result;
  foldkit::planners::detail::finish_plan(setup, o, waypoints, result, "solved", &pipeline);
  return result;
}

PlanSetup strip_setup(const CreasePattern& strip) {
  PlanSetup setup;
  setup.pattern = &strip;
  setup.system = std::make_shared<foldkit::geometry::ClosureSystem>(strip);
  return setup;
}

// The pipeline replayed other waypoints than the plan's (as many events): the plan's replay is
// simulate() of its own sequence, not the pipeline's report.
TEST(ReplayPipeline, PlanReplaysItselfWhenThePipelineReplayedOtherEvents) {
  const CreasePattern strip = build_or_throw(gen::strip(3));
  const PlanSetup setup = strip_setup(strip);
  const PlanOptions o;
  std::vector<FoldState> pushed, planned;
  for (int k = 1; k <= 6; ++k) {
    pushed.push_back(strip_state(strip, 0.1 * k, -0.1 * k));
    planned.push_back(strip_state(strip, 0.1 * k, -0.05 * k));
  }
  ReplayPipeline pipeline(setup, o);
  for (const FoldState& s : pushed) pipeline.push(s);
  const PlanResult r = finished(setup, o, planned, pipeline);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_EQ(r.sequence.events.size(), pipeline.events());  // a count would not tell them apart
  ASSERT_TRUE(r.replay.has_value());
  foldkit::test::expect_same_report(*r.replay, sim::simulate(strip, r.sequence, sim::SimulationOptions{}));
  EXPECT_EQ(r.replay->final_state.angles, planned.back().angles);
}

// No thread to be had (std::thread throws std::system_error under resource limits): the pipeline
// is inactive, and the plan is replayed after its waypoints as without one.
TEST(ReplayPipeline, NoThreadLeavesItInactiveAndThePlanReplayed) {
  const CreasePattern strip = build_or_throw(gen::strip(3));
  const PlanSetup setup = strip_setup(strip);
  const PlanOptions o;
  std::vector<FoldState> w;
  for (int k = 1; k <= 6; ++k) w.push_back(strip_state(strip, 0.1 * k, -0.1 * k));
  int starts = 0;
  const foldkit::planners::detail::ThreadStarter refused = [&](std::function<void()>) -> std::thread {
    ++starts;
    throw std::system_error(std::make_error_code(std::errc::resource_unavailable_try_again), "no thread");
  };
  std::unique_ptr<ReplayPipeline> pipeline;
  ASSERT_NO_THROW(pipeline = std::make_unique<ReplayPipeline>(setup, o, refused));
  EXPECT_EQ(starts, 1);
  EXPECT_FALSE(pipeline->active());
  for (const FoldState& s : w) pipeline->push(s);
  EXPECT_EQ(pipeline->events(), 0u);
  const PlanResult r = finished(setup, o, w, *pipeline);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_TRUE(r.replay.has_value());
  foldkit::test::expect_same_report(*r.replay, sim::simulate(strip, r.sequence, sim::SimulationOptions{}));
  // A starter that gives no thread (not joinable) leaves it inactive too.
  EXPECT_FALSE(ReplayPipeline(setup, o, [](std::function<void()>) { return std::thread(); }).active());
  // A starter that gives a thread is the pipeline's: the replay runs on it.
  const foldkit::planners::detail::ThreadStarter given = [&](std::function<void()> body) {
    ++starts;
    return std::thread(std::move(body));
  };
  ReplayPipeline started(setup, o, given);
  EXPECT_EQ(starts, 2);
  EXPECT_TRUE(started.active());
  for (const FoldState& s : w) started.push(s);
  const PlanResult piped = finished(setup, o, w, started);
  ASSERT_TRUE(piped.replay.has_value());
  foldkit::test::expect_same_report(*piped.replay, *r.replay);
}

}  // namespace
