#pragma once
/// @file
/// SVG drawings of flat crease patterns.
#include <string>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"

namespace foldkit::io {

/// How write_svg() draws a pattern.
struct SvgOptions {
  /// Scale, pixels per pattern unit; 0 scales so that the longer side of the drawing is 800 px,
  /// whatever the pattern's units.
  double pixels_per_unit = 0.0;
  bool joint_ids = false;  ///< label each crease with its joint ID
  /// With a state (one angle per joint, not owned), a crease is drawn by the sign of its angle;
  /// without, by its assignment.
  const geometry::FoldState* state = nullptr;
};

/// The flat sheet as SVG, y pointing up as in the pattern, with a 20 px margin, in Origami
/// Simulator's convention, so that it and read_svg_pattern() read it back: boundary black;
/// mountain red solid; valley blue dashed; unassigned/flat magenta (an undriven hinge); with a
/// state, each folded crease's stroke-opacity is |angle| / 180°, its target. Facets are filled
/// polygons without a stroke (not lines).
std::string write_svg(const geometry::CreasePattern& pattern, const SvgOptions& options = {});

}  // namespace foldkit::io
