#pragma once
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/geometry/progress.hpp"
#include "foldkit/geometry/status.hpp"
#include "foldkit/simulation/simulate.hpp"

namespace foldkit::folding {

struct ProjectedFoldingOptions {
  // Desired velocity, one entry per joint (only its direction matters). Empty: the assignment's
  // signs, mountain +1, valley −1, unassigned and flat 0.
  Eigen::VectorXd velocity;
  // Stop when the largest |fold angle| reaches target_fraction·π, in (0, 1].
  double target_fraction = 0.9;
  double max_step = 0.01;            // largest change of any crease per step, radians
  // Amplitude (radians, largest crease) of the first state, the closed state nearest to the
  // desired direction at this amplitude: the way out of the singular flat sheet.
  double lead_in = 0.1;
  double closure_tolerance = 1e-10;  // largest loop error (radians) accepted at every state
  bool collisions = true;            // simulation::CollisionWorld between and at the states
  int max_steps = 20000;
  // Rank of the Jacobian: singular values above √rank_tolerance · σ_max count. The LDLᵀ pivots
  // of JᵀJ + εI (above rank_tolerance × the largest) screen every step; when their count changes
  // or they collapse, geometry::LeastNormSolver::decide_rank decides from singular values.
  double rank_tolerance = 1e-8;
  // A state is singular when its smallest kept singular value falls below this × σ_max (screened
  // by √(smallest kept pivot / largest), confirmed by singular values).
  double singular_ratio = 1e-7;
  bool replay = true;                // replay the CMML in the simulator (collisions as above)
  double cmml_velocity = 1.0;        // fastest joint's speed in the CMML, rad/s
  geometry::ProgressFn progress;     // per step (steps, closure error), then the replay's
};

struct ProjectedFoldingResult {
  // Why projected-velocity folding stopped (docs/PROJECTED_FOLDING.md): Success (the largest fold
  // angle reached target_fraction·π), Collision (the next step makes facets cross; the path ends
  // before it), Singular (the closure Jacobian lost rank, its pivots collapsed, or a crease
  // returned to flat), NotRigidlyFoldable (no closed state near flat follows the desired
  // velocity: the square twist), NoProgress (the desired velocity has no component along the
  // motions closure allows), LimitReached (max_steps). A replay the simulator rejects keeps the
  // code and adds its reason to the message (see `replay`).
  geometry::Status status;
  std::vector<geometry::FoldState> states;  // the flat sheet first, then one state per step
  double fraction = 0.0;             // largest |fold angle| / π at the last state
  double max_closure_error = 0.0;    // largest loop error over the states
  int steps = 0;                     // states after the flat one
  int newton_iterations = 0;         // corrector iterations, all steps together
  int rank = 0;                      // rank of the closure Jacobian at the last state
  int dof = 0;                       // creases − rank there
  double min_pivot_ratio = 1.0;      // smallest σ_min/σ_max estimate (see singular_ratio) along the path
  int rank_decisions = 0;            // rank-revealing decisions made (the pivots' screen asked for them)
  double rank_gap = 0.0;             // RankDecision::gap() of the last decision (rank, dof above)
  double min_rank_gap = std::numeric_limits<double>::infinity();  // smallest gap over the decisions
  std::string rank_method;           // "dense-svd" or "inverse-subspace"
  double time = 0.0;                 // seconds, folding only (no replay)
  geometry::FoldSequence sequence;   // CMML: flat → states (geometry::path_sequence)
  std::optional<simulation::SimulationReport> replay;
};

// The assignment's signs: mountain +1, valley −1, others 0.
Eigen::VectorXd assignment_velocity(const geometry::CreasePattern& pattern);

// Tachi's rigid-origami simulation: from the flat sheet, step along the desired velocity
// projected onto the null space of the closure Jacobian, then return to the closure manifold
// (Newton, minimum-norm steps, signs kept) below closure_tolerance. The flat sheet is singular:
// the first states are the closed states nearest to the desired direction at amplitudes growing
// to lead_in; when they collapse back towards flat, the pattern does not fold rigidly along the
// desired velocity (NotRigidlyFoldable). docs/PROJECTED_FOLDING.md. Throws std::invalid_argument
// for options out of range, a desired velocity of the wrong size or zero (or no assignment).
ProjectedFoldingResult fold_projected(const geometry::CreasePattern& pattern, const ProjectedFoldingOptions& options = {});

}  // namespace foldkit::folding
