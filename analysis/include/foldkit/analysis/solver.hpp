#pragma once
#include <string>
#include <vector>

#include <Eigen/Core>

#include "foldkit/analysis/equilibrium.hpp"
#include "foldkit/geometry/progress.hpp"
#include "foldkit/geometry/status.hpp"

namespace foldkit::analysis {

struct SolveOptions {
  bool linear = false;        // small displacements: one solve of Σ DᵀKD at the unloaded state
  double tolerance = 1e-10;   // on the scaled residual (∞-norm; forces in units of the largest load)
  int max_iterations = 50;    // Newton iterations per load step
  int max_total_iterations = 2000;
  double min_load_step = 1.0 / 4096;  // load stepping gives up below this fraction of the load
  bool estimate_condition = true;
  geometry::ProgressFn progress;  // per Newton iteration
};

struct ModuleResult {
  int id = 0;
  bool fixed = false;
  Eigen::Vector3d displacement = Eigen::Vector3d::Zero();  // of the centroid, in length units
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();      // rotation vector, radians
};

struct SolveResult {
  // Success, Singular (linear: the system is singular or ill-conditioned), NoProgress (the
  // load step fell below min_load_step) or LimitReached (max_total_iterations).
  geometry::Status status;
  int iterations = 0;   // Newton iterations (linear mode: 1)
  int load_steps = 0;
  double residual_norm = 0.0;      // achieved scaled residual (∞-norm)
  double residual_floor = 0.0;     // the round-off level the tolerance was raised to, if above it
  double condition_estimate = 0.0; // of the Jacobi-scaled tangent at the solution (1-norm estimate)
  double max_displacement = 0.0;   // largest centroid displacement, length units
  std::vector<ModuleResult> modules;
};

// Newton with analytic tangent, SparseLU on the Jacobi-scaled system, backtracking line search on
// ‖r‖₂ and adaptive load stepping (see docs/STIFFNESS.md). Throws std::invalid_argument when a
// module is not tied to a fixed one (the system would be singular).
SolveResult solve(const Problem& problem, const SolveOptions& options = {});

}  // namespace foldkit::analysis
