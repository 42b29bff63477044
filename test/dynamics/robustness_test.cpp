// Stiff and extreme inputs: no NaN, no blow-up; bad options refused.
#include <cmath>

#include <gtest/gtest.h>

#include "foldkit/dynamics/dynamic_simulate.hpp"
#include "foldkit/geometry/generators.hpp"

using namespace foldkit;

TEST(DynamicRobustness, SpringsFromMilliToGigaOnOneSheetStayFinite) {
  // A strip of 13 panels, spring constants 1e-3 … 1e9 N·m/rad (a 1e12 ratio), critically damped
  // for a unit panel, all driven toward 0.3 rad under gravity.
  auto spec = geometry::generators::strip(13);
  for (std::size_t j = 0; j < spec.joints.size(); ++j) {
    spec.joints[j].spring = std::pow(10.0, -3.0 + static_cast<double>(j));
    spec.joints[j].damping = 2.0 * std::sqrt(spec.joints[j].spring / 3.0);
  }
  const auto p = geometry::build_or_throw(spec);
  geometry::FoldSequence seq;
  seq.events.push_back({1, {}});
  for (const auto& j : p.joints()) seq.events[0].folds.push_back({j.id, 0.3, 1.0, 0});
  dynamics::DynamicOptions o;
  o.drive = dynamics::Drive::Spring;
  o.gravity = Eigen::Vector3d(0, 0, -9.81);
  o.max_event_time = 5.0;
  const auto r = dynamics::simulate_dynamic(p, seq, o);
  EXPECT_NE(r.status.code, geometry::StatusCode::Singular) << r.status.message;
  ASSERT_TRUE(r.final_state.angles.allFinite());
  EXPECT_LE(r.final_state.angles.cwiseAbs().maxCoeff(), M_PI);
  EXPECT_TRUE(std::isfinite(r.kinetic_energy) && std::isfinite(r.potential_energy) && std::isfinite(r.spring_energy));
  // The springs of 1e6 N·m/rad and stiffer hold their angle within 1e-3 rad against the weight
  // of the strip beyond them (at most 5 kg at 2.5 m: 123 N·m, 1.2e-4 rad at 1e6).
  for (std::size_t j = 9; j < p.joints().size(); ++j) EXPECT_NEAR(r.final_state.angles[static_cast<Eigen::Index>(j)], 0.3, 1e-3) << j;
}

TEST(DynamicRobustness, BadOptionsAreRefused) {
  const auto p = geometry::build_or_throw(geometry::generators::strip(2));
  geometry::FoldSequence seq;
  seq.events.push_back({1, {{1, 0.5, 1.0, 0}}});
  auto refuse = [&](auto change) {
    dynamics::DynamicOptions o;
    change(o);
    EXPECT_THROW(dynamics::simulate_dynamic(p, seq, o), std::invalid_argument);
  };
  refuse([](auto& o) { o.density = -1.0; });
  refuse([](auto& o) { o.max_torque = -1.0; });
  refuse([](auto& o) { o.max_torque = NAN; });
  refuse([](auto& o) { o.gravity = Eigen::Vector3d(NAN, 0, -9.81); });
  refuse([](auto& o) { o.scale = 0.0; });
  refuse([](auto& o) { o.time_step = INFINITY; });
  refuse([](auto& o) { o.time_step = 0.5; });  // longer than the motors' approach_time
  refuse([](auto& o) { o.fixed_actor = 99; });
  refuse([](auto& o) { o.iterations = 0; });
  refuse([](auto& o) { o.projection_interval = -0.01; });
  refuse([](auto& o) { o.projection_interval = NAN; });
  refuse([](auto& o) { o.start = Eigen::VectorXd::Constant(5, 0.1); });
  geometry::FoldSequence unknown;
  unknown.events.push_back({1, {{42, 0.5, 1.0, 0}}});
  EXPECT_THROW(dynamics::simulate_dynamic(p, unknown, {}), std::invalid_argument);
  geometry::FoldSequence slow;
  slow.events.push_back({1, {{1, 0.5, 0.0, 7}}});
  try {
    dynamics::simulate_dynamic(p, slow, {});
    ADD_FAILURE() << "a zero speed was accepted";
  } catch (const simulation::SequenceError& e) {
    EXPECT_EQ(e.line, 7);
  }
}

TEST(DynamicRobustness, FixedActorStaysAndOthersFold) {
  // Holding the last panel instead of the first: the motors still reach their angles.
  const auto p = geometry::build_or_throw(geometry::generators::strip(3));
  geometry::FoldSequence seq;
  seq.events.push_back({1, {{1, 0.8, 1.0, 0}, {2, -0.5, 1.0, 0}}});
  dynamics::DynamicOptions o;
  o.fixed_actor = p.actors().back().id;
  o.record_frames = true;
  const auto r = dynamics::simulate_dynamic(p, seq, o);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_NEAR(r.final_state.angles[0], 0.8, 1e-4);
  EXPECT_NEAR(r.final_state.angles[1], -0.5, 1e-4);
  EXPECT_GT(r.frames.size(), 10u);
  EXPECT_EQ(r.events.size(), 1u);
  EXPECT_TRUE(r.events[0].reached);
}

// A soft spring, gravity off, starts so slowly (ω = √(k/I) = 0.5 rad/s) that every joint stays
// below settle_speed for settle_time far from its angle: that is not settled. Critically damped,
// it reaches its angle (θ*(1 − (1 + ωt)e^{−ωt})) and the run succeeds.
TEST(DynamicRobustness, SoftSpringIsNotSettledBeforeItMoves) {
  geometry::PatternSpec spec;
  spec.actors.push_back({1, {{{{{-1, 0}, {0, 0}, {0, 1}}}}, {{{{-1, 0}, {0, 1}, {-1, 1}}}}}});
  spec.actors.push_back({2, {{{{{0, 0}, {1, 0}, {1, 1}}}}, {{{{0, 0}, {1, 1}, {0, 1}}}}}});
  const double I = 1.0 / 3.0, omega = 0.5, k = omega * omega * I;  // the unit square about its edge, 1 kg/m²
  spec.joints.push_back({1, {{{0, 0}, {0, 1}}}, {1, 2}, k, 2.0 * std::sqrt(k * I)});
  const auto p = geometry::build_or_throw(spec);
  geometry::FoldSequence seq;
  seq.events.push_back({1, {{1, 0.3, 1.0, 0}}});
  dynamics::DynamicOptions o;
  o.drive = dynamics::Drive::Spring;
  o.settle_speed = 1e-2;  // the spring turns slower than this for its first 0.27 s (2 settle_times)
  o.reach_tolerance = 1e-3;
  const auto r = dynamics::simulate_dynamic(p, seq, o);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_NEAR(r.final_state.angles[0], 0.3, o.reach_tolerance);
  // Critically damped, it comes within the settle speed and the tolerance after some 20 s.
  EXPECT_GT(r.duration, 10.0);
}

// The engine's own refusal (ODE rejects a body whose inertia is not positive definite — here a
// density so small that the inertia underflows) is a status in the report, not an exception.
TEST(DynamicRobustness, EngineErrorIsAStatusNotAnException) {
  const auto p = geometry::build_or_throw(geometry::generators::strip(3));
  geometry::FoldSequence seq;
  seq.events.push_back({1, {{1, 0.5, 1.0, 0}}});
  dynamics::DynamicOptions o;
  o.density = 1e-320;
  dynamics::DynamicReport r;
  ASSERT_NO_THROW(r = dynamics::simulate_dynamic(p, seq, o));
  EXPECT_EQ(r.status.code, geometry::StatusCode::Singular) << r.status.message;
  EXPECT_NE(r.status.message.find("ODE"), std::string::npos) << r.status.message;
  EXPECT_EQ(r.final_state.angles.size(), 2);
}
