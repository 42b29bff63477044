// Hard simple chains for the planar Carpenter's rule (issue 36): Archimedean spirals, double
// spirals, tight zig-zags and loops that nearly touch themselves. Each must be straightened (CDR's
// theorem: every simple open chain can be) and every frame is certified by the oracle of
// carpenter_oracle.hpp, which recomputes all vertex distances and all non-adjacent bar gaps.
// Before the fix a 90-point spiral of five turns was refused ("LP failed at step 0
// (infeasible)"): its expansive motions turn the outer joints ~1e13 times faster than the inner
// ones, beyond the LP's speed box and Clp's tolerances (docs/CARPENTER.md, "Spirals").
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "carpenter_oracle.hpp"
#include "foldkit/folding/carpenter.hpp"

namespace {

using namespace foldkit::folding;
using foldkit::test::carpenter::check_frames;
using foldkit::test::carpenter::Oracle;
using Vec = Eigen::Vector2d;

// Points of r = r0 + a·θ from θ = 0, `step` apart in angle (equal_arc false) or, roughly, in arc
// length (the angle step step/|dr/dθ, r|).
Frame2 spiral(int n, double r0, double a, double step, bool equal_arc) {
  Frame2 p;
  double theta = 0.0;
  for (int i = 0; i < n; ++i) {
    const double r = r0 + a * theta;
    p.emplace_back(r * std::cos(theta), r * std::sin(theta));
    theta += equal_arc ? step / std::hypot(r, a) : step;
  }
  return p;
}

// Two spirals joined at their outer ends (both centres are chain ends, both enclosed).
Frame2 double_spiral(int n, double r0, double a, double step) {
  const Frame2 one = spiral(n, r0, a, step, false);
  double reach = 0.0;
  for (const Vec& q : one) reach = std::max(reach, q.norm());
  const Vec out = one.back().normalized() * 2.2 * reach;
  Frame2 p = one;
  for (int i = n - 1; i >= 0; --i) p.push_back(out - one[i]);  // the same spiral turned by π
  return p;
}

// An accordion: bars of length ~1 folded back and forth, `gap` apart.
Frame2 zig_zag(int n, double gap) {
  Frame2 p;
  for (int i = 0; i < n; ++i) p.emplace_back(i * gap, (i % 2) * 1.0);
  return p;
}

// Most of a circle: the last vertex is `gap` short of the first along the circle.
Frame2 almost_closed_loop(int n, double gap) {
  Frame2 p;
  const double sweep = 2.0 * M_PI - gap;
  for (int i = 0; i < n; ++i) p.emplace_back(std::cos(sweep * i / (n - 1)), std::sin(sweep * i / (n - 1)));
  return p;
}

Frame2 reversed_chain(Frame2 p) { return {p.rbegin(), p.rend()}; }
Frame2 mirrored(Frame2 p) {
  for (Vec& q : p) q.y() = -q.y();
  return p;
}

CarpenterPlanarResult run(const Frame2& input, CarpenterPlanarMethod method) {
  CarpenterPlanarOptions options;
  options.method = method;
  return carpenter_planar({input, false}, options);
}

// Straight, by the oracle's own arithmetic: the end-to-end distance equals the total length.
bool straight(const Frame2& p, double length) { return std::abs((p.back() - p.front()).norm() - length) <= 1e-9 * length; }

void expect_straightened(const CarpenterPlanarResult& r, const Frame2& input) {
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_GE(r.frames.size(), 2u);
  double length = 0.0;
  for (std::size_t i = 0; i + 1 < input.size(); ++i) length += (input[i + 1] - input[i]).norm();
  const Oracle o = check_frames(r.frames, input, false);
  EXPECT_LE(o.length_error, 1e-9);
  // Rounding of the layouts, relative to the chain's length (as carpenter_planar_methods_test).
  EXPECT_GE(o.vertex_growth, -1e-13 * length);
  EXPECT_GE(o.bar_growth, -1e-13 * length);
  EXPECT_GT(o.min_gap, 0.0);
  EXPECT_TRUE(straight(r.frames.back(), length));
  EXPECT_EQ(r.frames.front(), input);
}

void expect_straightened_both_ways(const Frame2& input, const std::string& name) {
  SCOPED_TRACE(name);
  ASSERT_NO_THROW(check_simple_chain({input, false}));
  for (const auto method : {CarpenterPlanarMethod::CarriedField, CarpenterPlanarMethod::Lp}) {
    SCOPED_TRACE(to_string(method));
    expect_straightened(run(input, method), input);
  }
}

// The spiral of the issue: r = 0.2 + 0.05·θ, 0.35 rad apart, 90 points (five turns). The LP over
// the whole chain fails on it, so some steps hold the slow centre rigid.
TEST(CarpenterPlanarHardChains, TheIssuesNinetyPointSpiralStraightens) {
  const Frame2 p = spiral(90, 0.2, 0.05, 0.35, false);
  expect_straightened_both_ways(p, "spiral 90");
  EXPECT_GT(run(p, CarpenterPlanarMethod::Lp).held_steps, 0u);
}

// Archimedean spirals of 20–130 points, by angle and by arc length, wound both ways, entered from
// the centre or from outside.
TEST(CarpenterPlanarHardChains, ArchimedeanSpiralsStraighten) {
  struct Spec {
    int n;
    double r0, a, step;
    bool equal_arc;
  };
  const Spec specs[] = {{20, 0.2, 0.05, 0.35, false}, {60, 0.2, 0.05, 0.35, false}, {100, 0.2, 0.05, 0.35, false},
                        {80, 0.1, 0.1, 0.3, false},   {130, 0.3, 0.03, 0.08, true}, {120, 0.5, 0.05, 0.1, true},
                        {70, 0.05, 0.02, 0.5, false}};
  int k = 0;
  for (const Spec& s : specs) {
    Frame2 p = spiral(s.n, s.r0, s.a, s.step, s.equal_arc);
    if (k % 2 == 1) p = mirrored(p);
    if (k % 3 == 2) p = reversed_chain(p);
    expect_straightened_both_ways(p, "spiral " + std::to_string(k++) + " of " + std::to_string(s.n) + " points");
  }
}

TEST(CarpenterPlanarHardChains, TightZigZagsAndNearlyTouchingLoopsStraighten) {
  for (const double gap : {1e-2, 1e-3})
    expect_straightened_both_ways(zig_zag(30, gap), "zig-zag, gap " + std::to_string(gap));
  for (const double gap : {1e-2, 1e-4})
    expect_straightened_both_ways(almost_closed_loop(40, gap), "loop, gap " + std::to_string(gap));
}

// The same spiral twice gives the same frames, bit for bit, through the held steps too.
TEST(CarpenterPlanarHardChains, HeldStepsAreDeterministic) {
  const Frame2 p = spiral(100, 0.2, 0.05, 0.35, false);
  const CarpenterPlanarResult a = run(p, CarpenterPlanarMethod::CarriedField);
  const CarpenterPlanarResult b = run(p, CarpenterPlanarMethod::CarriedField);
  ASSERT_TRUE(a.status.ok()) << a.status.message;
  EXPECT_GT(a.held_steps, 0u);
  EXPECT_EQ(a.frames, b.frames);
  EXPECT_EQ(a.lp_solves, b.lp_solves);
}

// The oracle's crossing test: two bars crossing give gap 0; two bars on one line, apart, give
// their distance along it even where rounding makes the orientation signs disagree.
TEST(CarpenterPlanarHardChains, OracleTellsCrossingBarsFromCollinearOnes) {
  using foldkit::test::carpenter::segment_gap;
  EXPECT_EQ(segment_gap({0, 0}, {1, 1}, {0, 1}, {1, 0}), 0.0);
  // Frame 41 of the mirrored 60-point spiral: bars 25 and 54 on one line, 8.79 apart.
  const Vec a(-0.3816450851700681, -3.6200407698230075), b(-0.43898282611180295, -3.8383295616723165);
  const Vec c(-2.6717493518553903, -12.33862795817556), d(-2.7739094300419267, -12.72755852426171);
  EXPECT_NEAR(segment_gap(a, b, c, d), (c - b).norm(), 1e-9);
  EXPECT_GT(segment_gap({0, 0}, {1, 0}, {0.5, 1e-9}, {0.5, 1}), 0.0);
  EXPECT_EQ(segment_gap({0, 0}, {1, 0}, {0.5, -1e-9}, {0.5, 1}), 0.0);
}

// Larger spirals (label scale): ten turns, 200 points (the speeds would span ~1e34 in one
// field), entered from the centre and from outside.
TEST(AtScale, CarpenterSpiralsOfTwoHundredPointsStraighten) {
  expect_straightened_both_ways(spiral(200, 0.2, 0.05, 0.35, false), "spiral 200");
  expect_straightened_both_ways(reversed_chain(spiral(200, 0.1, 0.1, 0.3, false)), "spiral 200 from outside");
}

// Two spirals joined at their outer ends (label scale, 4–8 s per run): both chain ends are slow
// and the middle fast, so the body held is at both ends. 2 × 90 made Clp's fresh primal simplex
// cycle for over ten minutes before its iterations were capped; 2 × 95 a held probe's rounds.
TEST(AtScale, CarpenterDoubleSpiralsStraighten) {
  for (const int n : {90, 95, 100, 130}) {
    const Frame2 p = double_spiral(n, 0.2, 0.05, 0.35);
    expect_straightened_both_ways(p, "double spiral 2 x " + std::to_string(n));
  }
}

}  // namespace
