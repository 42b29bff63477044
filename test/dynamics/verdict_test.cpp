// The dynamic model's verdicts with contacts, against closed forms: a motor too weak to lift a flap
// off the ground has stalled (not "blocked": the ground under the flap helps it), needing the
// flap's weight torque m·g·d; one swinging under gravity stalls instead of running to the time
// limit; a soft spring lifting a flap off the ground creeps on as its damper says instead of being
// called settled and blocked; a spring pressing a flap into the ground is blocked by it where its
// edge touches, needing nothing; friction and thickness with nothing to touch are refused.
#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "flap_patterns.hpp"
#include "foldkit/dynamics/dynamic_simulate.hpp"

using namespace foldkit;

namespace {

constexpr double kG = 9.81;
// The unit-square flap at this scale and density: m = ρ s², its centroid d = s/2 from the hinge.
constexpr double kScale = 0.5, kDensity = 2.0, kThickness = 0.002;
const double kWeightTorque = kDensity * kScale * kScale * kG * kScale / 2.0;

geometry::FoldSequence one_fold(int joint, double angle, double speed) {
  geometry::FoldSequence s;
  s.events.push_back({1, {{joint, angle, speed, 0}}});
  return s;
}

geometry::CreasePattern square_flap(double spring = 0.0, double damping = 0.0) {
  return geometry::build_or_throw(test::flap_spec(test::flap_shapes().front(), spring, damping));
}

// The flap (and the held base) lying on the ground: its lower face at z = −t/2 touches it.
dynamics::DynamicOptions on_the_ground() {
  dynamics::DynamicOptions o;
  o.gravity = Eigen::Vector3d(0, 0, -kG);
  o.density = kDensity;
  o.scale = kScale;
  o.ground = -kThickness / 2;
  o.thickness = kThickness;
  return o;
}

}  // namespace

// Lifting (a negative fold) the flap off the ground needs m·g·d at the start: a motor with less
// has stalled there, and the ground, which pushes the flap up, blocks nothing.
TEST(DynamicVerdict, WeakMotorLiftingAFlapOffTheGroundStallsNeedingItsWeight) {
  const auto pattern = square_flap();
  auto o = on_the_ground();
  o.max_torque = 0.1;
  const auto r = dynamics::simulate_dynamic(pattern, one_fold(1, -M_PI / 3, 0.5), o);
  EXPECT_EQ(r.status.code, geometry::StatusCode::NoProgress) << r.status.message;
  ASSERT_EQ(r.stalls.size(), 1u);
  EXPECT_TRUE(r.stalls[0].blocked_by.empty());
  EXPECT_NE(r.status.message.find("joint 1 stalled"), std::string::npos) << r.status.message;
  EXPECT_NEAR(r.stalls[0].needed_torque, kWeightTorque, 0.01 * kWeightTorque);
  EXPECT_DOUBLE_EQ(r.stalls[0].available_torque, 0.1);
  // With a little more than the weight torque the same motor lifts it.
  o.max_torque = 1.05 * kWeightTorque;
  const auto lifted = dynamics::simulate_dynamic(pattern, one_fold(1, -M_PI / 3, 0.5), o);
  EXPECT_TRUE(lifted.status.ok()) << lifted.status.message;
  EXPECT_NEAR(lifted.final_state.angles[0], -M_PI / 3, o.reach_tolerance);
}

// Without a ground the weak motor's flap falls and swings below the base, never at rest: it has
// stalled where it came closest (flat, at the start, needing m·g·d), not run out of time.
TEST(DynamicVerdict, WeakMotorSwingingUnderGravityStallsWithoutRunningToTheTimeLimit) {
  const auto pattern = square_flap();
  auto o = on_the_ground();
  o.ground.reset();
  o.thickness.reset();
  o.max_torque = 0.1;
  const auto r = dynamics::simulate_dynamic(pattern, one_fold(1, -M_PI / 3, 0.5), o);
  EXPECT_EQ(r.status.code, geometry::StatusCode::NoProgress) << r.status.message;
  ASSERT_EQ(r.stalls.size(), 1u);
  EXPECT_NEAR(r.stalls[0].needed_torque, kWeightTorque, 0.01 * kWeightTorque);
  EXPECT_LT(r.duration, 1.0);  // simulated seconds: well before max_event_time
}

// A spring k = 1 N·m/rad, c = 2000 N·m·s/rad lifting the flap of weight torque m g d off the
// ground creeps, its inertia negligible: c θ̇ = k(θ* − θ) − m g d, so after T it has turned
// (k|θ*| − m g d)/k · (1 − e^(−kT/c)). It is slower than settle_speed from the start, touching the
// ground: neither settled nor blocked, but out of time.
TEST(DynamicVerdict, SoftSpringLiftingAFlapOffTheGroundCreepsOnInsteadOfSettling) {
  const double k = 1.0, c = 2000.0, target = -M_PI / 3, T = 2.0;
  const auto pattern = square_flap(k, c);
  auto o = on_the_ground();
  o.drive = dynamics::Drive::Spring;
  o.density = 0.01;
  o.max_event_time = T;
  const double mgd = *o.density * kScale * kScale * kG * kScale / 2.0;
  const auto r = dynamics::simulate_dynamic(pattern, one_fold(1, target, 0.5), o);
  EXPECT_EQ(r.status.code, geometry::StatusCode::LimitReached) << r.status.message;
  EXPECT_TRUE(r.stalls.empty());
  const double expected = (k * std::abs(target) - mgd) / k * (1.0 - std::exp(-k * T / c));
  EXPECT_NEAR(-r.final_state.angles[0], expected, 0.01 * expected);
  // The same sheet held by nothing, its base resting on the ground too, is not settled either.
  o.hold_fixed = false;
  const auto free = dynamics::simulate_dynamic(pattern, one_fold(1, target, 0.5), o);
  EXPECT_EQ(free.status.code, geometry::StatusCode::LimitReached) << free.status.message;
  EXPECT_TRUE(free.stalls.empty());
}

// A spring folding the flap down (no gravity) onto a ground h below the base's mid-surface stops
// where the far edge's lower corner touches it: L sin φ + (t/2) cos φ = h. It is blocked by the
// ground, and holding the flap there without the ground needs nothing.
TEST(DynamicVerdict, SpringPressingAFlapIntoTheGroundIsBlockedNeedingNothing) {
  const double L = 1.0, h = 0.0011, t = kThickness;
  const auto pattern = square_flap(1.0, 0.1);
  dynamics::DynamicOptions o;
  o.drive = dynamics::Drive::Spring;
  o.ground = -h;
  o.thickness = t;
  const auto r = dynamics::simulate_dynamic(pattern, one_fold(1, M_PI / 3, 0.5), o);
  EXPECT_EQ(r.status.code, geometry::StatusCode::Collision) << r.status.message;
  ASSERT_EQ(r.stalls.size(), 1u);
  EXPECT_EQ(r.stalls[0].blocked_by, std::vector<int>{2});
  EXPECT_NEAR(r.stalls[0].needed_torque, 0.0, 1e-6);
  EXPECT_NEAR(r.stalls[0].available_torque, 1.0 * (M_PI / 3 - r.final_state.angles[0]), 1e-9);
  double phi = std::asin(h / L);
  for (int i = 0; i < 50; ++i)
    phi -= (L * std::sin(phi) + t / 2 * std::cos(phi) - h) / (L * std::cos(phi) - t / 2 * std::sin(phi));
  EXPECT_NEAR(r.final_state.angles[0], phi, 0.1 * t / L);
}

// Friction and thickness act only on contacts: given with nothing to touch they are refused.
TEST(DynamicVerdict, FrictionOrThicknessWithNothingToTouchIsRefused) {
  const auto pattern = square_flap();
  dynamics::DynamicOptions o;
  o.friction = 0.3;
  EXPECT_THROW(dynamics::simulate_dynamic(pattern, one_fold(1, 0.5, 0.5), o), std::invalid_argument);
  o.friction.reset();
  o.thickness = 0.01;
  EXPECT_THROW(dynamics::simulate_dynamic(pattern, one_fold(1, 0.5, 0.5), o), std::invalid_argument);
  o.friction = 0.3;
  o.ground = -1.0;  // something to touch: accepted
  EXPECT_TRUE(dynamics::simulate_dynamic(pattern, one_fold(1, 0.5, 0.5), o).status.ok());
}
