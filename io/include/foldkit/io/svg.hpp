#pragma once
#include <string>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"

namespace foldkit::io {

struct SvgOptions {
  // 0: scale so that the longer side of the drawing is 800 px, whatever the pattern's units.
  double pixels_per_unit = 0.0;
  bool joint_ids = false;
  // With a state, a crease is drawn by the sign of its angle; without, by its assignment.
  const geometry::FoldState* state = nullptr;
};

// Mountain: red solid; valley: blue dashed; unassigned/flat: grey; boundary: black
// (Origami Simulator's colours, so its SVG importer reads ours).
std::string write_svg(const geometry::CreasePattern& pattern, const SvgOptions& options = {});

}  // namespace foldkit::io
