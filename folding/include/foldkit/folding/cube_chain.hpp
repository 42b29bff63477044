#pragma once
/// @file
/// The fold of the paper's Fig. 8a sheet (geometry::generators::cube_sheet) into a straight chain
/// of closed cubes (Fig. 5a), as CMML the simulator replays without a collision. docs/CARPENTER.md.
#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_sequence.hpp"

namespace foldkit::folding {

/// The fold of a cube sheet into a chain of cubes. Net by net, three events each: the row rolls
/// up over its first tile (two valley hinges to −90°) while the hinge to the next net turns to
/// +180° at twice their speed, so the rest of the sheet keeps its direction and lands face to
/// face on the new cube's far face; then the two side caps (−90°); then the far cap (−90°). Each
/// cube forms on the side of the sheet away from the cubes before it, so nothing sweeps through
/// them. The cubes end in a straight line, each sharing a face with the next, hinged on one edge
/// of it.
/// @param sheet     cube_sheet(cubes), with its actor and joint IDs (docs/GENERATORS.md)
/// @param cubes     number of cubes (≥ 1)
/// @param speed     speed of the hinges within a net, radians per second (the hinge to the next
///                  net turns at twice this)
/// @return the sequence, 3 events per cube, titled after the sheet
/// @throws std::invalid_argument when `sheet` is not cube_sheet(cubes) (its actor and joint
///         counts, or a missing hinge), or cubes < 1, or speed is not positive and finite
geometry::FoldSequence fold_cube_chain(const geometry::CreasePattern& sheet, int cubes, double speed = 1.0);

}  // namespace foldkit::folding
