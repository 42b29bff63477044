#pragma once
/// @file
/// The static equilibrium solve of a stiffness Problem: Newton with load stepping, or one linear
/// solve (docs/STIFFNESS.md).
#include <string>
#include <vector>

#include <Eigen/Core>

#include "foldkit/analysis/equilibrium.hpp"
#include "foldkit/geometry/progress.hpp"
#include "foldkit/geometry/status.hpp"

namespace foldkit::analysis {

/// Options of solve().
struct SolveOptions {
  bool linear = false;        ///< small displacements: one solve of Σ DᵀKD at the unloaded state
  /// Largest accepted scaled residual (∞-norm; forces in units of the largest load, moments in
  /// that times the tile size); raised to the residual's round-off level
  /// (EquilibriumSystem::residual_floor) where that is higher; linear mode accepts at least 1e-8.
  double tolerance = 1e-10;
  int max_iterations = 50;    ///< Newton iterations per load step
  /// Newton iterations in all, every load step together (then StatusCode::LimitReached).
  int max_total_iterations = 2000;
  /// Load stepping gives up below this fraction of the load (then StatusCode::NoProgress).
  double min_load_step = 1.0 / 4096;
  bool estimate_condition = true;     ///< whether to estimate SolveResult::condition_estimate on success
  /// Called after every Newton iteration: iterations done of max_total_iterations, unit
  /// "Newton iterations" (not called in linear mode).
  geometry::ProgressFn progress;
};

/// The equilibrium of one module.
struct ModuleResult {
  int id = 0;                 ///< the module's actor ID
  bool fixed = false;         ///< whether it is held fixed (then it does not move)
  /// Displacement of its centroid, pattern units; zero for a fixed module and when the solve failed.
  Eigen::Vector3d displacement = Eigen::Vector3d::Zero();
  /// Its rotation vector, radians; zero for a fixed module and when the solve failed.
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();
};

/// What solve() found.
struct SolveResult {
  /// StatusCode::Success, StatusCode::Singular (linear: the system is singular or
  /// ill-conditioned), StatusCode::NoProgress (the load step fell below min_load_step) or
  /// StatusCode::LimitReached (max_total_iterations).
  geometry::Status status;
  int iterations = 0;   ///< Newton iterations (linear mode: 1, or 0 when the factorisation failed)
  int load_steps = 0;   ///< load steps completed (linear mode: 1, or 0 when the factorisation failed)
  /// Achieved scaled residual (∞-norm; linear mode: of the linear system); −1 when not finite.
  double residual_norm = 0.0;
  /// The residual's round-off level at the solution (EquilibriumSystem::residual_floor; linear
  /// mode: or that of evaluating K·x + r₀, where higher): the tolerance is raised to it where it
  /// is higher.
  double residual_floor = 0.0;
  /// 1-norm estimate of the condition number of the Jacobi-scaled tangent (at the solution, where it
  /// is symmetric; linear mode: at the unloaded state); 0 when not estimated (estimate_condition
  /// off, or no success).
  double condition_estimate = 0.0;
  double max_displacement = 0.0;   ///< largest centroid displacement, pattern units
  std::vector<ModuleResult> modules;  ///< one per module of the structure, in its order
};

/// Solves `problem` for static equilibrium: Newton with analytic tangent, a sparse LDLᵀ of the
/// Jacobi-scaled tangent's symmetric part, backtracking line search on ‖r‖₂ and adaptive load
/// stepping (see docs/STIFFNESS.md); with `options.linear`, one linear solve instead. A problem
/// without free modules is solved at once (StatusCode::Success).
/// @param problem  the structure, its stiffness, supports and loads
/// @param options  linear or not, tolerance, iteration and load-step limits, progress
/// @return the displacements and how the solve ended (failures are reported, not thrown)
/// @throws std::invalid_argument when a module is not tied to a fixed one by any chain of
///         connections (the system would be singular)
SolveResult solve(const Problem& problem, const SolveOptions& options = {});

}  // namespace foldkit::analysis
