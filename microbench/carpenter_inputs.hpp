#pragma once
// Inputs of Carpenter's rule at the sizes issue 20 names, shared by microbench/bench_carpenter.cpp
// and the AtScale tests, so that a test runs the very chain or polygon a benchmark measured.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "foldkit/folding/carpenter.hpp"

namespace foldkit::microbench {

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

// Seeded self-avoiding walk of `links` unit steps on the square lattice by the pivot algorithm
// (Madras & Sokal): from a straight walk, 10·links accepted pivots, each turning the walk's tail
// about a random vertex by a random non-trivial symmetry of the lattice, kept when the tail meets
// no vertex of the head. Then every vertex is moved by up to `jitter` in x and y (uniformly), so
// that no joint is straight; non-adjacent lattice bars lie at least 1 apart, so a jitter below
// 0.35 keeps the chain simple. This is the input issue 20 describes ("pivot algorithm, jittered by
// 0.1"); unlike random_chain, it takes seconds at 10,000 links (random_chain's dead-end search
// ran for an hour at 3,000 without finishing a chain).
inline folding::Frame2 random_lattice_walk(int links, unsigned seed, double jitter = 0.1) {
  using Point = std::array<long, 2>;
  std::mt19937 rng(seed);
  std::vector<Point> walk(static_cast<std::size_t>(links) + 1);
  for (int i = 0; i <= links; ++i) walk[static_cast<std::size_t>(i)] = {i, 0};
  // Unsigned, so that negative coordinates shift and wrap without undefined behaviour.
  const auto pack = [](const Point& p) {
    return (static_cast<std::uint64_t>(p[0]) << 32) ^ static_cast<std::uint32_t>(p[1]);
  };
  // The seven symmetries of the lattice other than the identity, as (x, y) → (a x + b y, c x + d y).
  static const int symmetry[7][4] = {{0, -1, 1, 0}, {-1, 0, 0, -1}, {0, 1, -1, 0}, {1, 0, 0, -1},
                                     {-1, 0, 0, 1}, {0, 1, 1, 0},   {0, -1, -1, 0}};
  std::uniform_int_distribution<int> pivot_at(1, std::max(1, links - 1)), which(0, 6);
  // Vertex by lattice point: a moved tail point may land where the old tail was, not on the head.
  std::unordered_map<std::uint64_t, std::size_t> index_of;
  for (std::size_t i = 0; i < walk.size(); ++i) index_of[pack(walk[i])] = i;
  std::vector<Point> tail;
  for (int accepted = 0; accepted < 10 * links && links > 1;) {
    const auto k = static_cast<std::size_t>(pivot_at(rng));
    const int* g = symmetry[which(rng)];
    const Point o = walk[k];
    tail.clear();
    bool free = true;
    for (std::size_t i = k + 1; i < walk.size() && free; ++i) {
      const long dx = walk[i][0] - o[0], dy = walk[i][1] - o[1];
      const Point q = {o[0] + g[0] * dx + g[1] * dy, o[1] + g[2] * dx + g[3] * dy};
      const auto it = index_of.find(pack(q));
      free = it == index_of.end() || it->second > k;
      tail.push_back(q);
    }
    if (!free) continue;
    for (std::size_t i = k + 1; i < walk.size(); ++i) index_of.erase(pack(walk[i]));
    for (std::size_t i = k + 1; i < walk.size(); ++i) index_of[pack(walk[i] = tail[i - k - 1])] = i;
    ++accepted;
  }
  std::uniform_real_distribution<double> shift(-jitter, jitter);
  folding::Frame2 p;
  for (const Point& q : walk) {
    const double x = static_cast<double>(q[0]) + shift(rng);
    p.emplace_back(x, static_cast<double>(q[1]) + shift(rng));
  }
  return p;
}

}  // namespace foldkit::microbench
