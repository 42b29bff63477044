// Planar Carpenter's rule against invariants checked here with code the planner does not use: a
// segment-intersection oracle, pairwise distances between consecutive frames, bar lengths, and
// turning angles recomputed from the frames.
#include "foldkit/folding/carpenter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "carpenter_inputs.hpp"
#include "foldkit/io/chain_file.hpp"
#include "foldkit/io/parse_error.hpp"

namespace {

using namespace foldkit::folding;
using Vec = Eigen::Vector2d;
using foldkit::io::frames_csv;
using foldkit::io::frames_json;

// Oracle: do closed segments ab and cd share a point? By the parametric solve, not by orientation
// signs, so it shares nothing with check_simple_chain.
bool segments_intersect(const Vec& a, const Vec& b, const Vec& c, const Vec& d) {
  const Vec r = b - a, s = d - c, ac = c - a;
  const double denom = r.x() * s.y() - r.y() * s.x();
  const double scale = r.norm() * s.norm();
  if (std::abs(denom) > 1e-14 * scale) {
    const double t = (ac.x() * s.y() - ac.y() * s.x()) / denom;
    const double u = (ac.x() * r.y() - ac.y() * r.x()) / denom;
    return t >= 0.0 && t <= 1.0 && u >= 0.0 && u <= 1.0;
  }
  // Parallel: they meet only when collinear and overlapping.
  if (std::abs(ac.x() * r.y() - ac.y() * r.x()) > 1e-14 * r.norm() * (ac.norm() + 1.0)) return false;
  const double rr = r.squaredNorm();
  const double t0 = ac.dot(r) / rr, t1 = (d - a).dot(r) / rr;
  return std::max(std::min(t0, t1), 0.0) <= std::min(std::max(t0, t1), 1.0);
}

double point_segment_distance(const Vec& p, const Vec& a, const Vec& b) {
  const Vec r = b - a;
  const double t = std::clamp((p - a).dot(r) / r.squaredNorm(), 0.0, 1.0);
  return (a + t * r - p).norm();
}

double segment_distance(const Vec& a, const Vec& b, const Vec& c, const Vec& d) {
  if (segments_intersect(a, b, c, d)) return 0.0;
  return std::min({point_segment_distance(a, c, d), point_segment_distance(b, c, d), point_segment_distance(c, a, b),
                   point_segment_distance(d, a, b)});
}

// Smallest gap between two non-neighbouring bars (0 when two meet).
double min_bar_gap(const Frame2& p, bool closed) {
  const std::size_t n = p.size(), bars = closed ? n : n - 1;
  double gap = std::numeric_limits<double>::infinity();
  for (std::size_t a = 0; a < bars; ++a)
    for (std::size_t b = a + 2; b < bars; ++b) {
      if (closed && a == 0 && b == bars - 1) continue;
      gap = std::min(gap, segment_distance(p[a], p[(a + 1) % n], p[b], p[(b + 1) % n]));
    }
  return gap;
}

// Random self-avoiding open chain: bars of length 0.5–1.5, turns up to ±2.6 rad, every bar kept
// 0.05 away from the bars before its neighbour.
Frame2 random_chain(int links, std::mt19937& rng) {
  std::uniform_real_distribution<double> length(0.5, 1.5), turn(-2.6, 2.6);
  for (;;) {
    Frame2 p = {Vec(0, 0)};
    double heading = 0.0;
    int failures = 0;
    while (static_cast<int>(p.size()) <= links && failures < 200) {
      const double h = heading + turn(rng);
      const Vec q = p.back() + length(rng) * Vec(std::cos(h), std::sin(h));
      bool ok = true;
      for (std::size_t b = 0; b + 2 < p.size() && ok; ++b)
        ok = segment_distance(p[b], p[b + 1], p.back(), q) > 0.05;
      if (ok) {
        p.push_back(q);
        heading = h;
        failures = 0;
      } else {
        ++failures;
      }
    }
    if (static_cast<int>(p.size()) == links + 1) return p;
  }
}

// Random star-shaped (hence simple) polygon, usually far from convex.
Frame2 random_polygon(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> radius(0.3, 1.5), jitter(0.1, 0.9);
  Frame2 p;
  for (int i = 0; i < n; ++i) {
    const double angle = 2.0 * M_PI * (i + jitter(rng)) / n;
    const double r = radius(rng);
    p.emplace_back(r * std::cos(angle), r * std::sin(angle));
  }
  return p;
}

void expect_valid_motion(const CarpenterPlanarResult& r, const Frame2& input, bool closed) {
  ASSERT_GE(r.frames.size(), 1u);
  const std::size_t n = input.size(), bars = closed ? n : n - 1;
  double length_error = 0.0, growth = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < r.frames.size(); ++f) {
    const Frame2& p = r.frames[f];
    ASSERT_EQ(p.size(), n);
    for (std::size_t b = 0; b < bars; ++b)
      length_error = std::max(length_error, std::abs((p[(b + 1) % n] - p[b]).norm() - (input[(b + 1) % n] - input[b]).norm()));
    ASSERT_GT(min_bar_gap(p, closed), 0.0) << "bars meet in frame " << f;
    if (f == 0) continue;
    const Frame2& q = r.frames[f - 1];
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) growth = std::min(growth, (p[j] - p[i]).norm() - (q[j] - q[i]).norm());
  }
  EXPECT_LE(length_error, 1e-9);
  EXPECT_GE(growth, -1e-12);
  EXPECT_LE(r.max_length_error, 1e-9);
  EXPECT_GE(r.min_distance_growth, -1e-12);
  for (std::size_t i = 0; i < n; ++i) EXPECT_LE((r.frames[0][i] - input[i]).norm(), 1e-9);
}

TEST(CarpenterPlanar, RandomOpenChainsStraighten) {
  std::mt19937 rng(20260522);
  for (int links : {10, 15, 25, 40}) {
    for (int trial = 0; trial < 3; ++trial) {
      const Frame2 input = random_chain(links, rng);
      SCOPED_TRACE("links " + std::to_string(links) + " trial " + std::to_string(trial));
      const CarpenterPlanarResult r = carpenter_planar({input, false});
      ASSERT_TRUE(r.status.ok()) << r.status.message;
      expect_valid_motion(r, input, false);
      for (double t : turning_angles(r.frames.back(), false)) EXPECT_NEAR(t, 0.0, 1e-9);
      EXPECT_TRUE(is_straight(r.frames.back()));
      EXPECT_GT(r.steps, 0u);
    }
  }
}

// One long chain, the size the issue names as the top of the range.
TEST(CarpenterPlanar, TwoHundredLinkChainStraightens) {
  std::mt19937 rng(7);
  const Frame2 input = random_chain(200, rng);
  CarpenterPlanarOptions options;
  options.frame_stride = 8;  // keeps the frame-by-frame oracle affordable
  const CarpenterPlanarResult r = carpenter_planar({input, false}, options);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  expect_valid_motion(r, input, false);
  EXPECT_TRUE(is_straight(r.frames.back()));
  // The end-to-end distance of a straight chain is its length.
  double length = 0.0;
  for (std::size_t i = 0; i + 1 < input.size(); ++i) length += (input[i + 1] - input[i]).norm();
  EXPECT_NEAR((r.frames.back().back() - r.frames.back().front()).norm(), length, 1e-9);
}

// Issue 20's input (microbench/carpenter_inputs.hpp): a pivot-algorithm walk on the square lattice,
// jittered by 0.1. It is a simple chain (check_simple_chain, an independent O(n²) test) of bars
// within 0.1·2√2 of unit length, the same for the same seed, and it straightens expansively.
TEST(CarpenterPlanar, JitteredLatticeWalkIsSimpleAndStraightens) {
  const Frame2 walk = foldkit::microbench::random_lattice_walk(2000, 3);
  ASSERT_EQ(walk.size(), 2001u);
  EXPECT_NO_THROW(check_simple_chain({walk, false}));
  for (std::size_t i = 0; i + 1 < walk.size(); ++i) EXPECT_NEAR((walk[i + 1] - walk[i]).norm(), 1.0, 0.2 * std::sqrt(2.0) + 1e-12);
  EXPECT_EQ(walk, foldkit::microbench::random_lattice_walk(2000, 3));
  // Far from straight: a self-avoiding walk's end-to-end distance grows like n^(3/4), not n.
  EXPECT_LT((walk.back() - walk.front()).norm(), 0.5 * 2000);
  const Frame2 small = foldkit::microbench::random_lattice_walk(150, 3);
  CarpenterPlanarOptions options;
  options.frame_stride = 4;
  const CarpenterPlanarResult r = carpenter_planar({small, false}, options);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  expect_valid_motion(r, small, false);
  EXPECT_TRUE(is_straight(r.frames.back()));
}

// Bar directions spanning at most π: the closed-form straightening (every bar direction moved
// linearly to a common one, docs/CARPENTER.md) takes over without an LP, in
// ceil(max |turn| / max_turn) steps, and the frame oracle still sees no distance shrink. A hook
// whose directions span more than π needs the LP first.
TEST(CarpenterPlanar, MonotoneChainsStraightenInClosedFormWithoutLps) {
  Frame2 zigzag;
  for (int i = 0; i <= 30; ++i) zigzag.emplace_back(i, (i % 2) * 0.8);  // turns ±2·atan(0.8) = ±1.35 rad
  const CarpenterPlanarResult z = carpenter_planar({zigzag, false});
  ASSERT_TRUE(z.status.ok()) << z.status.message;
  expect_valid_motion(z, zigzag, false);
  EXPECT_TRUE(is_straight(z.frames.back()));
  EXPECT_EQ(z.lp_solves, 0u);
  EXPECT_EQ(z.steps, 7u);  // ceil(1.35 / 0.2)

  std::mt19937 rng(17);
  std::uniform_real_distribution<double> direction(-1.5, 1.5), length(0.5, 1.5);
  Frame2 monotone = {Vec(0, 0)};
  for (int i = 0; i < 60; ++i) {
    const double h = direction(rng);
    monotone.push_back(monotone.back() + length(rng) * Vec(std::cos(h), std::sin(h)));
  }
  const CarpenterPlanarResult m = carpenter_planar({monotone, false});
  ASSERT_TRUE(m.status.ok()) << m.status.message;
  expect_valid_motion(m, monotone, false);
  EXPECT_EQ(m.lp_solves, 0u);

  const Frame2 hook = {{0, 0}, {4, 0}, {4, 2}, {1, 2}, {1, 1.5}};  // directions 0, π/2, π, 3π/2
  const CarpenterPlanarResult k = carpenter_planar({hook, false});
  ASSERT_TRUE(k.status.ok()) << k.status.message;
  expect_valid_motion(k, hook, false);
  EXPECT_GT(k.lp_solves, 0u);
}

TEST(CarpenterPlanar, RandomSimplePolygonsConvexify) {
  std::mt19937 rng(11);
  int nonconvex = 0;
  for (int n : {5, 8, 12, 20, 30}) {
    for (int trial = 0; trial < 2; ++trial) {
      const Frame2 input = random_polygon(n, rng);
      SCOPED_TRACE("n " + std::to_string(n) + " trial " + std::to_string(trial));
      ASSERT_NO_THROW(check_simple_chain({input, true}));
      nonconvex += is_convex(input) ? 0 : 1;
      const CarpenterPlanarResult r = carpenter_planar({input, true});
      ASSERT_TRUE(r.status.ok()) << r.status.message;
      expect_valid_motion(r, input, true);
      // Convex by the turning angles recomputed here: all of one sign, summing to ±2π.
      double total = 0.0;
      int left = 0, right = 0;
      for (double t : turning_angles(r.frames.back(), true)) {
        total += t;
        left += t > 1e-9;
        right += t < -1e-9;
      }
      EXPECT_TRUE(left == 0 || right == 0);
      EXPECT_NEAR(std::abs(total), 2.0 * M_PI, 1e-9);
    }
  }
  EXPECT_GE(nonconvex, 8);  // the generator does give work to do
}

// Polygons of 100–150 vertices, where the rounding of the layouts (vertex k is the sum of k bars)
// passed the fixed tolerance of the distance check: convexifying stopped as "no step keeps every
// distance growing" before the tolerance followed the summation's error bound (docs/CARPENTER.md).
// Every frame is checked here against that bound, 2·(2n + 2)·u·(|p₀| + total length) at most.
TEST(CarpenterPlanar, StarPolygonsOfAHundredAndMoreVerticesConvexify) {
  std::mt19937 rng(5);
  for (int n : {100, 150}) {
    const Frame2 input = random_polygon(n, rng);
    SCOPED_TRACE("n " + std::to_string(n));
    ASSERT_FALSE(is_convex(input));
    CarpenterPlanarOptions options;
    options.frame_stride = 1;
    const CarpenterPlanarResult r = carpenter_planar({input, true}, options);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    double reach = input[0].cwiseAbs().maxCoeff();
    for (int i = 0; i < n; ++i) reach += (input[(i + 1) % n] - input[i]).norm();
    const double bound = 2.0 * (2 * n + 2) * std::numeric_limits<double>::epsilon() * reach;
    double growth = std::numeric_limits<double>::infinity();
    for (std::size_t f = 1; f < r.frames.size(); ++f)
      for (int i = 0; i < n; ++i)
        for (int j = i + 2; j < n; ++j)
          if (!(i == 0 && j == n - 1)) growth = std::min(growth, (r.frames[f][j] - r.frames[f][i]).norm() - (r.frames[f - 1][j] - r.frames[f - 1][i]).norm());
    EXPECT_GE(growth, -bound);
    EXPECT_LE(r.max_length_error, 1e-9);
    int left = 0, right = 0;
    for (double t : turning_angles(r.frames.back(), true)) left += t > 1e-9, right += t < -1e-9;
    EXPECT_TRUE(left == 0 || right == 0);
  }
}

TEST(CarpenterPlanar, HandMadeCombPolygonConvexifies) {
  // A comb with three teeth: deep reflex vertices, far from star-shaped about its centre.
  const Frame2 input = {{0, 0}, {7, 0}, {7, 3}, {6, 3}, {6, 1}, {5, 1}, {5, 3}, {4, 3}, {4, 1}, {3, 1},
                        {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  const CarpenterPlanarResult r = carpenter_planar({input, true});
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  expect_valid_motion(r, input, true);
  EXPECT_TRUE(is_convex(r.frames.back()));
}

TEST(CarpenterPlanar, StraightAndConvexInputsNeedNoStep) {
  const CarpenterPlanarResult line = carpenter_planar({{{0, 0}, {1, 0}, {3, 0}, {4, 0}}, false});
  EXPECT_TRUE(line.status.ok());
  EXPECT_EQ(line.steps, 0u);
  EXPECT_EQ(line.frames.size(), 1u);
  const CarpenterPlanarResult square = carpenter_planar({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, true});
  EXPECT_TRUE(square.status.ok());
  EXPECT_EQ(square.steps, 0u);
}

TEST(CarpenterPlanar, CollinearRunsOfALatticePathAreMergedNotMoved) {
  // An L-shaped staircase on the unit lattice: many joints exactly straight.
  const Frame2 input = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 3}, {0, 4}, {1, 4}, {2, 4}, {3, 4}};
  const CarpenterPlanarResult r = carpenter_planar({input, false});
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  expect_valid_motion(r, input, false);
  // Merged runs stay straight in every frame.
  for (const Frame2& p : r.frames) {
    EXPECT_NEAR(turning_angles(p, false)[0], 0.0, 1e-12);
    EXPECT_NEAR(turning_angles(p, false)[2], 0.0, 1e-12);
  }
}

TEST(CarpenterPlanar, ConstraintGenerationNeedsFewerStrutsThanAllPairs) {
  // Same chain, LP seeded with near pairs and grown by violated ones vs. every pair from the
  // start: both straighten with valid motions, the first with fewer strut rows.
  std::mt19937 rng(5);
  const Frame2 input = random_chain(20, rng);
  CarpenterPlanarOptions all;
  all.all_struts = true;
  const CarpenterPlanarResult a = carpenter_planar({input, false}, all);
  const CarpenterPlanarResult g = carpenter_planar({input, false});
  ASSERT_TRUE(a.status.ok()) << a.status.message;
  ASSERT_TRUE(g.status.ok()) << g.status.message;
  expect_valid_motion(a, input, false);
  expect_valid_motion(g, input, false);
  EXPECT_LT(g.max_struts, a.max_struts);
  EXPECT_EQ(a.max_struts, 21u * 20u / 2u - 20u);  // 21 vertices: all pairs but the 20 bars
}

TEST(CarpenterPlanar, ReversedFramesFoldFromStraight) {
  std::mt19937 rng(3);
  const Frame2 input = random_chain(12, rng);
  const CarpenterPlanarResult r = carpenter_planar({input, false});
  ASSERT_TRUE(r.status.ok());
  const std::vector<Frame2> fold = reversed(r.frames);
  ASSERT_EQ(fold.size(), r.frames.size());
  EXPECT_TRUE(is_straight(fold.front()));
  for (std::size_t i = 0; i < input.size(); ++i) EXPECT_LE((fold.back()[i] - input[i]).norm(), 1e-9);
  // Folding is contractive: every distance shrinks or stays, frame to frame.
  const MotionCheck c = check_motion(reversed(fold), false);
  EXPECT_GE(c.min_distance_growth, -1e-12);
}

TEST(CarpenterPlanar, InvalidChainsAreRejected) {
  auto message = [](const PlanarChain& c) {
    try {
      check_simple_chain(c);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message({{{0, 0}}, false}).find("at least 2 points"), std::string::npos);
  EXPECT_NE(message({{{0, 0}, {1, 0}}, true}).find("at least 3 points"), std::string::npos);
  EXPECT_NE(message({{{0, 0}, {1, 0}, {1, 0}, {2, 1}}, false}).find("zero-length bar"), std::string::npos);
  EXPECT_NE(message({{{0, 0}, {2, 0}, {1, 0}}, false}).find("fold back"), std::string::npos);
  EXPECT_NE(message({{{0, 0}, {2, 0}, {2, 1}, {1, -1}}, false}).find("not simple"), std::string::npos);
  EXPECT_NE(message({{{0, 0}, {2, 0}, {0, 2}, {2, 2}}, true}).find("not simple"), std::string::npos);  // bow tie
  EXPECT_NE(message({{{0, 0}, {2, 0}, {1, 1}, {1, 0}}, false}).find("not simple"), std::string::npos);  // touches
  EXPECT_NE(message({{{0, 0}, {std::nan(""), 0}}, false}).find("not finite"), std::string::npos);
  EXPECT_THROW(carpenter_planar({{{0, 0}, {2, 0}, {2, 1}, {1, -1}}, false}), std::invalid_argument);
  EXPECT_EQ(message({{{0, 0}, {1, 0}, {1, 1}}, false}), "accepted");
}

TEST(CarpenterPlanar, OutputsCarryEveryFrame) {
  const std::vector<Frame2> frames = {{{0, 0}, {1, 0}, {1, 1}}, {{0, 0}, {1, 0}, {1.5, 0.8660254037844386}}};
  const std::string csv = frames_csv(frames);
  EXPECT_EQ(csv.rfind("frame,vertex,x,y\n0,0,0,0\n0,1,1,0\n0,2,1,1\n1,0,0,0\n", 0), 0u);
  const std::string json = frames_json(frames, false);
  EXPECT_NE(json.find("\"closed\": false"), std::string::npos);
  EXPECT_NE(json.find("[[0, 0], [1, 0], [1, 1]]"), std::string::npos);
  const auto seq = turning_angle_sequence(frames, false);
  ASSERT_EQ(seq.events.size(), 2u);
  ASSERT_EQ(seq.events[0].folds.size(), 1u);
  EXPECT_EQ(seq.events[0].folds[0].joint_id, 1);
  EXPECT_NEAR(seq.events[0].folds[0].angle, M_PI / 2, 1e-12);  // left turn of 90°
  EXPECT_NEAR(seq.events[1].folds[0].angle, M_PI / 3, 1e-9);
  EXPECT_GT(seq.events[1].folds[0].speed, 0.0);
}

}  // namespace
