#pragma once
/// @file
/// Projected-velocity folding (Tachi's rigid-origami simulation): folding a crease pattern out of
/// the flat sheet along a desired crease velocity, kept on the closure manifold
/// (docs/PROJECTED_FOLDING.md).
#include <functional>
#include <future>
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

/// Folding methods: projected-velocity folding, Carpenter's rule (planar chains and single
/// vertices), Hamiltonian paths through pixel and voxel shapes, and chains of cubes.
namespace foldkit::folding {

/// Options of fold_projected(); the ranges given are checked.
struct ProjectedFoldingOptions {
  /// Desired velocity, one entry per joint, finite and not all zero (only its direction
  /// matters). Empty: the assignment's signs, mountain +1, valley −1, unassigned and flat 0
  /// (assignment_velocity()).
  Eigen::VectorXd velocity;
  /// Target fold angles, radians, one per joint, each in [−π, π], not all 0 (a file's intended
  /// folded state: an SVG's stroke opacities, a FOLD key frame, a CMML's end state); empty: none.
  /// When given, they are the desired velocity (`velocity` must then be empty) and
  /// target_fraction is a fraction of their largest |angle| instead of π.
  Eigen::VectorXd toward;
  /// Stop when the largest |fold angle| reaches target_fraction·π (with `toward`:
  /// target_fraction·max|toward|), in (0, 1].
  double target_fraction = 0.9;
  /// Largest change of any crease per step, radians, in (0, 0.5]: the step when chord_tolerance
  /// is 0, else the cap of the adaptive steps.
  double max_step = 0.05;
  /// Replay (the simulator, motors) and the collision checks follow the straight chord between
  /// consecutive states, which leaves the closure manifold in between. After the lead-in, each
  /// step is sized so that the loop error at its chord's midpoint is at most this (radians; it
  /// grows as the square of the step): steps grow where the path is straight and shrink where it
  /// bends, at most doubling from one step to the next, at most max_step. 0: every step is
  /// max_step. Otherwise in (closure_tolerance, 0.1]. The default is a tenth of the simulator's
  /// closure tolerance (simulation::SimulationOptions::closure_tolerance); docs/PROJECTED_FOLDING.md
  /// lists the replays measured at 1e-5 to 4e-4.
  double chord_tolerance = 1e-4;
  /// Amplitude (radians, largest crease; in (0, 1], and at most half the target angle) of the
  /// first state, the closed state nearest to the desired direction at this amplitude: the way
  /// out of the singular flat sheet, reached in max(10, ⌈lead_in / max_step⌉) equal steps (the
  /// first step after it is as long).
  double lead_in = 0.1;
  double closure_tolerance = 1e-10;  ///< largest loop error (radians) accepted at every state, in (0, 1e-3)
  bool collisions = true;            ///< check simulation::CollisionWorld between and at the states (and in the replay)
  int max_steps = 20000;             ///< most states after the flat one, at least 1 (then StatusCode::LimitReached)
  /// Rank of the Jacobian: singular values above √rank_tolerance · σ_max count. The LDLᵀ pivots
  /// of JᵀJ + εI (above rank_tolerance × the largest) screen every step; when their count changes
  /// or they collapse, geometry::LeastNormSolver::decide_rank decides from singular values.
  /// Positive.
  double rank_tolerance = 1e-8;
  /// A state is singular when its smallest kept singular value falls below this × σ_max (screened
  /// by √(smallest kept pivot / largest), confirmed by singular values). At least 0.
  double singular_ratio = 1e-7;
  /// One factorisation per step: J factored at the predicted point gives one Newton step, the
  /// chord steps after it and the next step's tangent (refactored at every iterate only when the
  /// chord steps stall). false: refactor at every Newton iterate and for every tangent (the
  /// method before, kept for comparison in microbench/bench_projected_folding.cpp). Both stop at
  /// the same closure tolerance.
  bool chord_corrector = true;
  /// Predict each step to second order, x + h·v + ½h²·a, with a the change of the unit tangent
  /// over the step before (O(h³) off the manifold instead of O(h²): one Newton step usually
  /// corrects it). false: x + h·v (the predictor before, kept for comparison in
  /// microbench/bench_projected_folding.cpp).
  bool second_order_predictor = true;
  /// Replay the CMML in the simulator (default simulation options, collisions as above) when the
  /// path has more than the flat state.
  bool replay = true;
  double speed = 1.0;                ///< the fastest joint's speed in each CMML event, rad/s, positive and finite
  /// Called at every accepted state (steps so far, unit "steps", its loop error) and by the replay
  /// (simulation::SimulationOptions::progress: events replayed of those pushed so far, a whole
  /// that grows while the folding goes on). The replay runs on a thread of its own beside the
  /// folding, so the calls come from two threads, interleaved, one at a time (serialised): a
  /// callback that takes a lock its caller holds around fold_projected would deadlock. One that
  /// throws on the replay's thread is rethrown when the folding ends.
  geometry::ProgressFn progress;
  /// Called once with the CMML's sequence (what ProjectedFoldingResult::sequence will hold) before
  /// the replay judges it, so that the caller can use it meanwhile (`foldkit fold` writes its file
  /// on the other core, and keeps it only when the replay accepts it); as
  /// planners::PlanOptions::sequence_ready: the sequence may be read from another thread until
  /// the future returned (when valid) is ready, which fold_projected() waits for before it
  /// returns. Called only when there is a replay.
  std::function<std::future<void>(const geometry::FoldSequence&)> sequence_ready;
};

/// What fold_projected() found.
struct ProjectedFoldingResult {
  /// Why projected-velocity folding stopped (docs/PROJECTED_FOLDING.md): StatusCode::Success (the
  /// largest fold angle reached target_fraction·π), StatusCode::Collision (the next step makes
  /// facets cross; the path ends before it), StatusCode::Singular (the closure Jacobian lost
  /// rank, its pivots collapsed, a crease returned to flat, the way out of flat jumped between
  /// branches, or the correction failed even at max_step/64), StatusCode::NotRigidlyFoldable (no
  /// closed state near flat follows the desired velocity: the square twist),
  /// StatusCode::NoProgress (the desired velocity has no component along the motions closure
  /// allows), StatusCode::LimitReached (max_steps). A replay the simulator rejects keeps the code
  /// and adds its reason to the message (see `replay`).
  geometry::Status status;
  /// The flat sheet first, then one state per step (one angle per joint, radians).
  std::vector<geometry::FoldState> states;
  double fraction = 0.0;             ///< largest |fold angle| / π at the last state
  /// With ProjectedFoldingOptions::toward: the largest |fold angle − target| over the creases at
  /// the last state, radians (how far the fold ended from the targets); else empty.
  std::optional<double> target_distance;
  double max_closure_error = 0.0;    ///< largest loop error over the states, radians
  /// Largest loop error at the midpoint of the chord between consecutive states, radians (what
  /// chord_tolerance bounds after the lead-in; the lead-in's chords are measured, not sized).
  double max_chord_error = 0.0;
  int steps = 0;                     ///< states after the flat one
  int newton_iterations = 0;         ///< corrector iterations, all steps together
  /// Rank of the closure Jacobian at the last rank decision (0 when none was made: the fold
  /// ended in the lead-in).
  int rank = 0;
  int dof = 0;                       ///< creases − rank there
  /// Smallest σ_min/σ_max estimate (see singular_ratio) along the path; 1 when none was made.
  double min_pivot_ratio = 1.0;
  int rank_decisions = 0;            ///< rank-revealing decisions made (the pivots' screen asked for them)
  double rank_gap = 0.0;             ///< geometry::RankDecision::gap() of the last decision (rank, dof above)
  double min_rank_gap = std::numeric_limits<double>::infinity();  ///< smallest gap over the decisions
  /// The last decision's method: "dense-svd", "sparse-qr", "inverse-subspace" or "none" (empty when no
  /// decision was made).
  std::string rank_method;
  double seconds = 0.0;              ///< wall-clock seconds of the folding (not the replay)
  geometry::FoldSequence sequence;   ///< CMML: flat → states (geometry::path_sequence, at `speed`)
  /// The simulator's report on `sequence`; empty when not replayed (replay off, or no step).
  std::optional<simulation::SimulationReport> replay;
};

/// The assignment's signs, one entry per joint: mountain +1, valley −1, others 0.
Eigen::VectorXd assignment_velocity(const geometry::CreasePattern& pattern);

/// Tachi's rigid-origami simulation: from the flat sheet, step along the desired velocity
/// projected onto the null space of the closure Jacobian, then return to the closure manifold
/// (Newton, minimum-norm steps, signs kept) below closure_tolerance. The flat sheet is singular:
/// the first states are the closed states nearest to the desired direction at amplitudes growing
/// to lead_in; when they collapse back towards flat, the pattern does not fold rigidly along the
/// desired velocity (StatusCode::NotRigidlyFoldable). docs/PROJECTED_FOLDING.md.
/// @param pattern  the crease pattern, with at least one crease
/// @param options  desired velocity, target, steps, tolerances, replay
/// @return the path, how it ended, and the replay's report; stopping early is a status, not an
///         exception
/// @throws std::invalid_argument for a pattern without creases, options out of range, a desired
///         velocity or target angles of the wrong size, not finite or zero (or, when neither is
///         given, no assignment), both velocity and targets, a target beyond ±π
ProjectedFoldingResult fold_projected(const geometry::CreasePattern& pattern, const ProjectedFoldingOptions& options = {});

}  // namespace foldkit::folding
