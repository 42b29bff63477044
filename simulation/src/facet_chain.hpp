#pragma once
// The chain of creases CollisionWorld judges a pair of facets along. Private to foldkit::simulation.
#include <cstddef>
#include <vector>

#include "foldkit/geometry/crease_pattern.hpp"

namespace foldkit::simulation::detail {

/// chain_steps()'s answer when b is not within reach.
inline constexpr int kNoChain = -1;

/// The shortest chain of creases from actor a to actor b, as steps (joint << 1 | k): across joint
/// `joint` into its actors[k]. Breadth-first over the facet graph's creases, in crease order, so
/// the chain is the same whatever the actors' numbering when it is the only shortest one (round
/// a vertex, it is one of two of equal length, which differ by that vertex's closure error alone).
/// Every chain from one actor is a path in one breadth-first tree. {kNoChain} when b is not
/// reached within `max_visited` facets.
///
/// Written out rather than boost::breadth_first_search because it stops at b or after
/// `max_visited` facets, which a BGL visitor can do only by throwing.
std::vector<int> chain_steps(const geometry::CreasePattern& pattern, int a, int b, std::size_t max_visited);

}  // namespace foldkit::simulation::detail
