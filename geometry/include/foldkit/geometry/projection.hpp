#pragma once
/// @file
/// Projection of a fold state onto the closure manifold: the closed state nearest to a given
/// one, by Levenberg–Marquardt on the loop-closure equations (ClosureSystem).
#include <string>
#include <vector>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/status.hpp"

namespace foldkit::geometry {

/// Options of project().
struct ProjectionOptions {
  double tolerance = 1e-10;  ///< largest loop error (radians, ClosureSystem::max_error) accepted as closed
  int max_iterations = 200;  ///< most Levenberg–Marquardt iterations before giving up (StatusCode::LimitReached)
  /// Keep each crease on the side (mountain/valley) it starts on: near the flat state, where the
  /// Jacobian drops rank, an unbiased step can flip creases to the other branch. A step that
  /// would reach or cross 0 moves the crease to a tenth of its current angle instead; a crease
  /// that starts at exactly 0 is not held to a side.
  bool keep_signs = true;
  /// Creases (by joint index) held at their starting angles: only the others move. Empty: none;
  /// otherwise one entry per joint. A goal given by the angles of some creases is the closed
  /// state nearest to them this way.
  std::vector<bool> held;
};

/// What project() found.
struct ProjectionResult {
  FoldState state;  ///< the last accepted state (the start when no step was taken), one angle per joint, radians
  /// How it ended: StatusCode::Success (closed within the tolerance), StatusCode::InvalidInput
  /// (a non-finite start angle), StatusCode::LimitReached (max_iterations) or
  /// StatusCode::NoProgress (no step reduces the residual); the message says which.
  Status status;
  int iterations = 0;   ///< iterations taken
  double error = 0.0;   ///< largest loop error at `state`, radians (infinity for StatusCode::InvalidInput)
};

/// Projects `start` onto the closure manifold of `system`: Levenberg–Marquardt with
/// minimum-norm steps Δ = −Jᵀ(JJᵀ + λI)⁻¹ r (sparse LDLᵀ), damping λ = μ‖r‖ adapted by the gain
/// of each step. Angles stay within [−π, π].
/// @param system   the closure equations of the pattern
/// @param start    the state to start from, one angle per joint, radians
/// @param options  tolerance, iteration budget, sign keeping and held creases
/// @return the state reached and how it ended (never throws for a non-finite start: that is
///         StatusCode::InvalidInput)
/// @throws std::invalid_argument when `options.held` is neither empty nor one entry per joint
ProjectionResult project(const ClosureSystem& system, const FoldState& start, const ProjectionOptions& options = {});

}  // namespace foldkit::geometry
