#include "foldkit/geometry/driving_chart.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include <Eigen/QR>
#include <Eigen/SVD>

namespace foldkit::geometry {

DrivingChart choose_driving_chart(const ClosureSystem& system, const FoldState& state, int dof, unsigned int seed) {
  const Eigen::Index n = system.cols();
  if (dof < 0 || dof > n) throw std::invalid_argument("choose_driving_chart: dof " + std::to_string(dof) + " is out of range");
  DrivingChart chart;
  if (dof == 0) {
    for (Eigen::Index j = 0; j < n; ++j) chart.passive.push_back(static_cast<int>(j));
    chart.conditioning = 1.0;
    return chart;
  }
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  system.evaluate(state, r, J);
  // A few more random vectors than the null space has dimensions, projected through one
  // factorisation: their span is the null space, and the SVD below says whether it has `dof`
  // dimensions (a dense SVD of J would cost O(n³) on sheets of thousands of creases).
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  const int k = dof + 2;
  Eigen::MatrixXd V(n, k);
  LeastNormSolver solver;
  for (int c = 0; c < k; ++c) {
    Eigen::VectorXd w(n);
    for (Eigen::Index j = 0; j < n; ++j) w[j] = normal(rng);
    V.col(c) = c == 0 ? solver.project_onto_null_space(J, w).velocity : solver.project_with_last_factor(w).velocity;
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(V, Eigen::ComputeThinU);
  const Eigen::VectorXd& s = svd.singularValues();
  int found = 0;
  while (found < k && s[found] > 1e-6 * s[0]) ++found;
  if (found < dof)
    throw std::invalid_argument("choose_driving_chart: the null space has " + std::to_string(found) + " dimensions, not " +
                                std::to_string(dof) + " (the state is not regular)");
  const Eigen::MatrixXd basis = svd.matrixU().leftCols(dof);
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(basis.transpose());
  std::vector<char> driving(static_cast<std::size_t>(n), 0);
  for (int i = 0; i < dof; ++i) driving[static_cast<std::size_t>(qr.colsPermutation().indices()[i])] = 1;
  for (Eigen::Index j = 0; j < n; ++j) (driving[static_cast<std::size_t>(j)] ? chart.driving : chart.passive).push_back(static_cast<int>(j));
  const Eigen::MatrixXd R = qr.matrixR().topLeftCorner(dof, dof).triangularView<Eigen::Upper>();
  chart.conditioning = std::abs(R(dof - 1, dof - 1)) / std::abs(R(0, 0));
  return chart;
}

PassiveSolver::PassiveSolver(const ClosureSystem& system, const DrivingChart& chart, PassiveSolverOptions options)
    : system_(&system), chart_(&chart), options_(options), is_driving_(static_cast<std::size_t>(system.cols()), 0) {
  for (int j : chart.driving) {
    if (j < 0 || j >= system.cols()) throw std::invalid_argument("PassiveSolver: a driving crease is out of range");
    is_driving_[static_cast<std::size_t>(j)] = 1;
  }
}

Eigen::VectorXd PassiveSolver::driving_of(const FoldState& state) const {
  Eigen::VectorXd d(static_cast<Eigen::Index>(chart_->driving.size()));
  for (std::size_t i = 0; i < chart_->driving.size(); ++i) d[static_cast<Eigen::Index>(i)] = state.angles[chart_->driving[i]];
  return d;
}

void PassiveSolver::evaluate_passive(const FoldState& state) {
  system_->evaluate(state, r_, Jd_);
  // The driving columns are zeroed in place rather than removed: the sparsity pattern stays the
  // same, so the solver keeps its symbolic analysis, and the least-norm step leaves them at 0.
  J_ = Jd_;
  for (int j : chart_->driving)
    for (Eigen::SparseMatrix<double>::InnerIterator it(J_, j); it; ++it) it.valueRef() = 0.0;
}

Status PassiveSolver::correct(FoldState& state) {
  // Newton's step factors J at the point it starts from; the steps after it reuse that
  // factorisation (chord steps) while each at least quarters the error. Near the solution a chord
  // step costs a residual and two triangular solves where a Newton step costs a Jacobian, JᵀJ and
  // a factorisation, which were most of a continuation's time (plan Miura 40×40). A chord step
  // that does not quarter the error, or jumps, is undone and a Newton step taken from the same
  // point instead, so the corrector converges at least as Newton does and fails as Newton fails.
  const Eigen::VectorXd start = state.angles;
  evaluate_passive(state);
  double error = system_->residual_error(r_), previous = std::numeric_limits<double>::infinity();
  evaluated_ = true;  // r_ and J_ belong to `state` (after a chord step only r_ does)
  bool chord = false;     // the factorisation belongs to this correction
  Eigen::VectorXd step, saved;
  for (int newton = 0, turns = 0;; ++turns) {
    if (!std::isfinite(error)) return {StatusCode::NoProgress, "the loop error is not finite"};
    if (error <= options_.tolerance) return {StatusCode::Success, "closed"};
    if (chord && turns < 4 * options_.max_iterations && solver_.chord_step(J_, r_, step)) {
      saved = state.angles;
      state.angles += step;
      r_ = system_->residual(state);
      const double chord_error = system_->residual_error(r_);
      if (chord_error <= 0.25 * error && (state.angles - start).cwiseAbs().maxCoeff() <= options_.max_correction) {
        error = chord_error;
        continue;
      }
      state.angles = saved;
    }
    chord = false;
    if (!evaluated_) {
      evaluate_passive(state);
      error = system_->residual_error(r_);
      evaluated_ = true;
      if (!std::isfinite(error) || error <= options_.tolerance) continue;
    }
    if (newton >= options_.max_iterations)
      return {StatusCode::LimitReached, "not closed after " + std::to_string(newton) + " Newton iterations"};
    // Newton converges quadratically on a regular passive block; an error that does not even
    // halve means the block is (nearly) singular or the guess lies on no branch.
    if (newton >= 2 && error > 0.5 * previous) return {StatusCode::NoProgress, "Newton stalls (the passive block is singular here)"};
    previous = error;
    if (!solver_.min_norm_step(J_, r_, step)) return {StatusCode::NoProgress, "the passive block could not be factored"};
    factored_ = chord = true;
    ++newton;
    ++iterations_;
    state.angles += step;
    if ((state.angles - start).cwiseAbs().maxCoeff() > options_.max_correction)
      return {StatusCode::NoProgress, "the correction jumps (another branch)"};
    r_ = system_->residual(state);
    error = system_->residual_error(r_);
    evaluated_ = false;
  }
}

bool PassiveSolver::tangent(const Eigen::VectorXd& delta_driving, Eigen::VectorXd& velocity) {
  // d(passive) = −J_P⁺ J_D d(driving), through the factorisation the corrector made last.
  velocity = Eigen::VectorXd::Zero(system_->cols());
  for (std::size_t i = 0; i < chart_->driving.size(); ++i) velocity[chart_->driving[i]] = delta_driving[static_cast<Eigen::Index>(i)];
  const Eigen::VectorXd moved = Jd_ * velocity;
  Eigen::VectorXd step;
  if (!factored_ || !solver_.chord_step(J_, moved, step)) return false;
  velocity += step;
  return velocity.allFinite();
}

Status PassiveSolver::follow(const FoldState& from, const Eigen::VectorXd& target, FoldState& out, std::vector<FoldState>* path) {
  if (target.size() != static_cast<Eigen::Index>(chart_->driving.size()))
    throw std::invalid_argument("PassiveSolver::follow: the target does not hold one angle per driving crease");
  FoldState x = from;
  Status st = correct(x);
  if (!st) {
    out = x;
    return {st.code, "the start does not close: " + st.message};
  }
  // A fresh factorisation at the start, so that the first tangent is the start's own (J_ is
  // evaluated again only when correct() ended on chord steps, with J_ of an earlier point).
  // Reusing the last correction's
  // factorisation here, when it was made within a step of `from`, saved 5 % of a Miura 40×40
  // plan's wall time but sent the continuation onto another branch on a Resch goal that this
  // solves (scripts/experience-queries.py, goal 5: "the planned path jumps").
  Eigen::VectorXd unused;
  if (!evaluated_) evaluate_passive(x);
  factored_ = solver_.min_norm_step(J_, r_, unused) || factored_;
  if (path) path->push_back(x);
  const Eigen::VectorXd d0 = driving_of(x), D = target - d0;
  double t = 0.0, cap = 1.0;
  while (t < 1.0 && D.cwiseAbs().maxCoeff() > 0.0) {
    if (options_.stop && options_.stop()) {
      out = x;
      return {StatusCode::NoProgress, "stopped at " + std::to_string(t) + " of the way"};
    }
    Eigen::VectorXd v;
    if (!tangent(D, v)) v = Eigen::VectorXd::Zero(x.angles.size());
    for (std::size_t i = 0; i < chart_->driving.size(); ++i) v[chart_->driving[i]] = D[static_cast<Eigen::Index>(i)];
    const double speed = v.cwiseAbs().maxCoeff();
    double frac = std::min({1.0 - t, cap, speed > 0.0 ? options_.max_step / speed : 1.0});
    bool accepted = false;
    while (!accepted) {
      FoldState y{x.angles + frac * v};
      const double t_next = frac >= 1.0 - t ? 1.0 : t + frac;
      for (std::size_t i = 0; i < chart_->driving.size(); ++i)
        y.angles[chart_->driving[i]] = t_next >= 1.0 ? target[static_cast<Eigen::Index>(i)]
                                                    : d0[static_cast<Eigen::Index>(i)] + t_next * D[static_cast<Eigen::Index>(i)];
      st = correct(y);
      // A point farther than twice the step from the last is on another sheet of the manifold.
      if (st && (y.angles - x.angles).cwiseAbs().maxCoeff() <= 2.0 * options_.max_step) {
        x = std::move(y);
        t = t_next;
        cap = std::min(1.0, 2.0 * frac);
        accepted = true;
        if (path) path->push_back(x);
      } else {
        frac *= 0.5;
        if (frac < options_.min_fraction) {
          out = x;
          return {st ? StatusCode::NoProgress : st.code,
                  "continuation stalls at " + std::to_string(t) + " of the way (" + (st ? "a jump" : st.message) + ")"};
        }
      }
    }
  }
  out = std::move(x);
  return {StatusCode::Success, "reached"};
}

}  // namespace foldkit::geometry
