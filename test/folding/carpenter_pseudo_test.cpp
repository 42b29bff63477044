// Method `pseudo` of the planar Carpenter's rule: Streinu's pseudo-triangulation mechanism
// (docs/CARPENTER.md). The PPT's invariants (2m − 3 edges, every vertex pointed, no two edges
// meeting), the mechanism's velocity expansive on every pair, and whole runs certified frame by
// frame by the oracle that shares nothing with the planner (carpenter_oracle.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../../folding/src/carpenter_planar_chain.hpp"
#include "../../folding/src/carpenter_pseudo.hpp"
#include "carpenter_inputs.hpp"
#include "carpenter_certified.hpp"
#include "carpenter_oracle.hpp"
#include "foldkit/folding/carpenter.hpp"

namespace {

using namespace foldkit::folding;
using foldkit::test::carpenter::check_frames;
using foldkit::test::carpenter::expect_certified;
using foldkit::test::carpenter::Oracle;
namespace pd = foldkit::folding::pseudo_detail;

CarpenterPlanarResult run_pseudo(const Frame2& input, bool closed, std::size_t stride = 1) {
  CarpenterPlanarOptions options;
  options.method = CarpenterPlanarMethod::PseudoTriangulation;
  options.frame_stride = stride;
  return carpenter_planar({input, closed}, options);
}

// The bars of random chains and lattice walks completed to a PPT: 2m − 3 edges, every vertex
// pointed, nothing crossing; and the mechanism with the driver removed moves every non-edge
// pair apart (rate ≥ 0 up to rounding) and the driver at rate 1.
TEST(CarpenterPseudo, PptOfRandomChainsIsPointedAndItsMechanismExpansive) {
  for (unsigned seed = 1; seed <= 4; ++seed)
    for (const bool walk : {false, true}) {
      const Frame2 q = walk ? foldkit::microbench::random_lattice_walk(60, seed) : foldkit::microbench::random_chain(40, seed);
      const pd::PptGraph g = pd::build_ppt(q, false);
      const pd::PptCheck c = pd::check_ppt(q, g);
      EXPECT_TRUE(c.edge_count) << seed << " " << g.edges();
      EXPECT_TRUE(c.pointed) << seed;
      EXPECT_TRUE(c.non_crossing) << seed;
      for (std::size_t i = 0; i + 1 < q.size(); ++i) EXPECT_TRUE(g.has(static_cast<int>(i), static_cast<int>(i) + 1));
      const pd::Edge driver = pd::choose_driver(q, false, g);
      ASSERT_GE(driver.first, 0);
      const Frame2 v = pd::mechanism_velocity(q, g, driver);
      ASSERT_EQ(v.size(), q.size());
      double scale = 0.0;
      for (const auto& w : v) scale = std::max(scale, w.norm());
      for (int i = 0; i < static_cast<int>(q.size()); ++i)
        for (int j = i + 1; j < static_cast<int>(q.size()); ++j) {
          const Eigen::Vector2d d = q[j] - q[i];
          const double rate = d.dot(v[j] - v[i]);
          if (pd::Edge{i, j} == driver)
            EXPECT_NEAR(rate, 1.0, 1e-9);
          else if (g.has(i, j))
            EXPECT_NEAR(rate, 0.0, 1e-9 * (1.0 + scale * d.norm()));
          else
            EXPECT_GE(rate, -1e-9 * (1.0 + scale * d.norm())) << seed << ": " << i << "," << j;
        }
    }
}

// A closed chain's PPT keeps the closing bar.
TEST(CarpenterPseudo, PptOfAPolygonHasItsBars) {
  const Frame2 q = foldkit::microbench::random_star(30, 2);
  const pd::PptGraph g = pd::build_ppt(q, true);
  const pd::PptCheck c = pd::check_ppt(q, g);
  EXPECT_TRUE(c.edge_count && c.pointed && c.non_crossing);
  EXPECT_TRUE(g.has(0, 29));
}

// Random chains and star-shaped polygons straighten / convexify, every frame certified.
TEST(CarpenterPseudo, RandomChainsStraightenAndPolygonsConvexifyCertified) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const Frame2 chain = foldkit::microbench::random_chain(25, seed);
    const CarpenterPlanarResult r = run_pseudo(chain, false);
    expect_certified(r, chain, false);
    EXPECT_GT(r.flips + r.straightenings, 0u);
    EXPECT_EQ(r.steps + 1 >= r.frames.size(), true);
  }
  const Frame2 star = foldkit::microbench::random_star(30, 1);
  const CarpenterPlanarResult p = run_pseudo(star, true);
  expect_certified(p, star, true);
  EXPECT_GT(p.flips, 0u);
}

// Issue 36's input at 300 links: straight, every recorded frame certified (one in 5).
TEST(CarpenterPseudo, LatticeWalkOfThreeHundredLinksStraightensCertified) {
  const Frame2 walk = foldkit::microbench::random_lattice_walk(300, 2);
  const CarpenterPlanarResult r = run_pseudo(walk, false, 5);
  expect_certified(r, walk, false);
  EXPECT_GT(r.flips, 0u);
  EXPECT_GT(r.straightenings, 0u);
}

// Same input, same frames. (Seed 3 of the same size creeps: docs/CARPENTER.md, "Method `pseudo`".)
TEST(CarpenterPseudo, Deterministic) {
  const Frame2 walk = foldkit::microbench::random_lattice_walk(80, 1);
  const CarpenterPlanarResult a = run_pseudo(walk, false), b = run_pseudo(walk, false);
  ASSERT_TRUE(a.status.ok()) << a.status.message;
  ASSERT_EQ(a.frames.size(), b.frames.size());
  for (std::size_t f = 0; f < a.frames.size(); ++f) EXPECT_EQ(a.frames[f], b.frames[f]);
  EXPECT_EQ(a.flips, b.flips);
}

// The method's name, and the same bad-input errors as the other methods.
// Frames whose bars drifted past the contract (1e-9 of the shortest input bar) are a failure,
// whatever the method: the guard every run's status passes.
TEST(CarpenterPseudo, BarsThatDriftFailTheRun) {
  using Vec = Eigen::Vector2d;
  const Frame2 square = {Vec(0, 0), Vec(2, 0), Vec(2, 1), Vec(0, 1)};  // shortest bar 1 (closed)
  EXPECT_TRUE(foldkit::folding::planar_detail::length_drift(square, true, 0.9e-9).empty());
  EXPECT_NE(foldkit::folding::planar_detail::length_drift(square, true, 1.1e-9).find("drifted"), std::string::npos);
  EXPECT_FALSE(foldkit::folding::planar_detail::length_drift(square, false, 1.1e-9).empty());
  const Frame2 open = {Vec(0, 0), Vec(2, 0), Vec(2, 1.5)};  // shortest bar 1.5 (open: no closing bar)
  EXPECT_TRUE(foldkit::folding::planar_detail::length_drift(open, false, 1.4e-9).empty());
}

TEST(CarpenterPseudo, NameAndBadInput) {
  EXPECT_EQ(parse_carpenter_method("pseudo"), CarpenterPlanarMethod::PseudoTriangulation);
  EXPECT_STREQ(to_string(CarpenterPlanarMethod::PseudoTriangulation), "pseudo");
  CarpenterPlanarOptions options;
  options.method = CarpenterPlanarMethod::PseudoTriangulation;
  EXPECT_THROW(carpenter_planar({{Eigen::Vector2d(0, 0), Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0)}, false}, options),
               std::invalid_argument);
  EXPECT_THROW(carpenter_planar({{Eigen::Vector2d(0, 0)}, false}, options), std::invalid_argument);
}

}  // namespace
