// Contacts (DynamicOptions::ground, contacts) against closed forms and the kinematic simulator:
// a flap dropped onto the ground rests where its far edge touches it, a block on an incline sticks
// or slides as Coulomb's law says, a flap folded onto another stops on it (where the kinematic
// simulator reports the crossing), and a fold that touches nothing is not changed by contacts.
#include <cmath>

#include <gtest/gtest.h>

#include "flap_patterns.hpp"
#include "foldkit/dynamics/dynamic_simulate.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/simulation/simulate.hpp"
#include "one_motor_miura.hpp"

using namespace foldkit;

namespace {

constexpr double kG = 9.81;

geometry::FoldSequence one_fold(int joint, double angle, double speed) {
  geometry::FoldSequence s;
  s.events.push_back({1, {{joint, angle, speed, 0}}});
  return s;
}

// The flap of side L hangs from the hinge at z = 0 until the lower corner of its far edge, t/2
// below its mid-surface, touches the ground z = −h: L sin φ + (t/2) cos φ = h, by Newton.
double resting_angle(double L, double t, double h) {
  double phi = std::asin(h / L);
  for (int i = 0; i < 50; ++i)
    phi -= (L * std::sin(phi) + t / 2 * std::cos(phi) - h) / (L * std::cos(phi) - t / 2 * std::sin(phi));
  return phi;
}

// +1 when folding joint index j by a positive angle lifts `actor` (index) above the flat sheet
// (z > 0), the first actor held; −1 when it lowers it.
double lifting_sign(const geometry::CreasePattern& p, int j, int actor) {
  geometry::FoldState s = geometry::FoldState::flat(p);
  s.angles[j] = M_PI / 2;
  const auto poses = geometry::facet_poses(p, geometry::make_tree(p), s);
  const auto& V = p.vertices();
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& t : p.actors()[actor].triangles)
    for (int v : t.v) c += poses[actor] * Eigen::Vector3d(V[v].x(), V[v].y(), 0.0);
  return c.z() > 0 ? 1.0 : -1.0;
}

}  // namespace

TEST(DynamicContact, FlapDroppedOntoTheGroundRestsWhereItsEdgeTouches) {
  auto spec = test::flap_spec(test::flap_shapes().front());  // a unit square flap on x ≥ 0
  test::add_clock_flap(spec);
  const auto pattern = geometry::build_or_throw(spec);
  const double scale = 0.2, h = 0.1, t = 1e-3;
  dynamics::DynamicOptions o;
  o.gravity = Eigen::Vector3d(0, 0, -kG);
  o.scale = scale;
  o.ground = -h;
  o.thickness = t;
  const auto r = dynamics::simulate_dynamic(pattern, one_fold(2, -1.5, 0.5), o);  // the clock: 3 s
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  const double phi = resting_angle(scale, t, h);
  // Positive: the flap hangs below the base. At rest the ground's penetration is the engine's
  // contact error, below a tenth of the thickness: the angle within that over the flap's length.
  EXPECT_NEAR(r.final_state.angles[0], phi, 0.1 * t / scale);
  EXPECT_NEAR(r.kinetic_energy, 0.0, 1e-6);
  ASSERT_EQ(r.contacts.size(), 1u);
  EXPECT_TRUE(r.contacts[0].ground);
  EXPECT_EQ(r.contacts[0].actors, std::vector<int>{2});
  EXPECT_NEAR(r.contacts[0].point.z(), -h, r.max_penetration + 1e-12);  // the prism's deepest corner
  // The impact's penetration: at most one step's travel of the far edge, which arrives at
  // ω L, ½ I ω² = m g d sin φ (energy; I and m g d of the unit square about its hinge).
  const double m = scale * scale, I = m * scale * scale / 3.0, omega = std::sqrt(2.0 * m * kG * scale / 2.0 * std::sin(phi) / I);
  EXPECT_GT(r.max_penetration, 0.0);
  EXPECT_LE(r.max_penetration, omega * scale * o.time_step);
  EXPECT_DOUBLE_EQ(r.thickness, t);
  // Without a ground the same flap swings through that angle.
  o.ground.reset();
  o.thickness.reset();  // with nothing to touch it would be ignored: refused
  o.record_frames = true;
  const auto free = dynamics::simulate_dynamic(pattern, one_fold(2, -1.5, 0.5), o);
  double lowest = 0.0;
  for (const auto& f : free.frames) lowest = std::max(lowest, f.state.angles[0]);
  EXPECT_GT(lowest, phi + 0.5);
  EXPECT_TRUE(free.contacts.empty());
  EXPECT_EQ(free.thickness, 0.0);
}

// A square block on a plane inclined by α (gravity tilted by α, the ground level): with μ < tan α
// it slides down with acceleration g (sin α − μ cos α), with μ > tan α it stays. Its travel is
// read off the gravitational energy (−m g sin α · travel) and its speed off the kinetic energy.
TEST(DynamicContact, BlockOnAnInclineSlidesOrSticksAsCoulombSays) {
  geometry::PatternSpec spec;
  // The block: a unit square with a corner cut at (0, 0.99), where the clock's joint is.
  spec.actors.push_back({1, {{{{{0, 0}, {1, 0}, {1, 1}}}}, {{{{0, 0}, {1, 1}, {0, 0.99}}}}, {{{{0, 0.99}, {1, 1}, {0, 1}}}}}});
  spec.actors.push_back({2, {{{{{0, 1}, {0, 0.99}, {-0.01, 0.995}}}}}});  // the clock: 5e-5 of the block's mass
  spec.joints.push_back({1, {{{0, 0.99}, {0, 1}}}, {1, 2}, 0.0, 0.0});
  const auto pattern = geometry::build_or_throw(spec);
  const double alpha = 0.3, scale = 0.1, t = 1e-3, density = 1.0;
  const double mass = density * scale * scale;
  for (double mu : {0.1, 0.2, 0.4}) {
    SCOPED_TRACE(mu);
    dynamics::DynamicOptions o;
    o.gravity = kG * Eigen::Vector3d(std::sin(alpha), 0, -std::cos(alpha));
    o.scale = scale;
    o.density = density;
    o.hold_fixed = false;
    o.ground = -t / 2;  // the block's lower face on it
    o.thickness = t;
    o.friction = mu;
    o.max_torque = 1e-3;
    const auto r = dynamics::simulate_dynamic(pattern, one_fold(1, -1.0, 1.0), o);  // about 1 s
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    const double T = r.duration, a = std::max(0.0, kG * (std::sin(alpha) - mu * std::cos(alpha)));
    const double travel = -r.potential_energy / (mass * kG * std::sin(alpha));
    EXPECT_NEAR(travel, 0.5 * a * T * T, 0.02 * 0.5 * kG * std::sin(alpha) * T * T) << "T = " << T;
    EXPECT_NEAR(std::sqrt(2.0 * r.kinetic_energy / mass), a * T, 0.02 * kG * std::sin(alpha) * T);
    EXPECT_LE(r.max_penetration, 0.1 * t);
  }
}

// A fixed base (actor 1) with flap A (actor 2, joint 1, 0.7 wide) on its left edge and flap B
// (actor 3, joint 2, 0.7 wide) on its right edge.
geometry::CreasePattern two_flaps() {
  geometry::PatternSpec spec;
  spec.actors.push_back({1, {{{{{0, 0}, {1, 0}, {1, 1}}}}, {{{{0, 0}, {1, 1}, {0, 1}}}}}});
  spec.actors.push_back({2, {{{{{0, 0}, {0, 1}, {-0.7, 1}}}}, {{{{0, 0}, {-0.7, 1}, {-0.7, 0}}}}}});
  spec.actors.push_back({3, {{{{{1, 0}, {1.7, 0}, {1.7, 1}}}}, {{{{1, 0}, {1.7, 1}, {1, 1}}}}}});
  spec.joints.push_back({1, {{{0, 0}, {0, 1}}}, {1, 2}, 0.0, 0.0});
  spec.joints.push_back({2, {{{1, 0}, {1, 1}}}, {1, 3}, 0.0, 0.0});
  return geometry::build_or_throw(spec);
}

// A folded first (1 rad/s) up over the base to lie `lean` above it, then B over onto the base at
// `speed`: both up, the same side, whatever the crease directions.
geometry::FoldSequence fold_b_onto_a(const geometry::CreasePattern& pattern, double lean, double speed) {
  const double sign_a = lifting_sign(pattern, 0, 1), sign_b = lifting_sign(pattern, 1, 2);
  geometry::FoldSequence seq;
  seq.events.push_back({1, {{1, sign_a * (M_PI - lean), 1.0, 0}}});
  seq.events.push_back({2, {{2, sign_b * M_PI, speed, 0}}});
  return seq;
}

// A is folded first (a strong motor) to lie 10° above the base; then B, folded over onto the
// base, meets A's far edge and stops there — blocked, a collision, exit 3 — where the kinematic
// simulator reports the two passing through each other. B stops where its lower face touches the
// upper corner of A's far edge: with P that corner relative to B's hinge (d to the left, h up),
// d sin φ − h cos φ = t/2 for B's angle φ above the base.
TEST(DynamicContact, FlapFoldedOntoAnotherStopsOnItInsteadOfPassingThrough) {
  const auto pattern = two_flaps();
  const double lean = 10.0 * M_PI / 180.0, t = 2e-3;
  const geometry::FoldSequence seq = fold_b_onto_a(pattern, lean, 1.0);
  // The kinematic simulator: B passes through A.
  const auto kinematic = simulation::simulate(pattern, seq, simulation::SimulationOptions{});
  ASSERT_EQ(kinematic.status.code, geometry::StatusCode::Collision) << kinematic.status.message;
  dynamics::DynamicOptions o;
  o.contacts = true;
  o.thickness = t;
  o.joint_max_torque[1] = 1e3;
  o.max_torque = 1.0;
  const auto r = dynamics::simulate_dynamic(pattern, seq, o);
  EXPECT_EQ(r.status.code, geometry::StatusCode::Collision) << r.status.message;
  ASSERT_EQ(r.stalls.size(), 1u);
  EXPECT_EQ(r.stalls[0].joint, 2);
  EXPECT_EQ(r.stalls[0].blocked_by, (std::vector<int>{2, 3}));
  EXPECT_NE(r.status.message.find("joint 2 blocked"), std::string::npos) << r.status.message;
  ASSERT_EQ(r.events.size(), 2u);
  EXPECT_TRUE(r.events[0].reached);
  EXPECT_FALSE(r.events[1].reached);
  // A's top corner at its far edge, relative to B's hinge (x = 1, z = 0), the base's upper side z > 0.
  const Eigen::Vector2d tip = 0.7 * Eigen::Vector2d(std::cos(lean), std::sin(lean)) +
                              t / 2 * Eigen::Vector2d(-std::sin(lean), std::cos(lean));
  const double d = 1.0 - tip.x(), h = tip.y();
  double phi = std::atan2(h, d);
  for (int i = 0; i < 50; ++i) phi -= (d * std::sin(phi) - h * std::cos(phi) - t / 2) / (d * std::cos(phi) + h * std::sin(phi));
  // Pressed by its motor, B sinks into A by the contacts' penetration at most: 0.1 t at lever d.
  EXPECT_NEAR(std::abs(r.final_state.angles[1]), M_PI - phi, 0.1 * t / d);
  EXPECT_NEAR(std::abs(r.final_state.angles[0]), M_PI - lean, 1e-3);
  EXPECT_LE(r.max_penetration, 0.1 * t);
  ASSERT_EQ(r.contacts.size(), 1u);
  EXPECT_EQ(r.contacts[0].actors, (std::vector<int>{2, 3}));
  EXPECT_EQ(r.contacts[0].event, 2);
  EXPECT_FALSE(r.contacts[0].ground);
  // Without contacts the dynamic model, like the kinematic one, lets B pass through A to its angle.
  o.contacts = false;
  o.thickness.reset();  // with nothing to touch it would be ignored: refused
  const auto through = dynamics::simulate_dynamic(pattern, seq, o);
  EXPECT_TRUE(through.status.ok()) << through.status.message;
  EXPECT_NEAR(std::abs(through.final_state.angles[1]), M_PI, 2e-4);
}

// A Miura-ori folded by one motor touches nothing: with contacts on, every crease still follows
// the kinematic fold, and no contact is reported (the facets meeting at a vertex are not one).
TEST(DynamicContact, MiuraFoldWithContactsStillMatchesTheKinematicFold) {
  const microbench::OneMotorMiura scene = microbench::one_motor_miura(4);
  dynamics::DynamicOptions o;
  o.start = scene.start;
  o.max_torque = 1e3;
  o.contacts = true;
  const auto r = dynamics::simulate_dynamic(scene.pattern, scene.sequence, o);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_TRUE(r.contacts.empty()) << r.contacts.size() << " contacts, the first between actors " << r.contacts[0].actors[0];
  EXPECT_LE(r.max_closure_error, 1e-4);
  EXPECT_LE((r.final_state.angles - scene.kinematic.states.back().angles).cwiseAbs().maxCoeff(), 1e-3);
}

// B driven so fast (20 rad/s, 6 mm a step at A's edge) that it enters A by more than the
// thickness (1 mm) in one step: a collision that names a time step, and at that step B is
// blocked on A as at 1 rad/s. (Faster still, B could jump A unseen: see docs/SIMULATION.md.)
TEST(DynamicContact, FlapTooFastForTheThicknessIsRefusedNamingTheTimeStep) {
  const auto pattern = two_flaps();
  const geometry::FoldSequence seq = fold_b_onto_a(pattern, 10.0 * M_PI / 180.0, 20.0);
  dynamics::DynamicOptions o;
  o.contacts = true;
  o.thickness = 1e-3;
  o.joint_max_torque[1] = 1e3;
  o.max_torque = 100.0;
  const auto fast = dynamics::simulate_dynamic(pattern, seq, o);
  EXPECT_EQ(fast.status.code, geometry::StatusCode::Collision);
  const std::string& m = fast.status.message;
  EXPECT_NE(m.find("passed through"), std::string::npos) << m;
  EXPECT_GT(fast.max_penetration, o.thickness);
  const auto at = m.find("try a time step below ");
  ASSERT_NE(at, std::string::npos) << m;
  o.time_step = 0.9 * std::stod(m.substr(at + std::string("try a time step below ").size()));
  const auto r = dynamics::simulate_dynamic(pattern, seq, o);
  EXPECT_EQ(r.status.code, geometry::StatusCode::Collision);
  ASSERT_EQ(r.stalls.size(), 1u) << r.status.message;
  EXPECT_EQ(r.stalls[0].blocked_by, (std::vector<int>{2, 3}));
  EXPECT_LE(r.max_penetration, o.thickness);
}
