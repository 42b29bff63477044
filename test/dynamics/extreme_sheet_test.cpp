// Extreme sheets under the dynamic model (issue 33's "stiff and extreme"): a degree-32 vertex and
// sliver facets. Whatever the engine makes of them: no NaN, no blow-up, the sheet settles or the
// motors reach their angles — or a refusal that names the time step it needs.
#include <cmath>

#include <gtest/gtest.h>

#include "foldkit/dynamics/dynamic_simulate.hpp"
#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"

using namespace foldkit;

namespace {

// The report is finite everywhere and says either what happened or which time step to try.
void expect_sane(const dynamics::DynamicReport& r) {
  ASSERT_TRUE(r.final_state.angles.allFinite());
  EXPECT_TRUE(std::isfinite(r.kinetic_energy) && std::isfinite(r.potential_energy) && std::isfinite(r.spring_energy));
  EXPECT_TRUE(std::isfinite(r.max_closure_error));
  if (r.status.code == geometry::StatusCode::Singular) {
    EXPECT_NE(r.status.message.find("try "), std::string::npos) << r.status.message;
  }
}

}  // namespace

// 32 equal sectors round one vertex (29 degrees of freedom), every crease a damped spring toward
// flat, under gravity, the first wedge held: the others sag and come to rest, the loop closed.
TEST(DynamicExtreme, Degree32VertexUnderGravitySettlesWithTheLoopClosed) {
  const std::vector<double> sectors(32, 2.0 * M_PI / 32.0);
  auto spec = geometry::generators::single_vertex(sectors);
  for (auto& j : spec.joints) {
    j.spring = 5.0;
    j.damping = 2.0;
  }
  const auto p = geometry::build_or_throw(spec);
  geometry::FoldSequence seq;
  seq.events.push_back({1, {}});
  for (const auto& j : p.joints()) seq.events[0].folds.push_back({j.id, 0.0, 1.0, 0});
  dynamics::DynamicOptions o;
  o.drive = dynamics::Drive::Spring;
  o.gravity = Eigen::Vector3d(0, 0, -9.81);
  o.max_event_time = 20.0;
  const auto r = dynamics::simulate_dynamic(p, seq, o);
  expect_sane(r);
  // Gravity holds the springs short of flat: a stall of the spring drive, after settling (not a
  // time-out, not a blow-up).
  EXPECT_TRUE(r.status.code == geometry::StatusCode::NoProgress || r.status.ok()) << r.status.message;
  EXPECT_LT(r.duration, o.max_event_time);
  EXPECT_LE(r.max_closure_error, o.closure_tolerance);
  EXPECT_LT(r.kinetic_energy, 1e-4 * r.peak_kinetic_energy);
  EXPECT_GT(r.final_state.angles.cwiseAbs().maxCoeff(), 1e-3);  // it did sag
}

// A strip whose middle panel is a sliver 1e-4 wide (its inertia about the creases 1e8 times
// smaller than its neighbours'): motors fold the creases on either side under gravity.
TEST(DynamicExtreme, SliverPanelFoldsWithoutBlowingUp) {
  geometry::PatternSpec s;
  const double w = 1e-4;
  s.actors.push_back({1, {{{{{0, 0}, {1, 0}, {1, 1}}}}, {{{{0, 0}, {1, 1}, {0, 1}}}}}});
  s.actors.push_back({2, {{{{{1, 0}, {1 + w, 0}, {1 + w, 1}}}}, {{{{1, 0}, {1 + w, 1}, {1, 1}}}}}});
  s.actors.push_back({3, {{{{{1 + w, 0}, {2 + w, 0}, {2 + w, 1}}}}, {{{{1 + w, 0}, {2 + w, 1}, {1 + w, 1}}}}}});
  s.joints.push_back({1, {{{1, 0}, {1, 1}}}, {1, 2}, 0.0, 0.0});
  s.joints.push_back({2, {{{1 + w, 0}, {1 + w, 1}}}, {2, 3}, 0.0, 0.0});
  const auto p = geometry::build_or_throw(s);
  geometry::FoldSequence seq;
  seq.events.push_back({1, {{1, -0.6, 1.0, 0}, {2, -0.4, 1.0, 0}}});
  dynamics::DynamicOptions o;
  o.gravity = Eigen::Vector3d(0, 0, -9.81);
  o.max_torque = 50.0;
  const auto r = dynamics::simulate_dynamic(p, seq, o);
  expect_sane(r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_NEAR(r.final_state.angles[0], -0.6, o.reach_tolerance);
  EXPECT_NEAR(r.final_state.angles[1], -0.4, o.reach_tolerance);
}

// Sliver wedges round a vertex (sectors of 1e-3 rad beside wide ones), one motor, gravity off,
// contacts on: the free creases follow without NaN or blow-up. (The wedges either side of a
// sliver lie closer than the sheet's thickness along their whole length: they touch from the
// start, and the contacts let them.)
TEST(DynamicExtreme, SliverWedgesRoundAVertexStayFinite) {
  const double eps = 1e-3;
  const std::vector<double> sectors = {M_PI / 2, eps, M_PI / 2 - eps, M_PI / 2, eps, M_PI / 2 - eps};
  const auto p = geometry::build_or_throw(geometry::generators::single_vertex(sectors));
  geometry::FoldSequence seq;
  seq.events.push_back({1, {{p.joints()[0].id, 0.5, 0.5, 0}}});
  dynamics::DynamicOptions o;
  o.max_torque = 10.0;
  o.max_event_time = 5.0;
  o.contacts = true;
  const auto r = dynamics::simulate_dynamic(p, seq, o);
  expect_sane(r);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_NEAR(r.final_state.angles[0], 0.5, o.reach_tolerance);
  const geometry::ClosureSystem closure(p, 0);
  EXPECT_LE(closure.max_error(r.final_state), o.closure_tolerance);
}
