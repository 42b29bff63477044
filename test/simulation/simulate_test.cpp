#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/simulation/simulate.hpp"

namespace foldkit::simulation {
namespace {

namespace gen = geometry::generators;
using geometry::build_or_throw;
using geometry::CreasePattern;
using geometry::FoldSequence;

constexpr double kDeg = M_PI / 180.0;

FoldSequence one_event(std::vector<std::pair<int, double>> folds, double degrees_per_second = 45.0) {
  FoldSequence seq{"test", {{1, {}}}};
  for (auto [id, deg] : folds) seq.events[0].folds.push_back({id, deg * kDeg, degrees_per_second * kDeg, 0});
  return seq;
}

FoldSequence in_turn(std::vector<std::pair<int, double>> folds) {
  FoldSequence seq{"test", {}};
  int n = 1;
  for (auto [id, deg] : folds) seq.events.push_back({n++, {{id, deg * kDeg, 45.0 * kDeg, 0}}});
  return seq;
}

TEST(Simulate, ZigZagStripAt170IsValid) {
  const CreasePattern strip = build_or_throw(gen::strip(3));
  for (const FoldSequence& seq : {one_event({{1, 170}, {2, -170}}), in_turn({{1, 170}, {2, -170}})}) {
    const SimulationReport r = simulate(strip, seq);
    EXPECT_TRUE(r.status.ok()) << (r.problems.empty() ? "" : r.problems.front());
    EXPECT_TRUE(r.collisions.empty());
    EXPECT_LT(r.max_closure_error, 1e-12);  // a strip has no loops
    EXPECT_NEAR(r.final_state.angles[0], 170 * kDeg, 1e-15);
    EXPECT_NEAR(r.final_state.angles[1], -170 * kDeg, 1e-15);
  }
}

TEST(Simulate, RollingStripAt170CollidesEndPanels) {
  const CreasePattern strip = build_or_throw(gen::strip(3));
  for (const FoldSequence& seq : {one_event({{1, 170}, {2, 170}}), in_turn({{1, 170}, {2, 170}})}) {
    const SimulationReport r = simulate(strip, seq);
    EXPECT_FALSE(r.status.ok());
    ASSERT_EQ(r.collisions.size(), 1u);
    const CollisionEvent& c = r.collisions.front();
    EXPECT_EQ(c.actors, (std::array<int, 2>{1, 3}));
    EXPECT_EQ(c.kind, CrossingKind::Mesh);
    EXPECT_EQ(c.event, seq.events.back().number);
    // The end panels meet above the middle panel's span (x in [1, 2] once folded back).
    EXPECT_GT(c.time, 0.0);
    EXPECT_LE(c.time, r.duration);
    EXPECT_TRUE(std::isfinite(c.point.norm()));
  }
}

TEST(Simulate, CollisionFoundEvenWithHugeTimeStep) {
  const CreasePattern strip = build_or_throw(gen::strip(3));
  SimulationOptions o;
  o.time_step = 100.0;  // one step per event: the sub-steps must catch the crossing
  const SimulationReport r = simulate(strip, one_event({{1, 170}, {2, 170}}), o);
  EXPECT_EQ(r.steps, 1u);
  EXPECT_GT(r.checks, 10u);
  ASSERT_EQ(r.collision_count, 1u);
}

TEST(Simulate, FlatFoldTo180IsTouchingNotCrossing) {
  const CreasePattern strip = build_or_throw(gen::strip(2));
  for (double deg : {180.0, -180.0}) {
    const SimulationReport r = simulate(strip, one_event({{1, deg}}));
    EXPECT_TRUE(r.status.ok()) << deg;
    EXPECT_TRUE(r.collisions.empty()) << deg;
  }
  // Three panels zig-zag flat: all three stacked, still valid.
  const CreasePattern three = build_or_throw(gen::strip(3));
  EXPECT_TRUE(simulate(three, in_turn({{1, 180}, {2, -180}})).status.ok());
  // Rolled flat one crease after the other: the third panel wraps round the first one's free
  // edge (where the second crease now lies) and lands on top of it: a valid roll.
  EXPECT_TRUE(simulate(three, in_turn({{1, 180}, {2, 180}})).status.ok());
  // Rolled flat both at once: the end panels meet half-way and cross.
  EXPECT_FALSE(simulate(three, one_event({{1, 180}, {2, 180}})).status.ok());
}

TEST(Simulate, MountainFoldsThePanelBelowTheSheet) {
  const CreasePattern strip = build_or_throw(gen::strip(2));
  for (double deg : {90.0, -90.0}) {
    const SimulationReport r = simulate(strip, one_event({{1, deg}}));
    ASSERT_TRUE(r.status.ok());
    const auto poses = geometry::facet_poses(strip, geometry::make_tree(strip), r.final_state);
    // Panel 2's centre (1.5, 0.5) turns about the crease x = 1 by 90°: to (1, 0.5, ∓0.5).
    const Eigen::Vector3d centre = poses[1] * Eigen::Vector3d(1.5, 0.5, 0.0);
    EXPECT_NEAR(centre.x(), 1.0, 1e-12);
    EXPECT_NEAR(centre.y(), 0.5, 1e-12);
    EXPECT_NEAR(centre.z(), deg > 0 ? -0.5 : 0.5, 1e-12) << "positive = mountain: the panel falls below";
  }
}

// Degree-4 flat-foldable vertex, sectors (α, β, π−α, π−β); mode I: ρ0 = ρ2, ρ3 = −ρ1,
// tan(ρ1/2) = −cos((α+β)/2)/cos((α−β)/2)·tan(ρ0/2) (NOTES.md; Belcastro & Hull).
TEST(Simulate, DegreeFourAlongItsModeIsValidOneCreaseAloneIsNot) {
  const double alpha = 1.1, beta = 0.7;
  const CreasePattern p = build_or_throw(gen::single_vertex({alpha, beta, M_PI - alpha, M_PI - beta}));
  FoldSequence mode{"mode I", {}};
  const int waypoints = 60;
  for (int i = 1; i <= waypoints; ++i) {
    const double t = 2.0 * i / waypoints;
    const double r1 = 2 * std::atan(-std::cos((alpha + beta) / 2) / std::cos((alpha - beta) / 2) * std::tan(t / 2));
    const double v = 0.5;
    mode.events.push_back({i, {{1, t, v, 0}, {2, r1, v, 0}, {3, t, v, 0}, {4, -r1, v, 0}}});
  }
  SimulationOptions sync;
  sync.model = Actuation::Synchronised;
  const SimulationReport along = simulate(p, mode, sync);
  EXPECT_TRUE(along.status.ok()) << (along.problems.empty() ? "" : along.problems.front());
  EXPECT_LT(along.max_closure_error, 1e-3);
  EXPECT_GT(along.max_closure_error, 0.0);  // between waypoints the straight line leaves the mode
  EXPECT_EQ(along.events.size(), static_cast<std::size_t>(waypoints));

  const SimulationReport lone = simulate(p, one_event({{1, 60}}));
  EXPECT_FALSE(lone.status.ok());
  EXPECT_GT(lone.max_closure_error, 1e-3);
  ASSERT_FALSE(lone.problems.empty());
  EXPECT_NE(lone.problems.front().find("closure error"), std::string::npos);
}

TEST(Simulate, MotorAndSynchronisedTiming) {
  const CreasePattern strip = build_or_throw(gen::strip(3));
  const FoldSequence seq = one_event({{1, 90}, {2, 45}}, 90.0);  // 1 s and 0.5 s at 90°/s
  SimulationOptions o;
  o.record_frames = true;
  o.time_step = 0.25;
  for (Actuation model : {Actuation::Motor, Actuation::Synchronised}) {
    o.model = model;
    const SimulationReport r = simulate(strip, seq, o);
    ASSERT_TRUE(r.status.ok());
    EXPECT_DOUBLE_EQ(r.duration, 1.0);
    ASSERT_EQ(r.frames.size(), 5u);  // flat, then 0.25, 0.5, 0.75, 1
    const auto& half = r.frames[2];
    EXPECT_DOUBLE_EQ(half.time, 0.5);
    EXPECT_NEAR(half.state.angles[0], 45 * kDeg, 1e-12);
    EXPECT_NEAR(half.state.angles[1], (model == Actuation::Motor ? 45 : 22.5) * kDeg, 1e-12);
  }
}

TEST(Simulate, SpringSettlesOnTarget) {
  geometry::PatternSpec spec = gen::strip(2, 1.0, 1.0, {4.0, 4.0});  // critically damped: c² = 4k
  const CreasePattern strip = build_or_throw(spec);
  SimulationOptions o;
  o.model = Actuation::Spring;
  const SimulationReport r = simulate(strip, one_event({{1, 90}}), o);
  ASSERT_TRUE(r.status.ok()) << r.problems.front();
  EXPECT_EQ(r.final_state.angles[0], 90 * kDeg);
  // θ(t) − θ* = −θ*(1 + 2t)e^{−2t} for ω = 2: 1e-5 rad and 1e-4 rad/s are reached near t ≈ 7.5–9 s.
  EXPECT_GT(r.duration, 5.0);
  EXPECT_LT(r.duration, 12.0);
}

TEST(Simulate, UnderdampedSpringOvershootsPast180) {
  const CreasePattern strip = build_or_throw(gen::strip(2, 1.0, 1.0, {1.0, 0.1}));
  SimulationOptions o;
  o.model = Actuation::Spring;
  const SimulationReport r = simulate(strip, one_event({{1, 180}}), o);
  EXPECT_FALSE(r.status.ok());
  ASSERT_FALSE(r.collisions.empty());
  EXPECT_EQ(r.collisions.front().kind, CrossingKind::Crease);
  EXPECT_EQ(r.collisions.front().actors, (std::array<int, 2>{1, 2}));
}

TEST(Simulate, SpringWithoutStiffnessCannotMove) {
  const CreasePattern strip = build_or_throw(gen::strip(2, 1.0, 1.0, {0.0, 1.0}));
  SimulationOptions o;
  o.model = Actuation::Spring;
  const SimulationReport r = simulate(strip, one_event({{1, 30}}), o);
  EXPECT_FALSE(r.status.ok());
  EXPECT_FALSE(r.events.front().reached);
  EXPECT_NE(r.problems.front().find("spring constant 0"), std::string::npos);
}

TEST(Simulate, EndlessEventIsRefusedWithItsLine) {
  const CreasePattern strip = build_or_throw(gen::strip(2));
  FoldSequence seq{"slow", {{1, {{1, 1.0, 1e-12, 17}}}}};
  try {
    simulate(strip, seq);
    FAIL() << "expected SequenceError";
  } catch (const SequenceError& e) {
    EXPECT_EQ(e.line, 17);
    EXPECT_NE(std::string(e.what()).find("steps"), std::string::npos);
  }
}

TEST(Simulate, BadOptionsAreRefused) {
  const CreasePattern strip = build_or_throw(gen::strip(2));
  for (double dt : {0.0, -1.0, std::nan(""), HUGE_VAL}) {
    SimulationOptions o;
    o.time_step = dt;
    EXPECT_THROW(simulate(strip, one_event({{1, 30}}), o), std::invalid_argument);
  }
  EXPECT_THROW(parse_actuation("hydraulic"), std::invalid_argument);
  EXPECT_EQ(parse_actuation("sync"), Actuation::Synchronised);
}

// path_sequence gives each joint the speed at which all of an event's joints arrive together, so
// the motor model replays it exactly as the synchronised one does.
TEST(Simulate, PathSequenceArrivesTogetherUnderMotors) {
  const CreasePattern p = build_or_throw(gen::single_vertex({1.1, 0.7, M_PI - 1.1, M_PI - 0.7}));
  std::vector<geometry::FoldState> path;
  for (double t : {0.3, 0.7, 1.2}) {
    geometry::FoldState s = geometry::FoldState::flat(p);
    const double r1 = 2 * std::atan(-std::cos(0.9) / std::cos(0.2) * std::tan(t / 2));
    s.angles << t, r1, t, -r1;
    path.push_back(s);
  }
  const FoldSequence seq = geometry::path_sequence(p, path, 0.5);
  ASSERT_EQ(seq.events.size(), 3u);
  SimulationOptions o;
  o.record_frames = true;
  const SimulationReport motor = simulate(p, seq, o);
  o.model = Actuation::Synchronised;
  const SimulationReport sync = simulate(p, seq, o);
  ASSERT_EQ(motor.frames.size(), sync.frames.size());
  for (std::size_t i = 0; i < motor.frames.size(); ++i)
    EXPECT_LT((motor.frames[i].state.angles - sync.frames[i].state.angles).cwiseAbs().maxCoeff(), 1e-12) << i;
  EXPECT_NEAR(motor.duration, 1.2 / 0.5, 1e-12);  // the fastest joint (ρ0 = ρ2) at 0.5 rad/s throughout
}

TEST(Simulate, SameInputSameReport) {
  const CreasePattern miura = build_or_throw(gen::miura(4, 4));
  const geometry::ClosureSystem sys(miura);
  geometry::FoldState rough = geometry::FoldState::flat(miura);
  for (std::size_t j = 0; j < miura.joints().size(); ++j)
    rough.angles[static_cast<Eigen::Index>(j)] = miura.joints()[j].assignment == geometry::Assignment::Mountain ? 1.2 : -1.2;
  const FoldSequence seq = geometry::sequence_to(miura, rough, 0.5);
  SimulationOptions o;
  o.record_frames = true;
  const SimulationReport a = simulate(miura, seq, o), b = simulate(miura, seq, o);
  EXPECT_EQ(a.checks, b.checks);
  EXPECT_EQ(a.max_closure_error, b.max_closure_error);
  ASSERT_EQ(a.collisions.size(), b.collisions.size());
  for (std::size_t i = 0; i < a.collisions.size(); ++i) {
    EXPECT_EQ(a.collisions[i].actors, b.collisions[i].actors);
    EXPECT_EQ(a.collisions[i].time, b.collisions[i].time);
    EXPECT_EQ(a.collisions[i].point, b.collisions[i].point);
  }
  ASSERT_EQ(a.frames.size(), b.frames.size());
  for (std::size_t i = 0; i < a.frames.size(); ++i) EXPECT_EQ(a.frames[i].state.angles, b.frames[i].state.angles);
}

}  // namespace
}  // namespace foldkit::simulation
