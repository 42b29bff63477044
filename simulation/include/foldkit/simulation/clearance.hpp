#pragma once
/// @file
/// The smallest gap between facets over a motion.
#include <vector>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"

namespace foldkit::simulation {

/// Smallest distance (pattern units) between two facets that share no vertex of the pattern,
/// over the given states, by FCL's distance queries on the facets' triangles (so that code above
/// this folder measures clearance without FCL). Poses come from geometry::facet_poses on a tree
/// rooted at actor 0.
/// @param pattern  the pattern
/// @param states   fold states, each with one angle per joint (radians)
/// @return the smallest distance (0 when facets touch or cross); +∞ when every pair of facets
///         shares a vertex or `states` is empty
double min_clearance(const geometry::CreasePattern& pattern, const std::vector<geometry::FoldState>& states);

}  // namespace foldkit::simulation
