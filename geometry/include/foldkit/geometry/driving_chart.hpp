#pragma once
/// @file
/// Crease coordinates of the closure manifold: a few *driving* creases chosen so that every other
/// crease follows from them by closure, the Newton corrector that solves those others, and the
/// continuation that follows the manifold as the driving angles move (docs/PLANNING.md).
#include <functional>
#include <vector>

#include <Eigen/Core>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/null_space.hpp"
#include "foldkit/geometry/status.hpp"

namespace foldkit::geometry {

/// A chart of the closure manifold in crease coordinates: near a regular state of d degrees of
/// freedom, the closed states are a graph over d driving creases (the implicit function theorem
/// on the passive block of the Jacobian, which has full column rank there).
struct DrivingChart {
  std::vector<int> driving;  ///< joint indices of the driving creases, ascending; size = the DOF
  std::vector<int> passive;  ///< every other joint index, ascending
  /// How well the driving set was chosen: |r_dd / r_11| of the column-pivoted QR of the
  /// null-space basis' transpose (1 best, 0 singular): the smallest driving pivot relative to the
  /// largest. A passive block that is nearly singular shows here first.
  double conditioning = 0.0;
};

/// Chooses `dof` driving creases at a closed, regular `state`: an orthonormal basis N of the
/// Jacobian's null space (least-norm projections of `dof` + 2 seeded random vectors through one
/// sparse factorisation, then a rank-revealing QR), and the creases whose rows of N are the best
/// conditioned (column-pivoted QR of Nᵀ, Eigen's ColPivHouseholderQR): the passive block is then
/// as far from singular as a greedy choice gets.
/// @param system  the closure equations
/// @param state   a closed state where the Jacobian has its generic rank (not the flat sheet)
/// @param dof     the degrees of freedom there (geometry::mobility(system, state).dof), ≥ 0
/// @param seed    seed of the random vectors (the choice is deterministic for a seed)
/// @return the chart; a chart with no driving creases when `dof` is 0
/// @throws std::invalid_argument when `dof` is negative or exceeds the creases, or the null space
///         found has fewer than `dof` dimensions (the state is not regular or `dof` is wrong)
DrivingChart choose_driving_chart(const ClosureSystem& system, const FoldState& state, int dof, unsigned int seed = 1);

/// Settings of a PassiveSolver.
struct PassiveSolverOptions {
  double tolerance = 1e-12;      ///< largest loop error (radians) of a solved state
  int max_iterations = 12;       ///< Newton iterations per correction
  /// Largest change of any crease a single correction may make, radians: a larger one is a jump
  /// to another branch, not a correction.
  double max_correction = 0.25;
  /// Largest change of any crease between two continuation points, radians (the predictor's
  /// step is scaled to it).
  double max_step = 0.08;
  /// Smallest continuation step, as a fraction of the whole way: halving below it fails.
  double min_fraction = 1e-6;
  /// Asked before each continuation step (follow()); when it returns true the continuation stops
  /// where it is, with StatusCode::NoProgress ("stopped"). Empty: never. For a caller on another
  /// thread that may no longer want the result (the plan's straight plan).
  std::function<bool()> stop;
};

/// Solves the passive creases of a chart from its driving angles: Newton (Gauss–Newton on the
/// passive columns, the driving ones held) and continuation along the straight line in driving
/// coordinates with a tangent predictor from the same factorisation. Keeps a
/// geometry::LeastNormSolver (its symbolic analysis is reused), so it is not thread-safe: one
/// solver per thread.
class PassiveSolver {
 public:
  /// A solver for `chart` of `system`; both must outlive it.
  PassiveSolver(const ClosureSystem& system, const DrivingChart& chart, PassiveSolverOptions options = {});

  /// Newton on the passive creases of `state`, its driving angles held, until the loop error is
  /// at most options().tolerance.
  /// @return Success; NoProgress when the error stops falling or a correction exceeds
  ///         max_correction (the passive block is singular here, or the guess is on no branch);
  ///         LimitReached after max_iterations
  Status correct(FoldState& state);
  /// Follows the manifold from the closed `from` to the state whose driving angles are `target`
  /// (one per driving crease, in chart order): predictor–corrector steps along the straight line
  /// in driving coordinates, each moving no crease more than max_step, halved when a correction
  /// fails or jumps.
  /// @param from    a closed state (corrected first when it is not closed to the tolerance)
  /// @param target  the driving angles to reach
  /// @param out     the state reached (may be `from`); on failure, the last state reached
  /// @param path    when not null, every continuation point is appended (`from` first)
  /// @return Success, or the failing correction's status with the fraction reached in the message
  Status follow(const FoldState& from, const Eigen::VectorXd& target, FoldState& out, std::vector<FoldState>* path = nullptr);

  /// The driving angles of `state`, in chart order.
  Eigen::VectorXd driving_of(const FoldState& state) const;
  /// The chart.
  const DrivingChart& chart() const { return *chart_; }
  /// The settings.
  const PassiveSolverOptions& options() const { return options_; }
  /// Newton iterations taken since construction (for benchmarks and tests).
  long iterations() const { return iterations_; }

 private:
  void evaluate_passive(const FoldState& state);  // r_, J_ with the driving columns zeroed
  bool tangent(const Eigen::VectorXd& delta_driving, Eigen::VectorXd& velocity);

  const ClosureSystem* system_;
  const DrivingChart* chart_;
  PassiveSolverOptions options_;
  LeastNormSolver solver_;
  Eigen::VectorXd r_;
  Eigen::SparseMatrix<double> J_, Jd_;  // J_ passive columns only; Jd_ the full Jacobian
  std::vector<char> is_driving_;
  bool factored_ = false;
  bool evaluated_ = false;  // r_ and J_ belong to the state correct() last returned
  long iterations_ = 0;
};

}  // namespace foldkit::geometry
