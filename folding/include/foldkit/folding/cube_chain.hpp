#pragma once
// The fold of the paper's Fig. 8a sheet (geometry::generators::cube_sheet) into a straight chain
// of closed cubes (Fig. 5a), as CMML the simulator replays without a collision. docs/CARPENTER.md.
#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_sequence.hpp"

namespace foldkit::folding {

// Net by net, three events each: the row rolls up over its first tile (two valley hinges to
// −90°) while the hinge to the next net turns to +180° at twice their speed, so the rest of the
// sheet keeps its direction and lands face to face on the new cube's far face; then the two side
// caps (−90°); then the far cap (−90°). Each cube forms on the side of the sheet away from the
// cubes before it, so nothing sweeps through them. The cubes end in a straight line, each sharing
// a face with the next, hinged on one edge of it. Throws std::invalid_argument when `sheet` is not
// cube_sheet(cubes) (its actor and joint IDs, docs/GENERATORS.md), or cubes < 1, or velocity ≤ 0.
geometry::FoldSequence fold_cube_chain(const geometry::CreasePattern& sheet, int cubes, double velocity = 1.0);

}  // namespace foldkit::folding
