#pragma once
// An oracle for planar Carpenter motions that shares nothing with the planner's certificate:
// every frame's bar lengths, the distance between every two vertices AND between every two
// non-adjacent bars (segment to segment) recomputed and compared with the previous frame, and
// the smallest gap between non-adjacent bars (0: two bars meet). Used by the method tests and
// the hard-chain (spiral) tests.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "foldkit/folding/carpenter.hpp"

namespace foldkit::test::carpenter {

using foldkit::folding::Frame2;

// Distance between segments ab and cd, 0 when they cross. A crossing is declared only when the
// four orientation tests are clear of their rounding (a bound of 1e-13 of the product of the
// lengths involved); near-collinear segments are measured by their point-to-segment distances,
// which stay accurate there. (The sign test alone, microbench's segment_gap, called two far-apart
// bars of a straight merged stretch "crossing" when rounding gave the orientations opposite
// signs: a 60-point spiral's bars 25 and 54, 8.8 apart on one line.)
inline double segment_gap(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                          const Eigen::Vector2d& d) {
  auto point = [](const Eigen::Vector2d& p, const Eigen::Vector2d& s, const Eigen::Vector2d& e) {
    const Eigen::Vector2d r = e - s;
    const double t = std::clamp((p - s).dot(r) / r.squaredNorm(), 0.0, 1.0);
    return (s + t * r - p).norm();
  };
  // Orientation of p against the line se, with its sign only where it exceeds rounding.
  auto side = [](const Eigen::Vector2d& s, const Eigen::Vector2d& e, const Eigen::Vector2d& p) {
    const Eigen::Vector2d r = e - s, q = p - s;
    const double value = r.x() * q.y() - r.y() * q.x();
    return std::abs(value) > 1e-13 * r.norm() * q.norm() ? value : 0.0;
  };
  if (side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0) return 0.0;
  return std::min({point(a, c, d), point(b, c, d), point(c, a, b), point(d, a, b)});
}

struct Oracle {
  double length_error = 0.0;  // max |bar − input bar| / input bar
  double vertex_growth = std::numeric_limits<double>::infinity();  // min d_new − d_old, every vertex pair
  double bar_growth = std::numeric_limits<double>::infinity();     // the same, non-adjacent bars
  double min_gap = std::numeric_limits<double>::infinity();        // smallest non-adjacent bar gap
};

// Non-adjacent bars a < b of an n-vertex chain (closed: bar n − 1 joins the last vertex to 0).
template <typename F>
void for_bar_pairs(std::size_t n, bool closed, F&& f) {
  const std::size_t bars = closed ? n : n - 1;
  for (std::size_t a = 0; a < bars; ++a)
    for (std::size_t b = a + 2; b < bars; ++b)
      if (!(closed && a == 0 && b == bars - 1)) f(a, b);
}

inline Oracle check_frames(const std::vector<Frame2>& frames, const Frame2& input, bool closed) {
  Oracle o;
  const std::size_t n = input.size(), bars = closed ? n : n - 1;
  auto bar_gap = [&](const Frame2& p, std::size_t a, std::size_t b) {
    return segment_gap(p[a], p[(a + 1) % n], p[b], p[(b + 1) % n]);
  };
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const Frame2& p = frames[f];
    for (std::size_t b = 0; b < bars; ++b) {
      const double l0 = (input[(b + 1) % n] - input[b]).norm();
      o.length_error = std::max(o.length_error, std::abs((p[(b + 1) % n] - p[b]).norm() - l0) / l0);
    }
    for_bar_pairs(n, closed, [&](std::size_t a, std::size_t b) { o.min_gap = std::min(o.min_gap, bar_gap(p, a, b)); });
    if (f == 0) continue;
    const Frame2& q = frames[f - 1];
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) o.vertex_growth = std::min(o.vertex_growth, (p[j] - p[i]).norm() - (q[j] - q[i]).norm());
    for_bar_pairs(n, closed, [&](std::size_t a, std::size_t b) {
      o.bar_growth = std::min(o.bar_growth, bar_gap(p, a, b) - bar_gap(q, a, b));
    });
  }
  return o;
}

}  // namespace foldkit::test::carpenter
