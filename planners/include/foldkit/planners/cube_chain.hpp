#pragma once
// The fold of the paper's Fig. 8a sheet (geometry::generators::cube_sheet) into a chain of closed
// cubes (Fig. 5a), as CMML the simulator replays without a collision. docs/CARPENTER.md.
#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_sequence.hpp"

namespace foldkit::planners {

// Largest chain the Fig. 8a sheet folds into: every net closes its ring of four tiles on the
// line where the next net is hinged, so all the cubes of the chain turn about one common edge
// and four fill the space round it.
constexpr int kMaxCubeChain = 4;

// Net by net: the two caps up, then the ring rolled from its far end (the hinge between tiles 3
// and 4 first), the hinge to the next net turning against the last roll so that the rest of the
// sheet stays level, then folded back flat (±180°) onto the closed cube, where the next net rolls
// into the free space beside it. Every hinge of a net ends at −90° (valley), every hinge between
// nets at ±180°. Throws std::invalid_argument when `sheet` is not cube_sheet(cubes) (its actor
// and joint IDs, docs/GENERATORS.md), or cubes is outside [1, kMaxCubeChain], or velocity ≤ 0.
geometry::FoldSequence fold_cube_chain(const geometry::CreasePattern& sheet, int cubes, double velocity = 1.0);

}  // namespace foldkit::planners
