#pragma once
// Inputs of Carpenter's rule at the sizes issue 20 names, shared by benchmarks/bench_carpenter.cpp
// and the AtScale tests, so that a test runs the very polygon a benchmark measured.
#include <cmath>
#include <random>

#include <Eigen/Core>

#include "foldkit/folding/carpenter.hpp"

namespace foldkit::benchmarks {

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
