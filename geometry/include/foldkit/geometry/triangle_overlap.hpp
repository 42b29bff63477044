#pragma once
/// @file
/// Overlap tests between flat triangles, tolerant of facets that merely touch.
#include <array>
#include <utility>
#include <vector>

#include "foldkit/geometry/types.hpp"

namespace foldkit::geometry {

/// A triangle in the plane: its three corners (either orientation).
using Tri2 = std::array<Vec2, 3>;

/// True when the interiors of two triangles overlap by more than `tolerance`: facets that
/// merely touch along an edge or at a corner do not count. boost::geometry's predicates are
/// exact and would call near-touching facets overlapping, hence this separating-axis test.
/// @param a, b       the triangles
/// @param tolerance  a length (the triangles' units): the two must overlap by more than this
///                   along every edge normal of either triangle
bool triangles_overlap(const Tri2& a, const Tri2& b, double tolerance);

/// All pairs (i, j), i < j, of triangles whose interiors overlap by more than `tolerance` (a
/// length, as in triangles_overlap()), found through an R-tree of bounding boxes. Sorted.
std::vector<std::pair<int, int>> overlapping_pairs(const std::vector<Tri2>& triangles, double tolerance);

}  // namespace foldkit::geometry
