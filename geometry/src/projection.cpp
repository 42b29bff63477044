#include "foldkit/geometry/projection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/SparseCholesky>

namespace foldkit::geometry {
namespace {

// The trial point of a step, held to [−π, π] and, when asked, to each crease's starting side.
Eigen::VectorXd trial(const Eigen::VectorXd& x, const Eigen::VectorXd& step, const Eigen::VectorXd& start, bool keep_signs) {
  Eigen::VectorXd y = x + step;
  for (Eigen::Index i = 0; i < y.size(); ++i) {
    y[i] = std::clamp(y[i], -M_PI, M_PI);
    if (keep_signs && start[i] != 0.0 && y[i] * start[i] <= 0.0) y[i] = 0.1 * x[i];  // approach 0, never cross
  }
  return y;
}

}  // namespace

ProjectionResult project(const ClosureSystem& system, const FoldState& start, const ProjectionOptions& options) {
  ProjectionResult out;
  out.state = start;
  Eigen::VectorXd& x = out.state.angles;
  for (Eigen::Index i = 0; i < x.size(); ++i)
    if (!std::isfinite(x[i])) {
      out.status = {StatusCode::InvalidInput, "the start state has a non-finite angle"};
      out.error = std::numeric_limits<double>::infinity();
      return out;
    }
  if (!options.held.empty() && options.held.size() != static_cast<std::size_t>(x.size()))
    throw std::invalid_argument("project: `held` must have one entry per joint");
  // Held creases get no column in the step: J·diag(free).
  Eigen::VectorXd free = Eigen::VectorXd::Ones(x.size());
  for (std::size_t i = 0; i < options.held.size(); ++i)
    if (options.held[i]) free[static_cast<Eigen::Index>(i)] = 0.0;
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  auto evaluate = [&] {
    system.evaluate(out.state, r, J);
    if (!options.held.empty()) J = J * free.asDiagonal();
  };
  evaluate();
  out.error = system.max_error(out.state);
  double mu = 1e-2;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  while (out.error > options.tolerance) {
    if (out.iterations >= options.max_iterations) {
      out.status = {StatusCode::LimitReached, "no convergence in " + std::to_string(options.max_iterations) + " iterations"};
      return out;
    }
    ++out.iterations;
    const Eigen::SparseMatrix<double> JJt = J * J.transpose();
    bool improved = false;
    for (int attempt = 0; attempt < 40 && !improved; ++attempt) {
      Eigen::SparseMatrix<double> M = JJt;
      const double lambda = mu * r.norm();
      for (Eigen::Index i = 0; i < M.rows(); ++i) M.coeffRef(i, i) += lambda;
      solver.compute(M);
      if (solver.info() != Eigen::Success) {
        mu *= 10;
        continue;
      }
      const Eigen::VectorXd step = -(J.transpose() * solver.solve(r));
      FoldState next{trial(x, step, start.angles, options.keep_signs)};
      const Eigen::VectorXd r_next = system.residual(next);
      if (r_next.allFinite() && r_next.norm() < r.norm()) {
        x = next.angles;
        mu = std::max(mu / 3, 1e-12);
        improved = true;
      } else {
        mu *= 4;
      }
    }
    if (!improved) {
      out.status = {StatusCode::NoProgress, "stuck: no step reduces the residual (a local minimum off the closure manifold)"};
      out.error = system.max_error(out.state);
      return out;
    }
    evaluate();
    out.error = system.max_error(out.state);
  }
  out.status = {StatusCode::Success, "converged"};
  return out;
}

}  // namespace foldkit::geometry
