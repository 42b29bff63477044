#pragma once
// Inputs of Carpenter's rule at the sizes issue 20 names, shared by benchmarks/bench_carpenter.cpp
// and the AtScale tests, so that a test runs the very chain or polygon a benchmark measured.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "foldkit/folding/carpenter.hpp"

namespace foldkit::benchmarks {

// Distance between segments ab and cd (0 when they cross).
inline double segment_gap(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, const Eigen::Vector2d& d) {
  auto point = [](const Eigen::Vector2d& p, const Eigen::Vector2d& s, const Eigen::Vector2d& e) {
    const Eigen::Vector2d r = e - s;
    const double t = std::clamp((p - s).dot(r) / r.squaredNorm(), 0.0, 1.0);
    return (s + t * r - p).norm();
  };
  auto side = [](const Eigen::Vector2d& s, const Eigen::Vector2d& e, const Eigen::Vector2d& p) {
    const Eigen::Vector2d r = e - s, q = p - s;
    return r.x() * q.y() - r.y() * q.x();
  };
  if (side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0) return 0.0;
  return std::min({point(a, c, d), point(b, c, d), point(c, a, b), point(d, a, b)});
}

// Seeded self-avoiding chain: bars 0.5–1.5, turns up to ±2.6 rad, bars kept 0.05 apart. A walk
// whose tip is walled in (200 failed tries) backs up 2, 4, 8, … bars until it grows past the dead
// end: restarting from scratch instead, as this generator once did, took 30,000 restarts (14 s)
// for 400 links and never reached 1,000.
inline folding::Frame2 random_chain(int links, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> length(0.5, 1.5), turn(-2.6, 2.6);
  folding::Frame2 p = {Eigen::Vector2d(0, 0)};
  std::vector<double> heading = {0.0};
  int failures = 0;
  std::size_t retreat = 1, dead_end = 0;
  while (static_cast<int>(p.size()) <= links) {
    const double h = heading.back() + turn(rng);
    const Eigen::Vector2d q = p.back() + length(rng) * Eigen::Vector2d(std::cos(h), std::sin(h));
    bool ok = true;
    for (std::size_t b = 0; b + 2 < p.size() && ok; ++b) ok = segment_gap(p[b], p[b + 1], p.back(), q) > 0.05;
    if (ok) {
      p.push_back(q);
      heading.push_back(h);
      failures = 0;
      if (p.size() > dead_end) retreat = 1;
    } else if (++failures == 200) {
      failures = 0;
      if (retreat == 1) dead_end = p.size();
      retreat *= 2;
      if (retreat >= p.size()) {  // walled in from the start: begin again
        retreat = p.size() - 1;
        dead_end = 0;
      }
      p.resize(p.size() - retreat);
      heading.resize(p.size());
    }
  }
  return p;
}

// Seeded star-shaped simple polygon: n vertices at equally spaced angles (jittered by a third of
// the spacing) and radii in [0.4, 1.6] × √n, so that it is far from convex.
inline folding::Frame2 random_star(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> radius(0.4, 1.6), jitter(-1.0 / 3, 1.0 / 3);
  const double step = 2.0 * M_PI / n;
  folding::Frame2 p;
  for (int i = 0; i < n; ++i) {
    const double a = (i + jitter(rng)) * step;
    p.push_back(radius(rng) * std::sqrt(static_cast<double>(n)) * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  return p;
}

}  // namespace foldkit::benchmarks
