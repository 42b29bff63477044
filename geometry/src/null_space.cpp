#include "foldkit/geometry/null_space.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace foldkit::geometry {

bool LeastNormSolver::factor(const Eigen::SparseMatrix<double>& jacobian) {
  a_ = jacobian.transpose() * jacobian;
  double largest = 0.0;
  for (Eigen::Index k = 0; k < a_.cols(); ++k) largest = std::max(largest, a_.coeff(k, k));
  eps_ = 1e-4 * rank_tolerance_ * std::max(largest, 1.0);
  for (Eigen::Index k = 0; k < a_.cols(); ++k) a_.coeffRef(k, k) += eps_;
  a_.makeCompressed();
  const int* outer = a_.outerIndexPtr();
  const int* inner = a_.innerIndexPtr();
  const auto cols = static_cast<std::size_t>(a_.cols()) + 1, nnz = static_cast<std::size_t>(a_.nonZeros());
  if (analyses_ == 0 || outer_.size() != cols || inner_.size() != nnz || !std::equal(outer_.begin(), outer_.end(), outer) ||
      !std::equal(inner_.begin(), inner_.end(), inner)) {
    ldlt_.analyzePattern(a_);
    outer_.assign(outer, outer + cols);
    inner_.assign(inner, inner + nnz);
    ++analyses_;
  }
  ldlt_.factorize(a_);
  return ldlt_.info() == Eigen::Success;
}

Eigen::VectorXd LeastNormSolver::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x = ldlt_.solve(b);
  x += ldlt_.solve(b - a_ * x);
  return x;
}

bool LeastNormSolver::min_norm_step(const Eigen::SparseMatrix<double>& jacobian, const Eigen::VectorXd& residual,
                                    Eigen::VectorXd& step) {
  if (!factor(jacobian)) return false;
  step = -solve(jacobian.transpose() * residual);
  return step.allFinite();
}

NullSpaceVelocity LeastNormSolver::project_onto_null_space(const Eigen::SparseMatrix<double>& jacobian,
                                                           const Eigen::VectorXd& desired) {
  NullSpaceVelocity t;
  const Eigen::Index n = jacobian.cols();
  if (jacobian.rows() == 0 || jacobian.nonZeros() == 0) {
    t.velocity = desired;
    return t;
  }
  if (!factor(jacobian)) {
    t.velocity = Eigen::VectorXd::Zero(n);
    t.rank = static_cast<int>(n);
    t.pivot_ratio = 0.0;
    return t;
  }
  t.velocity = eps_ * solve(desired);

  const Eigen::VectorXd d = ldlt_.vectorD();
  const double top = d.maxCoeff();
  double smallest_kept = std::numeric_limits<double>::infinity();
  for (Eigen::Index k = 0; k < n; ++k)
    if (d[k] > rank_tolerance_ * top) {
      ++t.rank;
      smallest_kept = std::min(smallest_kept, d[k]);
    }
  t.pivot_ratio = t.rank > 0 ? std::sqrt(smallest_kept / top) : 1.0;
  return t;
}

NullSpaceVelocity project_onto_null_space(const Eigen::SparseMatrix<double>& jacobian, const Eigen::VectorXd& desired,
                                          double rank_tolerance) {
  return LeastNormSolver(rank_tolerance).project_onto_null_space(jacobian, desired);
}

bool min_norm_step(const Eigen::SparseMatrix<double>& jacobian, const Eigen::VectorXd& residual, double rank_tolerance,
                   Eigen::VectorXd& step) {
  return LeastNormSolver(rank_tolerance).min_norm_step(jacobian, residual, step);
}

}  // namespace foldkit::geometry
