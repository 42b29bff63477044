// The oracle of test/support/same_report.hpp: two copies of a report are the same, and a copy
// with any one field changed (also only in the bits of a double: -0.0 for 0.0) is not, so that
// the tests that rely on it (SequenceReplay, ReplayPipeline) see every field.
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include "foldkit/simulation/simulate.hpp"
#include "same_report.hpp"

namespace foldkit::simulation {
namespace {

// A crossing whose every field differs from its default and from the other crossings'.
CollisionEvent crossing(double seed) {
  CollisionEvent c;
  c.time = 1.25 + seed;
  c.event = 2 + static_cast<int>(seed);
  c.actors = {3, 7};
  c.point = Eigen::Vector3d(0.5, -0.25, 0.125 + seed);
  c.kind = CrossingKind::Stacked;
  c.depth = 0.01 + seed;
  c.closure_error = 1e-4 + seed;
  c.closed_depth = 0.002 + seed;
  c.state.angles = Eigen::Vector2d(0.3, -0.4 - seed);
  return c;
}

// A report with every field set, every list holding two entries.
SimulationReport full_report() {
  SimulationReport r;
  r.status = {geometry::StatusCode::Collision, "facets 3 and 7 cross"};
  r.model = Actuation::Spring;
  r.time_step = 0.02;
  r.duration = 3.5;
  r.max_closure_error = 2e-4;
  r.closure_tolerance = 1e-3;
  r.steps = 175;
  r.checks = 402;
  r.events = {{1, 0.0, 1.5, 1e-5, true}, {2, 1.5, 3.5, 2e-4, false}};
  r.collisions = {crossing(0.0), crossing(1.0)};
  r.collision_count = 5;
  r.numerical = {crossing(2.0), crossing(3.0)};
  r.numerical_count = 4;
  r.problems = {"closure", "collision"};
  r.frames = {{0.0, -1, {Eigen::Vector2d(0.0, 0.0)}}, {1.5, 1, {Eigen::Vector2d(0.1, 0.2)}}};
  r.final_state.angles = Eigen::Vector2d(0.3, -0.4);
  return r;
}

// How many failures expect_same_report reports for `a` and `b` (intercepted: they do not fail
// this test).
int failures(const SimulationReport& a, const SimulationReport& b) {
  ::testing::TestPartResultArray results;
  {
    const ::testing::ScopedFakeTestPartResultReporter reporter(
        ::testing::ScopedFakeTestPartResultReporter::INTERCEPT_ONLY_CURRENT_THREAD, &results);
    test::expect_same_report(a, b);
  }
  return results.size();
}

using Mutation = std::pair<const char*, std::function<void(SimulationReport&)>>;

// One change per field (of the report, and of an entry of each of its lists).
std::vector<Mutation> mutations() {
  std::vector<Mutation> m = {
      {"status.code", [](SimulationReport& r) { r.status.code = geometry::StatusCode::ClosureViolated; }},
      {"status.message", [](SimulationReport& r) { r.status.message += "!"; }},
      {"model", [](SimulationReport& r) { r.model = Actuation::Motor; }},
      {"time_step", [](SimulationReport& r) { r.time_step = std::nextafter(r.time_step, 1.0); }},
      {"duration", [](SimulationReport& r) { r.duration = std::nextafter(r.duration, 0.0); }},
      {"max_closure_error", [](SimulationReport& r) { r.max_closure_error *= 2.0; }},
      {"closure_tolerance", [](SimulationReport& r) { r.closure_tolerance *= 2.0; }},
      {"steps", [](SimulationReport& r) { ++r.steps; }},
      {"checks", [](SimulationReport& r) { ++r.checks; }},
      {"collision_count", [](SimulationReport& r) { ++r.collision_count; }},
      {"numerical_count", [](SimulationReport& r) { ++r.numerical_count; }},
      {"problems", [](SimulationReport& r) { r.problems.back() += "!"; }},
      {"final_state", [](SimulationReport& r) { r.final_state.angles[1] += 1e-12; }},
      {"final_state size", [](SimulationReport& r) { r.final_state.angles.resize(1); }},
      {"events size", [](SimulationReport& r) { r.events.pop_back(); }},
      {"events.number", [](SimulationReport& r) { ++r.events[1].number; }},
      {"events.start", [](SimulationReport& r) { r.events[1].start += 0.5; }},
      {"events.end", [](SimulationReport& r) { r.events[1].end += 0.5; }},
      {"events.max_closure_error", [](SimulationReport& r) { r.events[1].max_closure_error *= 2.0; }},
      {"events.reached", [](SimulationReport& r) { r.events[1].reached = true; }},
      {"frames size", [](SimulationReport& r) { r.frames.pop_back(); }},
      {"frames.time", [](SimulationReport& r) { r.frames[1].time += 0.5; }},
      {"frames.event", [](SimulationReport& r) { ++r.frames[1].event; }},
      {"frames.state", [](SimulationReport& r) { r.frames[1].state.angles[0] = 0.5; }},
      {"frames[0].state -0.0", [](SimulationReport& r) { r.frames[0].state.angles[0] = -0.0; }},
  };
  // The same changes in either list of crossings.
  for (const bool numerical : {false, true}) {
    const auto in = [numerical](std::function<void(CollisionEvent&)> change) {
      return [numerical, change](SimulationReport& r) { change((numerical ? r.numerical : r.collisions)[1]); };
    };
    const auto list = [numerical](SimulationReport& r) -> std::vector<CollisionEvent>& {
      return numerical ? r.numerical : r.collisions;
    };
    const char* const name = numerical ? "numerical" : "collisions";
    m.push_back({name, [list](SimulationReport& r) { list(r).pop_back(); }});
    m.push_back({name, in([](CollisionEvent& c) { c.time += 0.5; })});
    m.push_back({name, in([](CollisionEvent& c) { ++c.event; })});
    m.push_back({name, in([](CollisionEvent& c) { c.actors[1] = 8; })});
    m.push_back({name, in([](CollisionEvent& c) { c.point.z() += 1e-9; })});
    m.push_back({name, in([](CollisionEvent& c) { c.kind = CrossingKind::Crease; })});
    m.push_back({name, in([](CollisionEvent& c) { c.depth *= 2.0; })});
    m.push_back({name, in([](CollisionEvent& c) { c.closure_error *= 2.0; })});
    m.push_back({name, in([](CollisionEvent& c) { c.closed_depth = -1.0; })});
    m.push_back({name, in([](CollisionEvent& c) { c.state.angles[1] += 0.25; })});
  }
  return m;
}

TEST(SameReport, EqualCopiesPass) {
  const SimulationReport r = full_report();
  EXPECT_EQ(failures(r, r), 0);
  SimulationReport nan = r;  // the same NaN on both sides is the same result
  nan.max_closure_error = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(failures(nan, nan), 0);
}

TEST(SameReport, EveryFieldChangedFails) {
  const SimulationReport r = full_report();
  for (const auto& [name, change] : mutations()) {
    SimulationReport other = r;
    change(other);
    EXPECT_GT(failures(r, other), 0) << name << " changed and the reports still compare equal";
    EXPECT_GT(failures(other, r), 0) << name << " changed (as the first report) and they still compare equal";
  }
}

}  // namespace
}  // namespace foldkit::simulation
