// simulation::SequenceReplay fed one event at a time against simulate() of the whole sequence:
// the same report, accepted or rejected (the plan's replay pipeline relies on it).
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "foldkit/geometry/generators.hpp"
#include "foldkit/simulation/simulate.hpp"
#include "same_report.hpp"

namespace foldkit::simulation {
namespace {

namespace gen = geometry::generators;
using geometry::build_or_throw;
using geometry::CreasePattern;
using geometry::FoldSequence;

constexpr double kDeg = M_PI / 180.0;

SimulationReport event_by_event(const CreasePattern& p, const FoldSequence& seq, const SimulationOptions& o) {
  SequenceReplay replay(p, o);
  for (const auto& e : seq.events) replay.add(e, seq.events.size());
  return replay.finish();
}

// A Miura 4×4 folded along a straight line in angle space: loops open (closure violated) and
// facets cross, so both kinds of problem are in the report.
FoldSequence rough_miura(const CreasePattern& miura) {
  geometry::FoldState rough = geometry::FoldState::flat(miura);
  for (std::size_t j = 0; j < miura.joints().size(); ++j)
    rough.angles[static_cast<Eigen::Index>(j)] = miura.joints()[j].assignment == geometry::Assignment::Mountain ? 1.2 : -1.2;
  return geometry::sequence_to(miura, rough, 0.5);
}

TEST(SequenceReplay, ValidSequenceSameReportAsSimulate) {
  const CreasePattern strip = build_or_throw(gen::strip(3));
  const FoldSequence seq{"zig-zag", {{1, {{1, 170 * kDeg, 45 * kDeg, 0}}}, {2, {{2, -170 * kDeg, 45 * kDeg, 0}}}}};
  SimulationOptions o;
  o.record_frames = true;
  const SimulationReport whole = simulate(strip, seq, o), pieces = event_by_event(strip, seq, o);
  EXPECT_TRUE(whole.status.ok());
  test::expect_same_report(whole, pieces);
}

TEST(SequenceReplay, CollidingSequenceSameReportAsSimulate) {
  const CreasePattern strip = build_or_throw(gen::strip(3));
  const FoldSequence seq{"roll", {{1, {{1, 170 * kDeg, 45 * kDeg, 0}}}, {2, {{2, 170 * kDeg, 45 * kDeg, 0}}}}};
  const SimulationReport whole = simulate(strip, seq), pieces = event_by_event(strip, seq, {});
  EXPECT_EQ(whole.status.code, geometry::StatusCode::Collision);
  test::expect_same_report(whole, pieces);
}

TEST(SequenceReplay, ClosureAndCollisionsSameReportAsSimulate) {
  const CreasePattern miura = build_or_throw(gen::miura(4, 4));
  FoldSequence seq = rough_miura(miura);
  // Split into several events, so that the state carried from one to the next matters.
  FoldSequence split{"split", {}};
  for (int k = 1; k <= 4; ++k) {
    geometry::FoldEvent e{k, seq.events.front().folds};
    for (auto& f : e.folds) f.angle *= k / 4.0;
    split.events.push_back(e);
  }
  SimulationOptions o;
  o.record_frames = true;
  const SimulationReport whole = simulate(miura, split, o), pieces = event_by_event(miura, split, o);
  EXPECT_FALSE(whole.status.ok());
  EXPECT_FALSE(whole.problems.empty());
  test::expect_same_report(whole, pieces);
}

TEST(SequenceReplay, NoEventIsTheFlatSheet) {
  const CreasePattern strip = build_or_throw(gen::strip(3));
  SequenceReplay replay(strip);
  test::expect_same_report(simulate(strip, FoldSequence{}), replay.finish());
}

TEST(SequenceReplay, SpentAfterFinishAndOptionsChecked) {
  const CreasePattern strip = build_or_throw(gen::strip(3));
  SequenceReplay replay(strip);
  replay.finish();
  EXPECT_THROW(replay.finish(), std::logic_error);
  EXPECT_THROW(replay.add({1, {{1, 0.5, 1.0, 0}}}, 1), std::logic_error);
  SimulationOptions bad;
  bad.time_step = 0.0;
  EXPECT_THROW(SequenceReplay(strip, bad), std::invalid_argument);
}

TEST(SequenceReplay, SequenceErrorOnTheEventThatCausesIt) {
  const CreasePattern strip = build_or_throw(gen::strip(3));
  SequenceReplay replay(strip);
  replay.add({1, {{1, 0.5, 1.0, 0}}}, 2);
  EXPECT_THROW(replay.add({2, {{2, 0.5, 0.0, 7}}}, 2), SequenceError);
  // Half an event was replayed: the replay is spent, no report follows.
  EXPECT_THROW(replay.add({3, {{1, 0.2, 1.0, 0}}}, 3), std::logic_error);
  EXPECT_THROW(replay.finish(), std::logic_error);
}

}  // namespace
}  // namespace foldkit::simulation
