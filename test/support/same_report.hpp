#pragma once
// Two simulation reports are the same verdict, figure for figure: the oracle of the replay fed an
// event at a time (simulation::SequenceReplay, the plan's replay pipeline) against simulate().
// Both are the same computation, so every field must be equal, doubles bit for bit (0.0 and -0.0
// differ, a NaN equals the same NaN): a replay that drifted by one rounding is a different one.
// A field added to SimulationReport, CollisionEvent, EventReport or Frame must be added here
// (test/simulation/same_report_test.cpp checks that each one compared makes a difference).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include <Eigen/Core>
#include <gtest/gtest.h>

#include "foldkit/simulation/simulate.hpp"

namespace foldkit::test {

// Whether `a` and `b` have the same bits (not ==: -0.0 == 0.0, NaN != NaN).
inline bool same_bits(double a, double b) {
  std::uint64_t x = 0, y = 0;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return x == y;
}

inline ::testing::AssertionResult same_double(const char* what, double a, double b) {
  if (same_bits(a, b)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << what << ": " << ::testing::PrintToString(a) << " vs "
                                       << ::testing::PrintToString(b) << " (not the same bits)";
}

// Vectors of any size (Eigen's == needs equal sizes), coefficient by coefficient, bit for bit.
template <typename A, typename B>
::testing::AssertionResult same_vector(const char* what, const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  if (a.size() != b.size())
    return ::testing::AssertionFailure() << what << ": " << a.size() << " vs " << b.size() << " coefficients";
  for (Eigen::Index i = 0; i < a.size(); ++i)
    if (!same_bits(a(i), b(i)))
      return ::testing::AssertionFailure() << what << "[" << i << "]: " << ::testing::PrintToString(a(i)) << " vs "
                                           << ::testing::PrintToString(b(i)) << " (not the same bits)";
  return ::testing::AssertionSuccess();
}

// Every field of two crossings (collisions or numerical ones); `list` and `i` name them.
inline void expect_same_crossing(const simulation::CollisionEvent& a, const simulation::CollisionEvent& b, const char* list,
                                 std::size_t i) {
  SCOPED_TRACE(std::string(list) + "[" + std::to_string(i) + "]");
  EXPECT_TRUE(same_double("time", a.time, b.time));
  EXPECT_EQ(a.event, b.event);
  EXPECT_EQ(a.actors, b.actors);
  EXPECT_TRUE(same_vector("point", a.point, b.point));
  EXPECT_EQ(a.kind, b.kind);
  EXPECT_TRUE(same_double("depth", a.depth, b.depth));
  EXPECT_TRUE(same_double("closure_error", a.closure_error, b.closure_error));
  EXPECT_TRUE(same_double("closed_depth", a.closed_depth, b.closed_depth));
  EXPECT_TRUE(same_vector("state", a.state.angles, b.state.angles));
}

// Every field of the two reports and of their events, crossings and frames.
inline void expect_same_report(const simulation::SimulationReport& a, const simulation::SimulationReport& b) {
  EXPECT_EQ(a.status.code, b.status.code);
  EXPECT_EQ(a.status.message, b.status.message);
  EXPECT_EQ(a.model, b.model);
  EXPECT_TRUE(same_double("time_step", a.time_step, b.time_step));
  EXPECT_TRUE(same_double("duration", a.duration, b.duration));
  EXPECT_TRUE(same_double("max_closure_error", a.max_closure_error, b.max_closure_error));
  EXPECT_TRUE(same_double("closure_tolerance", a.closure_tolerance, b.closure_tolerance));
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.checks, b.checks);
  EXPECT_EQ(a.collision_count, b.collision_count);
  EXPECT_EQ(a.numerical_count, b.numerical_count);
  EXPECT_EQ(a.problems, b.problems);
  EXPECT_TRUE(same_vector("final_state", a.final_state.angles, b.final_state.angles));
  EXPECT_EQ(a.events.size(), b.events.size());
  for (std::size_t i = 0; i < a.events.size() && i < b.events.size(); ++i) {
    SCOPED_TRACE("events[" + std::to_string(i) + "]");
    EXPECT_EQ(a.events[i].number, b.events[i].number);
    EXPECT_TRUE(same_double("start", a.events[i].start, b.events[i].start));
    EXPECT_TRUE(same_double("end", a.events[i].end, b.events[i].end));
    EXPECT_TRUE(same_double("max_closure_error", a.events[i].max_closure_error, b.events[i].max_closure_error));
    EXPECT_EQ(a.events[i].reached, b.events[i].reached);
  }
  EXPECT_EQ(a.collisions.size(), b.collisions.size());
  for (std::size_t i = 0; i < a.collisions.size() && i < b.collisions.size(); ++i)
    expect_same_crossing(a.collisions[i], b.collisions[i], "collisions", i);
  EXPECT_EQ(a.numerical.size(), b.numerical.size());
  for (std::size_t i = 0; i < a.numerical.size() && i < b.numerical.size(); ++i)
    expect_same_crossing(a.numerical[i], b.numerical[i], "numerical", i);
  EXPECT_EQ(a.frames.size(), b.frames.size());
  for (std::size_t i = 0; i < a.frames.size() && i < b.frames.size(); ++i) {
    SCOPED_TRACE("frames[" + std::to_string(i) + "]");
    EXPECT_TRUE(same_double("time", a.frames[i].time, b.frames[i].time));
    EXPECT_EQ(a.frames[i].event, b.frames[i].event);
    EXPECT_TRUE(same_vector("state", a.frames[i].state.angles, b.frames[i].state.angles));
  }
}

}  // namespace foldkit::test
