#pragma once
// A random closed, non-crossing folded state of a single vertex, not filtered for reachability:
// active angles uniform in [−amplitude, amplitude], the passive ones in closed form on a random
// branch (statespaces::SingleVertexChain), kept when its largest fold is in [smallest, π − 0.05]
// and the FCL world finds no crossing facets.
#include <random>
#include <stdexcept>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/simulation/collision_world.hpp"
#include "foldkit/statespaces/single_vertex_chain.hpp"

namespace foldkit::test {

inline geometry::FoldState random_vertex_state(const geometry::CreasePattern& p, unsigned seed, double amplitude = 2.5,
                                               double smallest = 0.8) {
  const statespaces::SingleVertexChain chain(p);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> angle(-amplitude, amplitude);
  simulation::CollisionWorld world(p);
  const auto tree = geometry::make_tree(p);
  for (int k = 0; k < 100000; ++k) {
    geometry::FoldState f = geometry::FoldState::flat(p);
    for (int j : chain.active_joints()) f.angles[j] = angle(rng);
    if (!chain.solve(f, rng() % 2 == 0 ? 1 : -1)) continue;
    if (f.angles.cwiseAbs().maxCoeff() < smallest || f.angles.cwiseAbs().maxCoeff() > M_PI - 0.05) continue;
    world.reset();
    if (!world.check(geometry::facet_poses(p, tree, f), f).empty()) continue;
    return f;
  }
  throw std::runtime_error("random_vertex_state: no non-crossing folded state found");
}

}  // namespace foldkit::test
