#pragma once
#include <vector>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"

namespace foldkit::simulation {

// Smallest distance (pattern units) between two facets that share no vertex of the pattern, over
// the given states, by FCL's distance queries on the facets' triangles (so that code above this
// folder measures clearance without FCL). +∞ when every pair shares a vertex.
double min_clearance(const geometry::CreasePattern& pattern, const std::vector<geometry::FoldState>& states);

}  // namespace foldkit::simulation
