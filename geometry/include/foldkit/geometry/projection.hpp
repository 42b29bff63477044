#pragma once
#include <string>
#include <vector>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/status.hpp"

namespace foldkit::geometry {

struct ProjectionOptions {
  double tolerance = 1e-10;  // largest loop error (radians) accepted as closed
  int max_iterations = 200;
  // Keep each crease on the side (mountain/valley) it starts on: near the flat state, where the
  // Jacobian drops rank, an unbiased step can flip creases to the other branch.
  bool keep_signs = true;
  // Creases (by joint index) held at their starting angles: only the others move. Empty: none.
  // A goal given by the angles of some creases is the closed state nearest to them this way.
  std::vector<bool> held;
};

struct ProjectionResult {
  FoldState state;
  // Success (closed within the tolerance), InvalidInput (a non-finite start angle),
  // LimitReached (max_iterations) or NoProgress (no step reduces the residual); the message
  // says which.
  Status status;
  int iterations = 0;
  double error = 0.0;   // largest loop error at `state`
};

// Levenberg–Marquardt with minimum-norm steps Δ = −Jᵀ(JJᵀ + λI)⁻¹ r (sparse LDLᵀ), damping
// λ = μ‖r‖ adapted by the gain of each step. Angles stay within [−π, π].
ProjectionResult project(const ClosureSystem& system, const FoldState& start, const ProjectionOptions& options = {});

}  // namespace foldkit::geometry
