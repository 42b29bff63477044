#include "projected_folding_tangent.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/SparseCholesky>

namespace foldkit::planners::detail {

namespace {

struct Regularised {
  Eigen::SparseMatrix<double> a;  // JᵀJ + εI
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  double eps = 0.0;

  bool factor(const Eigen::SparseMatrix<double>& jacobian, double rank_tolerance) {
    a = jacobian.transpose() * jacobian;
    double largest = 0.0;
    for (Eigen::Index k = 0; k < a.cols(); ++k) largest = std::max(largest, a.coeff(k, k));
    eps = 1e-4 * rank_tolerance * std::max(largest, 1.0);
    for (Eigen::Index k = 0; k < a.cols(); ++k) a.coeffRef(k, k) += eps;
    a.makeCompressed();
    ldlt.compute(a);
    return ldlt.info() == Eigen::Success;
  }
  // With one step of iterative refinement: the matrix is deliberately ill-conditioned (1/ε).
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const {
    Eigen::VectorXd x = ldlt.solve(b);
    x += ldlt.solve(b - a * x);
    return x;
  }
};

}  // namespace

bool min_norm_step(const Eigen::SparseMatrix<double>& jacobian, const Eigen::VectorXd& residual, double rank_tolerance,
                   Eigen::VectorXd& step) {
  Regularised reg;
  if (!reg.factor(jacobian, rank_tolerance)) return false;
  step = -reg.solve(jacobian.transpose() * residual);
  return step.allFinite();
}

Tangent project_onto_null_space(const Eigen::SparseMatrix<double>& jacobian, const Eigen::VectorXd& desired,
                                double rank_tolerance) {
  Tangent t;
  const Eigen::Index n = jacobian.cols();
  if (jacobian.rows() == 0 || jacobian.nonZeros() == 0) {
    t.velocity = desired;
    return t;
  }
  Regularised reg;
  if (!reg.factor(jacobian, rank_tolerance)) {
    t.velocity = Eigen::VectorXd::Zero(n);
    t.rank = static_cast<int>(n);
    t.pivot_ratio = 0.0;
    return t;
  }
  t.velocity = reg.eps * reg.solve(desired);

  const Eigen::VectorXd d = reg.ldlt.vectorD();
  const double top = d.maxCoeff();
  double smallest_kept = std::numeric_limits<double>::infinity();
  for (Eigen::Index k = 0; k < n; ++k)
    if (d[k] > rank_tolerance * top) {
      ++t.rank;
      smallest_kept = std::min(smallest_kept, d[k]);
    }
  t.pivot_ratio = t.rank > 0 ? std::sqrt(smallest_kept / top) : 1.0;
  return t;
}

}  // namespace foldkit::planners::detail
