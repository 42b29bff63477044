#pragma once
#include <array>
#include <utility>
#include <vector>

#include "foldkit/geometry/types.hpp"

namespace foldkit::geometry {

using Tri2 = std::array<Vec2, 3>;

// True when the interiors of two triangles overlap by more than `tolerance` (a length): facets
// that merely touch along an edge or at a corner do not count. boost::geometry's predicates are
// exact and would call near-touching facets overlapping, hence this separating-axis test.
bool triangles_overlap(const Tri2& a, const Tri2& b, double tolerance);

// All pairs (i < j) of triangles whose interiors overlap, found through an R-tree of bounding boxes.
std::vector<std::pair<int, int>> overlapping_pairs(const std::vector<Tri2>& triangles, double tolerance);

}  // namespace foldkit::geometry
