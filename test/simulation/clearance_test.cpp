// simulation::min_clearance against closed forms on a folded strip.
#include <cmath>

#include <gtest/gtest.h>

#include "foldkit/geometry/generators.hpp"
#include "foldkit/simulation/clearance.hpp"

namespace {

using foldkit::geometry::FoldState;
using foldkit::simulation::min_clearance;

// Facets 1 and 3 of a three-panel strip share no vertex: flat, and with both creases at 90° (a
// U), they are the middle panel's width apart; with 60° the gap is 1 + 2·cos 60° at the far edges
// closing to 1 at the creases (parallel walls tilt inwards at 120° − …: the nearest points stay
// the crease lines, 1 apart).
TEST(Clearance, ClearanceOfAFoldedStripIsTheMiddlePanelsWidth) {
  const auto p = foldkit::geometry::build_or_throw(foldkit::geometry::generators::strip(3, 1.0, 1.0));
  FoldState s = FoldState::flat(p);
  EXPECT_NEAR(min_clearance(p, {s}), 1.0, 1e-9);
  s.angles.setConstant(M_PI / 2);
  EXPECT_NEAR(min_clearance(p, {s}), 1.0, 1e-9);
  // Past 90° the free edges lean towards each other: 1 − 2·sin(θ − 90°).
  s.angles.setConstant(M_PI / 2 + 0.2);
  EXPECT_NEAR(min_clearance(p, {s}), 1.0 - 2.0 * std::sin(0.2), 1e-9);
  const auto one = foldkit::geometry::build_or_throw(foldkit::geometry::generators::strip(2));
  EXPECT_TRUE(std::isinf(min_clearance(one, {FoldState::flat(one)})));  // every pair shares a vertex
}

}  // namespace
