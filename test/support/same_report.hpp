#pragma once
// Two simulation reports are the same verdict, figure for figure: the oracle of the replay fed an
// event at a time (simulation::SequenceReplay, the plan's replay pipeline) against simulate().
#include <gtest/gtest.h>

#include "foldkit/simulation/simulate.hpp"

namespace foldkit::test {

inline void expect_same_report(const simulation::SimulationReport& a, const simulation::SimulationReport& b) {
  EXPECT_EQ(a.status.code, b.status.code);
  EXPECT_EQ(a.status.message, b.status.message);
  EXPECT_EQ(a.problems, b.problems);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.checks, b.checks);
  EXPECT_EQ(a.duration, b.duration);
  EXPECT_EQ(a.max_closure_error, b.max_closure_error);
  EXPECT_EQ(a.collision_count, b.collision_count);
  EXPECT_EQ(a.numerical_count, b.numerical_count);
  EXPECT_EQ(a.final_state.angles, b.final_state.angles);
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t i = 0; i < a.events.size(); ++i) {
    EXPECT_EQ(a.events[i].number, b.events[i].number) << i;
    EXPECT_EQ(a.events[i].start, b.events[i].start) << i;
    EXPECT_EQ(a.events[i].end, b.events[i].end) << i;
    EXPECT_EQ(a.events[i].max_closure_error, b.events[i].max_closure_error) << i;
    EXPECT_EQ(a.events[i].reached, b.events[i].reached) << i;
  }
  ASSERT_EQ(a.collisions.size(), b.collisions.size());
  for (std::size_t i = 0; i < a.collisions.size(); ++i) {
    EXPECT_EQ(a.collisions[i].actors, b.collisions[i].actors) << i;
    EXPECT_EQ(a.collisions[i].event, b.collisions[i].event) << i;
    EXPECT_EQ(a.collisions[i].time, b.collisions[i].time) << i;
    EXPECT_EQ(a.collisions[i].point, b.collisions[i].point) << i;
  }
  ASSERT_EQ(a.frames.size(), b.frames.size());
  for (std::size_t i = 0; i < a.frames.size(); ++i) {
    EXPECT_EQ(a.frames[i].time, b.frames[i].time) << i;
    EXPECT_EQ(a.frames[i].event, b.frames[i].event) << i;
    EXPECT_EQ(a.frames[i].state.angles, b.frames[i].state.angles) << i;
  }
}

}  // namespace foldkit::test
