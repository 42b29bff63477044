#pragma once
// Carpenter's rule on the sphere (Streinu & Whiteley, "Single-vertex origami and spherical
// expansive motions", JCDCG 2004): a single-vertex crease pattern in any closed, non-crossing
// folded state is brought to flat by expansive motions of its spherical polygon, and the frames
// replayed backwards fold it (the paper's Fig. 4). docs/CARPENTER.md.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/geometry/status.hpp"

namespace foldkit::folding {

struct CarpenterSphericalOptions {
  // Largest move of any crease direction in one step (radians of arc, before restoring).
  double step = 0.02;
  // Largest change of any fold angle between two frames: steps are merged up to it (radians).
  double frame_step = 0.02;
  // Flat is reached when every fold angle is below this (radians); the last frame is then set
  // exactly flat, where every pairwise distance is at its largest.
  double flat_tolerance = 1e-5;
  // A crease whose fold angle falls below this stays straight from then on (it is merged into
  // one bar with its neighbours, as the planar rule merges straight joints).
  double straight_tolerance = 1e-10;
  // The input must close to this (geometry::ClosureSystem::max_error, radians).
  double closure_tolerance = 1e-6;
  // Limits: the method stops with a message instead of looping.
  int max_steps = 20000;
  // An LP optimum (smallest rate of distance growth, radians per unit of motion) below this
  // counts as no strictly expansive motion.
  double min_rate = 1e-12;
  // Speed of the fastest crease in the folding CMML (radians per second).
  double velocity = 0.5;
};

struct CarpenterSphericalResult {
  // Success: the last frame is the flat state (the message says after how many steps).
  // Otherwise LimitReached (max_steps) or NoProgress (no strictly expansive motion, or a step
  // failed), with the reason in the message.
  geometry::Status status;
  std::vector<geometry::FoldState> frames;  // folded (the input) … flat
  int steps = 0;                            // LP steps taken
  double max_sector_error = 0.0;            // largest |arc between neighbouring creases − sector angle|
  double min_distance_growth = 0.0;         // smallest change of a pairwise spherical distance between frames
  double min_rate = 0.0;                    // smallest LP optimum t over the steps (docs/CARPENTER.md)
  double max_closure_error = 0.0;           // largest closure residual of a frame (radians)
  std::vector<int> joints;                  // the vertex's joints (indices), counter-clockwise
  geometry::FoldSequence folding;           // CMML: the frames reversed, flat → folded
};

// Flattens the single interior vertex of `pattern` from `folded`. Throws std::invalid_argument
// when the pattern is not one interior vertex (every joint on it, sectors below π), `folded`
// has the wrong size or does not close, or its sectors cross; returns a status other than Success with a
// message when the method stops (no strictly expansive motion, step limit).
CarpenterSphericalResult flatten_single_vertex(const geometry::CreasePattern& pattern, const geometry::FoldState& folded,
                                    const CarpenterSphericalOptions& options = {});

// The unit direction of each crease of the single vertex (counter-clockwise, as
// CarpenterSphericalResult::joints) in the pose where the facet of pattern.actors()[0] is fixed.
std::vector<Eigen::Vector3d> crease_directions(const geometry::CreasePattern& pattern, const geometry::FoldState& state);

}  // namespace foldkit::folding
