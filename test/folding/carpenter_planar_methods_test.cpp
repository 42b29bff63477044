// The two methods of the planar Carpenter's rule (CarpenterPlanarMethod: the global LP per step,
// and the carried field mended by window LPs) against an oracle that shares nothing with the
// planner's certificate: every frame's bar lengths, the distance between every two vertices AND
// between every two non-adjacent bars (segment to segment) recomputed and compared with the
// previous frame, and no two non-adjacent bars meeting.
#include "foldkit/folding/carpenter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "carpenter_inputs.hpp"
#include "carpenter_certified.hpp"
#include "carpenter_oracle.hpp"

namespace {

using namespace foldkit::folding;
using Vec = Eigen::Vector2d;
using foldkit::test::carpenter::check_frames;
using foldkit::test::carpenter::expect_certified;
using foldkit::test::carpenter::Oracle;

CarpenterPlanarResult run(const Frame2& input, bool closed, CarpenterPlanarMethod method, std::size_t stride = 1) {
  CarpenterPlanarOptions options;
  options.method = method;
  options.frame_stride = stride;
  return carpenter_planar({input, closed}, options);
}

// The benchmark's own input at a size where the carried field has to be mended many times: both
// methods straighten it, every frame certified by the oracle; the carried field takes most steps
// without the global LP and needs fewer global LPs.
TEST(CarpenterPlanarMethods, LatticeWalkStraightensCertifiedByBothMethods) {
  const Frame2 walk = foldkit::microbench::random_lattice_walk(300, 2);
  const CarpenterPlanarResult lp = run(walk, false, CarpenterPlanarMethod::Lp, 3);
  const CarpenterPlanarResult carried = run(walk, false, CarpenterPlanarMethod::CarriedField, 3);
  {
    SCOPED_TRACE("lp");
    expect_certified(lp, walk, false);
  }
  {
    SCOPED_TRACE("carried");
    expect_certified(carried, walk, false);
  }
  EXPECT_EQ(lp.carried_steps, 0u);
  EXPECT_EQ(lp.window_lp_solves, 0u);
  EXPECT_GT(carried.carried_steps, carried.steps / 2);
  EXPECT_GT(carried.window_lp_solves, 0u);
  EXPECT_LT(carried.lp_solves - carried.window_lp_solves, (lp.lp_solves + 1) / 2);
}

// Random chains of random_chain (bars 0.5–1.5, sharp turns), several seeds, every frame.
TEST(CarpenterPlanarMethods, RandomChainsStraightenCertifiedByTheCarriedField) {
  for (unsigned seed : {1u, 2u, 3u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Frame2 chain = foldkit::microbench::random_chain(60, seed);
    expect_certified(run(chain, false, CarpenterPlanarMethod::CarriedField), chain, false);
  }
}

// The same input and options give the same frames, bit for bit.
TEST(CarpenterPlanarMethods, CarriedFieldIsDeterministic) {
  const Frame2 walk = foldkit::microbench::random_lattice_walk(120, 5);
  const CarpenterPlanarResult a = run(walk, false, CarpenterPlanarMethod::CarriedField);
  const CarpenterPlanarResult b = run(walk, false, CarpenterPlanarMethod::CarriedField);
  ASSERT_TRUE(a.status.ok()) << a.status.message;
  EXPECT_EQ(a.frames, b.frames);
  EXPECT_EQ(a.lp_solves, b.lp_solves);
}

// Options out of range are refused before anything runs: a carry floor above the LP's 1 would
// keep pairs weak for ever, a NaN one would flag none (any field passing), and a NaN window is
// undefined when cast to a joint count.
TEST(CarpenterPlanarMethods, OptionsOutOfRangeAreRefused) {
  PlanarChain chain;
  chain.points = foldkit::microbench::random_lattice_walk(20, 1);
  const std::vector<std::pair<void (*)(CarpenterPlanarOptions&), const char*>> bad = {
      {[](CarpenterPlanarOptions& o) { o.carry_rate = 0.0; }, "carry_rate"},
      {[](CarpenterPlanarOptions& o) { o.carry_rate = 1.5; }, "carry_rate"},
      {[](CarpenterPlanarOptions& o) { o.carry_rate = std::numeric_limits<double>::quiet_NaN(); }, "carry_rate"},
      {[](CarpenterPlanarOptions& o) { o.repair_window = -0.1; }, "repair_window"},
      {[](CarpenterPlanarOptions& o) { o.repair_window = std::numeric_limits<double>::quiet_NaN(); }, "repair_window"},
      {[](CarpenterPlanarOptions& o) { o.max_turn = 0.0; }, "max_turn"},
      {[](CarpenterPlanarOptions& o) { o.near_radius = std::numeric_limits<double>::infinity(); }, "near_radius"}};
  for (const auto& [set, name] : bad) {
    CarpenterPlanarOptions o;
    set(o);
    try {
      carpenter_planar(chain, o);
      ADD_FAILURE() << name << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

// A polygon cannot carry a field (dropping a joint's speed would open it): the CarriedField
// method convexifies it exactly as the global LP does.
TEST(CarpenterPlanarMethods, ClosedChainsTakeTheGlobalLpUnderEitherMethod) {
  const Frame2 star = foldkit::microbench::random_star(40, 3);
  const CarpenterPlanarResult lp = run(star, true, CarpenterPlanarMethod::Lp);
  const CarpenterPlanarResult carried = run(star, true, CarpenterPlanarMethod::CarriedField);
  expect_certified(carried, star, true);
  EXPECT_EQ(carried.carried_steps, 0u);
  EXPECT_EQ(carried.frames, lp.frames);
}

// The oracle itself fails on a motion that brings two bars closer, and on a stretched bar.
TEST(CarpenterPlanarMethods, OracleCatchesShrinkingAndStretching) {
  const Frame2 a = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  Frame2 closer = a;
  closer[3] = Vec(0.2, 0.4);  // bar 2 turned about (1, 1), its length kept: its tip nears bar 0
  const Oracle shrink = check_frames({a, closer}, a, false);
  EXPECT_LE(shrink.length_error, 1e-12);
  EXPECT_LT(shrink.bar_growth, 0.0);
  EXPECT_LT(shrink.vertex_growth, 0.0);
  Frame2 stretched = a;
  stretched[3] = Vec(-0.5, 1);
  EXPECT_GT(check_frames({a, stretched}, a, false).length_error, 0.1);
}

// Issue 36's target size, the 10,000-link walk of bench_carpenter's
// StraightenLatticeWalkCarried/10000: it does not straighten in minutes (docs/CARPENTER.md,
// Limits: the first global LP alone took 139 s of CPU), so this runs its first step and certifies
// it at that size: check_motion recomputes bar lengths and all 5·10⁷ vertex distances from the
// frames, not from the planner's own bookkeeping.
TEST(AtScale, TenThousandLinkWalkTakesACertifiedFirstStep) {
  const Frame2 walk = foldkit::microbench::random_lattice_walk(10000, 1);
  CarpenterPlanarOptions options;
  options.max_steps = 1;
  const CarpenterPlanarResult r = carpenter_planar({walk, false}, options);
  EXPECT_EQ(r.status.code, foldkit::geometry::StatusCode::LimitReached) << r.status.message;
  ASSERT_EQ(r.steps, 1u);
  ASSERT_EQ(r.frames.size(), 2u);
  EXPECT_EQ(r.frames.front(), walk);
  EXPECT_NE(r.frames.back(), walk);
  const MotionCheck check = check_motion(r.frames, false);
  EXPECT_LE(check.max_length_error, 1e-9);
  EXPECT_GE(check.min_distance_growth, -1e-9);
}

}  // namespace
