// Flaps on a fixed base against closed forms: the torque that lifts a flap against gravity
// (m·g·d), the period of a free flap swinging as a physical pendulum (elliptic integral), and
// the angle where a spring balances gravity.
#include <cmath>

#include <gtest/gtest.h>

#include "flap_patterns.hpp"
#include "foldkit/dynamics/dynamic_simulate.hpp"

using namespace foldkit;

namespace {

constexpr double kG = 9.81, kDensity = 0.8, kScale = 0.2;

geometry::FoldSequence one_fold(int joint, double angle, double speed) {
  geometry::FoldSequence s;
  s.events.push_back({1, {{joint, angle, speed, 0}}});
  return s;
}

dynamics::DynamicOptions gravity_options() {
  dynamics::DynamicOptions o;
  o.gravity = Eigen::Vector3d(0, 0, -kG);
  o.density = kDensity;
  o.scale = kScale;
  return o;
}

// m·g·d of the flap at the horizontal, N·m.
double lift_torque(const test::Flap& flap) {
  const auto m = test::moments(flap.polygon);
  return kDensity * kG * m.first * std::pow(kScale, 3);
}

}  // namespace

TEST(DynamicFlap, MotorWithMoreThanWeightTorqueLiftsEveryShape) {
  for (const auto& flap : test::flap_shapes()) {
    SCOPED_TRACE(flap.name);
    const auto pattern = geometry::build_or_throw(test::flap_spec(flap));
    auto o = gravity_options();
    o.max_torque = 1.05 * lift_torque(flap);
    o.record_frames = true;
    // Lifting the flap above the base is a valley fold (negative).
    const auto r = dynamics::simulate_dynamic(pattern, one_fold(1, -1.0, 0.5), o);
    EXPECT_TRUE(r.status.ok()) << r.status.message;
    // Turning at its steady speed the motor carries the weight alone: m·g·d·cos θ (lifting is
    // negative torque). The frames from 0.5 rad on are past the acceleration.
    ASSERT_EQ(r.frame_torques.size(), r.frames.size());
    int steady = 0;
    for (std::size_t k = 0; k < r.frames.size(); ++k) {
      const double angle = r.frames[k].state.angles[0];
      if (angle > -0.5 || angle < -0.9) continue;
      EXPECT_NEAR(-r.frame_torques[k][0], lift_torque(flap) * std::cos(angle), 0.01 * lift_torque(flap)) << angle;
      ++steady;
    }
    EXPECT_GT(steady, 10);
    EXPECT_NEAR(r.final_state.angles[0], -1.0, 2e-4);
    EXPECT_TRUE(r.stalls.empty());
    EXPECT_LE(r.joints[0].peak_torque, o.max_torque * (1 + 1e-3));  // read off the joint's wrench
    EXPECT_GE(r.joints[0].peak_torque, 0.99 * lift_torque(flap));
  }
}

TEST(DynamicFlap, MotorWithLessThanWeightTorqueStallsNamingTheJoint) {
  for (const auto& flap : test::flap_shapes()) {
    SCOPED_TRACE(flap.name);
    const auto pattern = geometry::build_or_throw(test::flap_spec(flap));
    auto o = gravity_options();
    o.max_torque = 0.95 * lift_torque(flap);
    const auto r = dynamics::simulate_dynamic(pattern, one_fold(1, -1.0, 0.5), o);
    EXPECT_EQ(r.status.code, geometry::StatusCode::NoProgress);
    ASSERT_EQ(r.stalls.size(), 1u);
    const auto& s = r.stalls[0];
    EXPECT_EQ(s.joint, 1);
    EXPECT_NE(r.status.message.find("joint 1"), std::string::npos) << r.status.message;
    EXPECT_DOUBLE_EQ(s.available_torque, o.max_torque);
    // Held where it stalled (near the horizontal), it needs m·g·d·cos θ.
    EXPECT_NEAR(s.needed_torque, lift_torque(flap) * std::cos(s.angle), 0.01 * lift_torque(flap));
    EXPECT_GT(s.needed_torque, s.available_torque);
    EXPECT_FALSE(r.events.at(0).reached);
  }
}

TEST(DynamicFlap, FreeFlapSwingsWithThePendulumPeriod) {
  for (const auto& flap : test::flap_shapes()) {
    SCOPED_TRACE(flap.name);
    auto spec = test::flap_spec(flap);
    test::add_clock_flap(spec);
    const auto pattern = geometry::build_or_throw(spec);
    auto o = gravity_options();
    o.time_step = 2e-4;
    o.check_interval = 1e-3;
    o.record_frames = true;
    o.start = Eigen::Vector2d(0.4, 0.0);  // released 0.4 rad below the horizontal
    const auto r = dynamics::simulate_dynamic(pattern, one_fold(2, -1.5, 0.5), o);  // the clock: 3 s
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    // Physical pendulum about the hinge: T = 4 √(I/(m g d)) K(sin(θ₀/2)), θ₀ the amplitude about
    // the hanging position (π/2).
    const auto m = test::moments(flap.polygon);
    const double L = kScale, I = kDensity * m.second * L * L * L * L, mgd = kDensity * kG * m.first * L * L * L;
    const double amplitude = M_PI / 2 - 0.4;
    const double period = 4.0 * std::sqrt(I / mgd) * std::comp_ellint_1(std::sin(amplitude / 2));
    // Upward crossings of the hanging position, interpolated between frames.
    std::vector<double> crossings;
    for (std::size_t k = 1; k < r.frames.size(); ++k) {
      const double a = r.frames[k - 1].state.angles[0] - M_PI / 2, b = r.frames[k].state.angles[0] - M_PI / 2;
      if (a < 0 && b >= 0) crossings.push_back(r.frames[k - 1].time + (r.frames[k].time - r.frames[k - 1].time) * a / (a - b));
    }
    ASSERT_GE(crossings.size(), 2u);
    const double measured = (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
    EXPECT_NEAR(measured, period, 0.01 * period) << "measured " << measured << " s, closed form " << period << " s";
  }
}

TEST(DynamicFlap, SpringSettlesWhereItBalancesGravity) {
  for (const auto& flap : test::flap_shapes()) {
    SCOPED_TRACE(flap.name);
    const double mgd = lift_torque(flap), k = 2.0 * mgd, target = 0.2;
    const auto m = test::moments(flap.polygon);
    const double I = kDensity * m.second * std::pow(kScale, 4);
    const auto pattern = geometry::build_or_throw(test::flap_spec(flap, k, 2.0 * std::sqrt(k * I)));
    auto o = gravity_options();
    o.drive = dynamics::Drive::Spring;
    o.settle_speed = 1e-5;
    const auto r = dynamics::simulate_dynamic(pattern, one_fold(1, target, 1.0), o);
    // k(θ − θ*) = m g d cos θ, by Newton from θ*.
    double theta = target;
    for (int i = 0; i < 50; ++i)
      theta -= (k * (theta - target) - mgd * std::cos(theta)) / (k + mgd * std::sin(theta));
    EXPECT_NEAR(r.final_state.angles[0], theta, 1e-3);
    // The spring does not reach its own angle: reported as a stall of joint 1, with the torque
    // it had (k·|θ* − θ|) against what holding there needs (m g d cos θ).
    ASSERT_EQ(r.stalls.size(), 1u);
    EXPECT_EQ(r.stalls[0].joint, 1);
    EXPECT_NEAR(r.stalls[0].needed_torque, mgd * std::cos(theta), 0.01 * mgd);
    EXPECT_NEAR(r.stalls[0].available_torque, k * (theta - target), 0.01 * mgd);
  }
}

// A complete fold (±180°), the last event of much origami: the angle reads in (−π, π], and the
// motor must stop at ±π rather than turn back through flat once it reads −π + ε. Without gravity
// a motor folds the flap onto the base and holds it; beyond ±180° is refused.
TEST(DynamicFlap, MotorFoldsTheFlapCompletelyFlatOntoTheBase) {
  const auto pattern = geometry::build_or_throw(test::flap_spec(test::flap_shapes().front()));
  for (double target : {M_PI, -M_PI}) {
    SCOPED_TRACE(target);
    dynamics::DynamicOptions o;
    o.max_torque = 10.0;
    o.max_event_time = 20.0;
    const auto r = dynamics::simulate_dynamic(pattern, one_fold(1, target, 1.0), o);
    EXPECT_TRUE(r.status.ok()) << r.status.message;
    EXPECT_LE(std::abs(std::remainder(r.final_state.angles[0] - target, 2.0 * M_PI)), 2e-4);
    EXPECT_LT(r.duration, 5.0);  // π rad at 1 rad/s, not a turn back the long way
  }
  EXPECT_THROW(dynamics::simulate_dynamic(pattern, one_fold(1, 3.2, 1.0), dynamics::DynamicOptions{}), std::invalid_argument);
}
