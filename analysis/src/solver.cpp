#include "foldkit/analysis/solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/SparseLU>

namespace foldkit::analysis {
namespace {

using Sparse = Eigen::SparseMatrix<double>;
using Eigen::VectorXd;
using geometry::StatusCode;

bool finite(const VectorXd& v) { return v.allFinite(); }

// The Jacobi-scaled tangent S·H·S (S = diag(1/√|Hᵢᵢ|)) factorised by SparseLU; the pattern of H
// never changes, so it is analysed once.
class ScaledLU {
 public:
  bool factor(const Sparse& h) {
    s_ = h.diagonal().cwiseAbs().cwiseSqrt().cwiseInverse();
    for (Eigen::Index i = 0; i < s_.size(); ++i)
      if (!std::isfinite(s_[i])) s_[i] = 1.0;
    scaled_ = s_.asDiagonal() * h * s_.asDiagonal();
    scaled_.makeCompressed();
    if (!analysed_) {
      lu_.analyzePattern(scaled_);
      analysed_ = true;
    }
    lu_.factorize(scaled_);
    return lu_.info() == Eigen::Success;
  }
  // H⁻¹ b.
  VectorXd solve(const VectorXd& b) { return s_.cwiseProduct(VectorXd(lu_.solve(s_.cwiseProduct(b)))); }

  // Hager's estimate of ‖(SHS)⁻¹‖₁ times ‖SHS‖₁: a 1-norm condition estimate of the scaled system.
  double condition() {
    const Eigen::Index n = scaled_.rows();
    if (n == 0) return 1.0;
    double norm = 0.0;
    for (Eigen::Index j = 0; j < n; ++j) norm = std::max(norm, scaled_.col(j).cwiseAbs().sum());
    VectorXd x = VectorXd::Constant(n, 1.0 / static_cast<double>(n));
    double inv = 0.0;
    for (int k = 0; k < 5; ++k) {
      const VectorXd y = lu_.solve(x);
      inv = y.lpNorm<1>();
      const VectorXd xi = y.unaryExpr([](double v) { return v >= 0 ? 1.0 : -1.0; });
      const VectorXd z = lu_.transpose().solve(xi);
      Eigen::Index j = 0;
      if (z.cwiseAbs().maxCoeff(&j) <= z.dot(x)) break;
      x.setZero();
      x[j] = 1.0;
    }
    return norm * inv;
  }

 private:
  VectorXd s_;
  Sparse scaled_;
  Eigen::SparseLU<Sparse, Eigen::COLAMDOrdering<int>> lu_;
  bool analysed_ = false;
};

struct Newton {
  const EquilibriumSystem& sys;
  const SolveOptions& opt;
  ScaledLU& lu;
  double tolerance;
  int iterations = 0;

  double tol(const VectorXd& x) const { return std::max(tolerance, sys.residual_floor(x)); }

  // Largest step along dx that turns no module by more than 0.5 rad: beyond that the tangent
  // says little.
  static double capped(const VectorXd& dx) {
    double largest = 0.0;
    for (Eigen::Index i = 3; i < dx.size(); i += 6) largest = std::max(largest, dx.segment<3>(i).norm());
    return std::min(1.0, 0.5 / std::max(largest, 1e-300));
  }

  // Drives x to equilibrium at `lambda` × the load; false when it cannot.
  //
  // Globalisation: a full (capped) Newton step after a large rotation opens the stiff springs to
  // second order, so ‖r‖ jumps by the stiffness ratio although the next step closes them again
  // (the Maratos effect). The watchdog therefore lets ‖r‖ rise for a few full steps; if it has not
  // fallen below the best point by then, it goes back there and backtracks along that point's
  // Newton direction until ‖r‖ decreases (Armijo).
  bool run(VectorXd& x, double lambda) {
    constexpr int kWatchdog = 6;
    VectorXd best = x;
    double best_merit = std::numeric_limits<double>::infinity();
    int since_best = 0;
    for (int it = 0; it < opt.max_iterations && iterations < opt.max_total_iterations; ++it) {
      VectorXd r = sys.residual(x, lambda);
      const bool ok = finite(r);
      // The floor bounds the round-off of displaced springs; the first state of a run is taken
      // exactly (springs at rest) or from the last load step, so a load below the floor still
      // gets one Newton step rather than passing as solved where it stands.
      if (ok && r.lpNorm<Eigen::Infinity>() <= (it == 0 ? tolerance : tol(x))) return true;
      if (ok && r.norm() < (1.0 - 1e-4) * best_merit) {
        best = x;
        best_merit = r.norm();
        since_best = 0;
      } else if (!ok || ++since_best >= kWatchdog) {
        x = best;
        r = sys.residual(x, lambda);
        if (!line_search(x, r, lambda)) return false;
        best_merit = sys.residual(x, lambda).norm();
        best = x;
        since_best = 0;
        continue;
      }
      if (!lu.factor(sys.tangent(x, lambda))) return false;
      const VectorXd dx = lu.solve(-r);
      if (!finite(dx)) return false;
      ++iterations;
      if (opt.progress) opt.progress({static_cast<double>(iterations), static_cast<double>(opt.max_total_iterations), "Newton iterations", -1.0});
      if (dx.lpNorm<Eigen::Infinity>() <= 1e-13 * (1.0 + x.lpNorm<Eigen::Infinity>()))
        return r.lpNorm<Eigen::Infinity>() <= 16.0 * tol(x);  // stalled at round-off
      x = sys.retract(x, capped(dx) * dx);
    }
    return sys.residual(x, lambda).lpNorm<Eigen::Infinity>() <= tol(x);
  }

  bool line_search(VectorXd& x, const VectorXd& r, double lambda) {
    if (!lu.factor(sys.tangent(x, lambda))) return false;
    const VectorXd dx = lu.solve(-r);
    if (!finite(dx)) return false;
    ++iterations;
    const double merit = r.norm();
    for (double alpha = capped(dx); alpha > 1e-6; alpha *= 0.5) {
      const VectorXd trial = sys.retract(x, alpha * dx);
      const VectorXd rt = sys.residual(trial, lambda);
      if (finite(rt) && rt.norm() <= (1.0 - 1e-4 * alpha) * merit) {
        x = trial;
        return true;
      }
    }
    return false;
  }
};

}  // namespace

SolveResult solve(const Problem& problem, const SolveOptions& options) {
  if (const int m = unrestrained_module(problem); m >= 0)
    throw std::invalid_argument("module " + std::to_string(problem.structure.modules[m].id) +
                                " is not tied to a fixed module by any chain of connections");
  const EquilibriumSystem sys(problem);
  SolveResult out;
  const double tol = std::max(options.tolerance, sys.residual_floor(VectorXd::Zero(sys.size())));
  VectorXd x = VectorXd::Zero(sys.size());
  ScaledLU lu;
  if (sys.size() == 0) {
    out.status = {StatusCode::Success, "no free module: nothing to solve"};
  } else if (options.linear) {
    if (lu.factor(sys.tangent(x, 1.0, false))) {
      const VectorXd r0 = sys.residual(x, 1.0);
      x = lu.solve(-r0);
      const VectorXd lin = sys.tangent(x, 1.0, false) * x + r0;
      out.iterations = out.load_steps = 1;
      out.residual_norm = lin.lpNorm<Eigen::Infinity>();
      out.residual_floor = sys.residual_floor(x);
      // Judged at the solution: the floor grows with the displacements the load produced.
      if (finite(x) && std::isfinite(out.residual_norm) && out.residual_norm <= std::max({tol, out.residual_floor, 1e-8}))
        out.status = {StatusCode::Success, "linear solution"};
    }
    if (!out.status) out.status = {StatusCode::Singular, "the linear system is singular or ill-conditioned"};
  } else {
    Newton newton{sys, options, lu, options.tolerance};
    double lambda = 0.0, step = 1.0;
    bool failed = false;
    while (lambda < 1.0 && !failed) {
      const double target = std::min(1.0, lambda + step);
      VectorXd trial = x;
      if (newton.run(trial, target)) {
        x = trial;
        lambda = target;
        ++out.load_steps;
        step *= 2.0;
      } else {
        step *= 0.5;
        failed = step < options.min_load_step || newton.iterations >= options.max_total_iterations;
      }
    }
    if (!failed) {
      // One polishing step: at the round-off floor it still often gains a digit.
      const VectorXd r = sys.residual(x, 1.0);
      if (lu.factor(sys.tangent(x, 1.0))) {
        const VectorXd trial = sys.retract(x, lu.solve(-r));
        const VectorXd rt = sys.residual(trial, 1.0);
        if (finite(rt) && rt.lpNorm<Eigen::Infinity>() < r.lpNorm<Eigen::Infinity>()) x = trial;
      }
    }
    out.iterations = newton.iterations;
    const VectorXd r = sys.residual(x, lambda);
    out.residual_norm = r.lpNorm<Eigen::Infinity>();
    out.residual_floor = sys.residual_floor(x);
    if (!failed)
      out.status = {StatusCode::Success, "converged"};
    else
      out.status = {newton.iterations >= options.max_total_iterations ? StatusCode::LimitReached : StatusCode::NoProgress,
                    "did not converge: reached " + std::to_string(lambda) + " of the load"};
    if (out.status && options.estimate_condition && lu.factor(sys.tangent(x, 1.0))) out.condition_estimate = lu.condition();
  }
  if (options.linear && out.status && options.estimate_condition) out.condition_estimate = lu.condition();
  const auto& modules = problem.structure.modules;
  for (std::size_t i = 0; i < modules.size(); ++i) {
    ModuleResult m;
    m.id = modules[i].id;
    const int k = sys.index_of(static_cast<int>(i));
    m.fixed = k < 0;
    if (k >= 0 && out.status) {
      m.displacement = x.segment<3>(6 * k) * sys.length_unit();
      m.rotation = x.segment<3>(6 * k + 3);
    }
    out.max_displacement = std::max(out.max_displacement, m.displacement.norm());
    out.modules.push_back(m);
  }
  if (!std::isfinite(out.residual_norm)) out.residual_norm = -1.0;
  return out;
}

}  // namespace foldkit::analysis
