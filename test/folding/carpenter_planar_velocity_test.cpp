// The struts a step's first LP starts with (detail::near_pairs, carpenter_planar_velocity.cpp),
// against every pair measured directly: the grid it buckets the vertices in must miss none and
// add none, and on a star-shaped polygon the radius follows the vertices' spacing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "../../folding/src/carpenter_planar_struts.hpp"
#include "../../folding/src/carpenter_planar_velocity.hpp"
#include "carpenter_inputs.hpp"
#include "foldkit/folding/carpenter.hpp"

namespace {

using namespace foldkit::folding;
using Pairs = std::vector<std::pair<int, int>>;

bool is_bar(int a, int b, int m, bool closed) { return b - a == 1 || (closed && a == 0 && b == m - 1); }

// Every non-bar pair (a < b) closer than `radius`, all pairs compared.
Pairs pairs_within(const Frame2& p, bool closed, double radius) {
  const int m = static_cast<int>(p.size());
  Pairs out;
  for (int a = 0; a < m; ++a)
    for (int b = a + 1; b < m; ++b)
      if (!is_bar(a, b, m, closed) && (p[b] - p[a]).norm() < radius) out.emplace_back(a, b);
  return out;
}

// The median over the vertices of the distance to the nearest non-bar vertex (the upper one for
// an even count, as near_pairs takes it).
double median_nearest(const Frame2& p, bool closed) {
  const int m = static_cast<int>(p.size());
  std::vector<double> nearest(p.size(), std::numeric_limits<double>::infinity());
  for (int a = 0; a < m; ++a)
    for (int b = a + 1; b < m; ++b)
      if (!is_bar(a, b, m, closed)) {
        const double d = (p[b] - p[a]).norm();
        nearest[a] = std::min(nearest[a], d);
        nearest[b] = std::min(nearest[b], d);
      }
  std::sort(nearest.begin(), nearest.end());
  return nearest[p.size() / 2];
}

double mean_bar(const Frame2& p, bool closed) {
  const std::size_t bars = closed ? p.size() : p.size() - 1;
  double sum = 0.0;
  for (std::size_t a = 0; a < bars; ++a) sum += (p[(a + 1) % p.size()] - p[a]).norm();
  return sum / static_cast<double>(bars);
}

Pairs near(const Frame2& p, bool closed, double radius) {
  const detail::struts::StrutModel model(p, closed);
  return detail::near_pairs(model, p, radius);
}

// On a jittered lattice walk the vertices lie about a bar apart, so the radius is kept: the pairs
// are exactly those closer than it (one and two mean bars, the radii the planner uses).
TEST(CarpenterNearPairs, OnALatticeWalkAreEveryPairWithinTheRadius) {
  for (const int links : {300, 1000}) {
    const Frame2 p = foldkit::microbench::random_lattice_walk(links, 2);
    const double bar = mean_bar(p, false);
    ASSERT_GT(median_nearest(p, false), 1.2 * bar);  // 2 medians > 2.4 mean bars: the radius is kept
    for (const double radius : {bar, 2.0 * bar}) {
      const Pairs expected = pairs_within(p, false, radius);
      EXPECT_FALSE(expected.empty());
      EXPECT_EQ(near(p, false, radius), expected) << links << " links, radius " << radius;
    }
  }
}

// On a star-shaped polygon the spokes are long and the vertices crowd the centre: one mean bar
// would take in tens of thousands of pairs, so the radius shrinks to twice the median nearest distance.
TEST(CarpenterNearPairs, OnAStarPolygonFollowTheVerticesSpacing) {
  for (const int n : {200, 1000}) {
    const Frame2 p = foldkit::microbench::random_star(n, 1);
    const double bar = mean_bar(p, true);
    const double spacing = 2.0 * median_nearest(p, true);
    ASSERT_LT(spacing, bar);
    const Pairs expected = pairs_within(p, true, spacing);
    EXPECT_FALSE(expected.empty());
    const Pairs got = near(p, true, bar);
    EXPECT_EQ(got, expected) << n << "-gon";
    const std::size_t by_bar = pairs_within(p, true, bar).size();
    const std::size_t fewer = n == 1000 ? 10 : 2;  // 1,731 pairs against 31,892; 435 against 1,186
    EXPECT_LT(fewer * got.size(), by_bar) << n << "-gon";
    RecordProperty("pairs_" + std::to_string(n), static_cast<int>(got.size()));
    RecordProperty("pairs_within_a_mean_bar_" + std::to_string(n), static_cast<int>(by_bar));
  }
}

// Chains too short for any non-bar pair, and pairs all farther than the radius: nothing.
TEST(CarpenterNearPairs, NoPairInRangeGivesNone) {
  const Frame2 triangle = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
  EXPECT_TRUE(near(triangle, true, 5.0).empty());
  const Frame2 square = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}};
  EXPECT_TRUE(near(square, true, 1.0).empty());  // the diagonals are √2 long
  EXPECT_EQ(near(square, true, 1.5), (Pairs{{0, 2}, {1, 3}}));
}

}  // namespace
