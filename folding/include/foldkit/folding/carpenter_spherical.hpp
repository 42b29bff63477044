#pragma once
/// @file
/// Carpenter's rule on the sphere (Streinu & Whiteley, "Single-vertex origami and spherical
/// expansive motions", JCDCG 2004): a single-vertex crease pattern in any closed, non-crossing
/// folded state is brought to flat by expansive motions of its spherical polygon, and the frames
/// replayed backwards fold it (the paper's Fig. 4). docs/CARPENTER.md.
#include <functional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/geometry/status.hpp"

namespace foldkit::folding {

/// Options of flatten_single_vertex(). step, frame_step, the flat and straight tolerances and
/// speed must be positive, max_steps at least 1.
struct CarpenterSphericalOptions {
  /// Largest move of any crease direction in one step (radians of arc, before restoring).
  double step = 0.02;
  /// Largest change of any fold angle between two frames: steps are merged up to it (radians).
  double frame_step = 0.02;
  /// Flat is reached when every fold angle is below this (radians); the last frame is then set
  /// exactly flat, where every pairwise distance is at its largest.
  double flat_tolerance = 1e-5;
  /// A crease whose fold angle falls below this (radians) stays straight from then on (it is
  /// merged into one bar with its neighbours, as the planar rule merges straight joints).
  double straight_tolerance = 1e-10;
  /// The input must close to this (geometry::ClosureSystem::max_error, radians).
  double closure_tolerance = 1e-6;
  /// Steps at most: the method then stops with StatusCode::LimitReached instead of looping.
  int max_steps = 20000;
  /// An LP optimum (smallest rate of distance growth, radians per unit of motion) at or below
  /// this counts as no strictly expansive motion.
  double min_rate = 1e-12;
  /// Speed of the fastest crease in the folding CMML (radians per second).
  double speed = 0.5;
  /// Asked before every step (may be empty): when it answers true the method stops with
  /// StatusCode::LimitReached and the frames so far. A caller with a time limit (a planner's
  /// termination condition) passes it here, so that the whole search keeps to the limit.
  std::function<bool()> stop;
};

/// What flatten_single_vertex() found.
struct CarpenterSphericalResult {
  /// StatusCode::Success: the last frame is the flat state (the message says after how many
  /// steps). Otherwise StatusCode::LimitReached (max_steps, or `stop` answered true) or StatusCode::NoProgress (no
  /// strictly expansive motion, or a step failed), with the reason in the message.
  geometry::Status status;
  /// Folded (the input) … flat (or the last state reached), steps merged up to frame_step apart
  /// (see CarpenterSphericalOptions::frame_step); one angle per joint of the pattern, radians.
  std::vector<geometry::FoldState> frames;
  int steps = 0;                            ///< LP steps taken
  double max_sector_error = 0.0;            ///< largest |arc between neighbouring creases − sector angle|, radians
  /// Smallest change of a pairwise spherical distance over a step (radians; ≥ 0 up to rounding
  /// for an expansive motion); 0 when no step was taken.
  double min_distance_growth = 0.0;
  double min_rate = 0.0;                    ///< smallest LP optimum t over the steps (docs/CARPENTER.md); 0 when none
  double max_closure_error = 0.0;           ///< largest closure residual of the input and the states reached (radians)
  std::vector<int> joints;                  ///< the vertex's joints (indices), counter-clockwise
  /// CMML: the frames reversed, flat → folded (geometry::path_sequence at `speed`).
  geometry::FoldSequence folding;
};

/// Flattens the single interior vertex of `pattern` from `folded`; stopping early (no strictly
/// expansive motion, step limit) is a status other than StatusCode::Success with a message.
/// @param pattern  one interior vertex of degree ≥ 3 carrying every joint, no crease passing
///                 straight through it, every sector below π
/// @param folded   the start: one angle per joint (radians, each within ±π), closed to
///                 options.closure_tolerance, its sectors not crossing
/// @param options  step sizes, tolerances, limits and the CMML speed
/// @throws std::invalid_argument when an option is out of range, the pattern is not as above,
///         or `folded` has the wrong size, does not close, folds a crease past 180 degrees or
///         crosses itself
CarpenterSphericalResult flatten_single_vertex(const geometry::CreasePattern& pattern, const geometry::FoldState& folded,
                                    const CarpenterSphericalOptions& options = {});

/// The unit direction of each crease of the single vertex (counter-clockwise, as
/// CarpenterSphericalResult::joints) in the pose where the facet of pattern.actors()[0] is fixed.
/// @param pattern  a single-vertex pattern, as flatten_single_vertex() needs
/// @param state    one angle per joint, radians
/// @throws std::invalid_argument when the pattern is not such a vertex or `state` has the wrong size
std::vector<Eigen::Vector3d> crease_directions(const geometry::CreasePattern& pattern, const geometry::FoldState& state);

}  // namespace foldkit::folding
