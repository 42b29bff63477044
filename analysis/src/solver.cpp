#include "foldkit/analysis/solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <Eigen/SparseCholesky>

namespace foldkit::analysis {
namespace {

using Sparse = Eigen::SparseMatrix<double>;
using Eigen::VectorXd;
using geometry::StatusCode;

bool finite(const VectorXd& v) { return v.allFinite(); }

// The Jacobi-scaled tangent S·H·S (S = diag(1/√|Hᵢᵢ|)), symmetrised and factorised by a sparse
// LDLᵀ (AMD ordering, analysed once: the pattern of H never changes).
//
// Why the symmetric part: H is the derivative of the potential's gradient under left
// perturbations, and differs from its transpose by terms that grow with the unbalanced forces
// and moments (measured: ‖H − Hᵀ‖ ≈ 0.3–0.7 ‖r‖ on a loaded cube), which vanish at equilibrium. The step from ½(H + Hᵀ) is therefore off by
// O(‖r‖·‖dx‖) and Newton stays quadratic (as many iterations as LU on H, or fewer, on every benchmark
// structure), while LDLᵀ is 1.5–2× cheaper than SparseLU here (bench_stiffness_ceres). Where the
// symmetric part is singular (no pivot), the caller backtracks or halves the load step as for LU.
class ScaledTangent {
 public:
  bool factor(const Sparse& h) {
    if (!same_pattern(h)) analyse(h);
    s_ = h.diagonal().cwiseAbs().cwiseSqrt().cwiseInverse();
    for (Eigen::Index i = 0; i < s_.size(); ++i)
      if (!std::isfinite(s_[i])) s_[i] = 1.0;
    const double* v = h.valuePtr();
    const int* outer = h.outerIndexPtr();
    const int* inner = h.innerIndexPtr();
    double* out = scaled_.valuePtr();
    for (Eigen::Index j = 0; j < h.outerSize(); ++j)
      for (int e = outer[j]; e < outer[j + 1]; ++e)
        out[e] = 0.5 * (v[e] + v[partner_[static_cast<std::size_t>(e)]]) * s_[inner[e]] * s_[j];
    ldlt_.factorize(scaled_);
    return ldlt_.info() == Eigen::Success;
  }
  // H⁻¹ b (of the symmetric part).
  VectorXd solve(const VectorXd& b) { return s_.cwiseProduct(VectorXd(ldlt_.solve(s_.cwiseProduct(b)))); }

  // Hager's estimate of ‖(SHS)⁻¹‖₁ times ‖SHS‖₁: a 1-norm condition estimate of the scaled system.
  double condition() {
    const Eigen::Index n = scaled_.rows();
    if (n == 0) return 1.0;
    double norm = 0.0;
    for (Eigen::Index j = 0; j < n; ++j) norm = std::max(norm, scaled_.col(j).cwiseAbs().sum());
    VectorXd x = VectorXd::Constant(n, 1.0 / static_cast<double>(n));
    double inv = 0.0;
    for (int k = 0; k < 5; ++k) {
      const VectorXd y = ldlt_.solve(x);
      inv = y.lpNorm<1>();
      const VectorXd xi = y.unaryExpr([](double v) { return v >= 0 ? 1.0 : -1.0; });
      const VectorXd z = ldlt_.solve(xi);  // symmetric: the transpose solve is the same
      Eigen::Index j = 0;
      if (z.cwiseAbs().maxCoeff(&j) <= z.dot(x)) break;
      x.setZero();
      x[j] = 1.0;
    }
    return norm * inv;
  }

 private:
  bool same_pattern(const Sparse& h) const {
    return h.isCompressed() && scaled_.rows() == h.rows() && scaled_.nonZeros() == h.nonZeros() &&
           std::equal(h.outerIndexPtr(), h.outerIndexPtr() + h.outerSize() + 1, scaled_.outerIndexPtr()) &&
           std::equal(h.innerIndexPtr(), h.innerIndexPtr() + h.nonZeros(), scaled_.innerIndexPtr());
  }
  // The pattern must be structurally symmetric (EquilibriumSystem's is: whole 6×6 blocks in pairs).
  void analyse(const Sparse& h) {
    scaled_ = h;
    scaled_.makeCompressed();
    partner_.assign(static_cast<std::size_t>(scaled_.nonZeros()), 0);
    const int* outer = scaled_.outerIndexPtr();
    const int* inner = scaled_.innerIndexPtr();
    for (Eigen::Index j = 0; j < scaled_.outerSize(); ++j)
      for (int e = outer[j]; e < outer[j + 1]; ++e) {
        const int i = inner[e];
        const int* at = std::lower_bound(inner + outer[i], inner + outer[i + 1], static_cast<int>(j));
        if (at == inner + outer[i + 1] || *at != j) throw std::logic_error("stiffness tangent: pattern not symmetric");
        partner_[static_cast<std::size_t>(e)] = static_cast<std::size_t>(at - inner);
      }
    ldlt_.analyzePattern(scaled_);
  }

  VectorXd s_;
  Sparse scaled_;
  std::vector<std::size_t> partner_;  // the position of each entry's transpose
  Eigen::SimplicialLDLT<Sparse, Eigen::Lower, Eigen::AMDOrdering<int>> ldlt_;
};

// The round-off level of K·x + r₀ evaluated in floating point, entry by entry: row i sums mᵢ
// products, so it is off by about √mᵢ·ε·((|K|·|x|)ᵢ + |r₀ᵢ|) (the probabilistic bound of Higham &
// Mary 2019; the worst case mᵢ·ε·… is some 10× above what is seen). On long slender structures
// |K|·|x| is many orders above |K·x|, and this, not the solve, limits the residual.
double product_floor(const Sparse& k, const VectorXd& x, const VectorXd& r0) {
  VectorXd terms = VectorXd::Ones(k.rows()), magnitude = r0.cwiseAbs();
  for (Eigen::Index j = 0; j < k.outerSize(); ++j)
    for (Sparse::InnerIterator it(k, j); it; ++it) {
      terms[it.row()] += 1.0;
      magnitude[it.row()] += std::abs(it.value() * x[j]);
    }
  return std::numeric_limits<double>::epsilon() * terms.cwiseSqrt().cwiseProduct(magnitude).maxCoeff();
}

struct Newton {
  const EquilibriumSystem& sys;
  const SolveOptions& opt;
  ScaledTangent& tangent_solver;
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
      if (!tangent_solver.factor(sys.tangent(x, lambda))) return false;
      const VectorXd dx = tangent_solver.solve(-r);
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
    if (!tangent_solver.factor(sys.tangent(x, lambda))) return false;
    const VectorXd dx = tangent_solver.solve(-r);
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

// Linear mode: one solve of Σ DᵀKD at the unloaded state, its residual judged at the solution
// (the floors grow with the displacements the load produced).
void solve_linear(const EquilibriumSystem& sys, double tol, ScaledTangent& tangent_solver, VectorXd& x, SolveResult& out) {
  const Sparse k = sys.tangent(x, 1.0, false);
  if (tangent_solver.factor(k)) {
    const VectorXd r0 = sys.residual(x, 1.0);
    x = tangent_solver.solve(-r0);
    const VectorXd lin = k * x + r0;
    out.iterations = out.load_steps = 1;
    out.residual_norm = lin.lpNorm<Eigen::Infinity>();
    out.residual_floor = finite(x) ? std::max(sys.residual_floor(x), product_floor(k, x, r0)) : 0.0;
    if (finite(x) && std::isfinite(out.residual_norm) && out.residual_norm <= std::max({tol, out.residual_floor, 1e-8}))
      out.status = {StatusCode::Success, "linear solution"};
  }
  if (!out.status) out.status = {StatusCode::Singular, "the linear system is singular or ill-conditioned"};
}

}  // namespace

SolveResult solve(const Problem& problem, const SolveOptions& options) {
  if (const int m = unrestrained_module(problem); m >= 0)
    throw std::invalid_argument("module " + std::to_string(problem.structure.modules[m].id) +
                                " is not tied to a fixed module by any chain of connections");
  const EquilibriumSystem sys(problem);
  SolveResult out;
  const double tol = std::max(options.tolerance, sys.residual_floor(VectorXd::Zero(sys.size())));
  VectorXd x = VectorXd::Zero(sys.size());
  ScaledTangent tangent_solver;
  if (sys.size() == 0) {
    out.status = {StatusCode::Success, "no free module: nothing to solve"};
  } else if (options.linear) {
    solve_linear(sys, tol, tangent_solver, x, out);
  } else {
    Newton newton{sys, options, tangent_solver, options.tolerance};
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
    bool factored_at_x = false;  // tangent_solver holds the tangent at the final x
    if (!failed) {
      // One polishing step: at the round-off floor it still often gains a digit.
      const VectorXd r = sys.residual(x, 1.0);
      if (tangent_solver.factor(sys.tangent(x, 1.0))) {
        factored_at_x = true;
        const VectorXd trial = sys.retract(x, tangent_solver.solve(-r));
        const VectorXd rt = sys.residual(trial, 1.0);
        if (finite(rt) && rt.lpNorm<Eigen::Infinity>() < r.lpNorm<Eigen::Infinity>()) {
          x = trial;
          factored_at_x = false;
        }
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
    if (out.status && options.estimate_condition && (factored_at_x || tangent_solver.factor(sys.tangent(x, 1.0))))
      out.condition_estimate = tangent_solver.condition();
  }
  if (options.linear && out.status && options.estimate_condition) out.condition_estimate = tangent_solver.condition();
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
