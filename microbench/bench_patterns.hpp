#pragma once
// The patterns and states the benchmarks share, so their sizes mean the same thing.
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/projection.hpp"

namespace foldkit::bench {

// id > 0: a degree-id vertex with equal sectors; id < 0: a Miura-ori −id × −id.
inline geometry::CreasePattern pattern_for(int id) {
  namespace gen = geometry::generators;
  if (id > 0) return geometry::build_or_throw(gen::single_vertex(std::vector<double>(static_cast<std::size_t>(id), 2 * M_PI / id)));
  return geometry::build_or_throw(gen::miura(-id, -id));
}

// Every crease at a seeded uniform angle in [−0.5, 0.5] rad (not closed: the benchmarks time the
// evaluation, not a solve).
inline geometry::FoldState some_state(const geometry::CreasePattern& p) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  geometry::FoldState s = geometry::FoldState::flat(p);
  for (Eigen::Index i = 0; i < s.angles.size(); ++i) s.angles[i] = u(rng);
  return s;
}

// A Miura-ori folded along its mode by continuation: every crease at least m (0.1, 0.2, …, m_end)
// on its assigned side, projected back to closure at each step. Throws when a step fails.
inline geometry::FoldState closed_miura(const geometry::CreasePattern& p, const geometry::ClosureSystem& sys, double m_end) {
  geometry::FoldState s = geometry::FoldState::flat(p);
  for (double m = 0.1; m <= m_end + 1e-9; m += 0.1) {
    for (std::size_t j = 0; j < p.joints().size(); ++j) {
      const auto i = static_cast<Eigen::Index>(j);
      s.angles[i] = (p.joints()[j].assignment == geometry::Assignment::Mountain ? 1 : -1) * std::max(m, std::abs(s.angles[i]));
    }
    const auto r = geometry::project(sys, s);
    if (!r.status.ok()) throw std::runtime_error("closed_miura: continuation failed: " + r.status.message);
    s = r.state;
  }
  return s;
}

}  // namespace foldkit::bench
