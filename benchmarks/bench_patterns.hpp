#pragma once
// The patterns and states bench_closure and bench_fk share, so their sizes mean the same thing.
#include <cmath>
#include <random>
#include <vector>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/geometry/generators.hpp"

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

}  // namespace foldkit::bench
