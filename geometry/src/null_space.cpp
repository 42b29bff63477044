#include "foldkit/geometry/null_space.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <random>

#include <Eigen/QR>
#include <Eigen/SVD>

#include "sparse_qr_rank.hpp"

namespace foldkit::geometry {

bool LeastNormSolver::factor(const Eigen::SparseMatrix<double>& jacobian, double eps_floor) {
  a_ = jacobian.transpose() * jacobian;
  double largest = 0.0;
  for (Eigen::Index k = 0; k < a_.cols(); ++k) largest = std::max(largest, a_.coeff(k, k));
  eps_ = 1e-4 * rank_tolerance_ * std::max(largest, eps_floor);
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
  factored_ = ldlt_.info() == Eigen::Success;
  return factored_;
}

Eigen::VectorXd LeastNormSolver::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x = ldlt_.solve(b);
  x += ldlt_.solve(b - a_ * x);
  return x;
}

bool LeastNormSolver::min_norm_step(const Eigen::SparseMatrix<double>& jacobian, const Eigen::VectorXd& residual,
                                    Eigen::VectorXd& step, bool refine) {
  if (!factor(jacobian)) return false;
  const Eigen::VectorXd b = jacobian.transpose() * residual;
  step = refine ? Eigen::VectorXd(-solve(b)) : Eigen::VectorXd(-ldlt_.solve(b));
  return step.allFinite();
}

bool LeastNormSolver::chord_step(const Eigen::SparseMatrix<double>& jacobian, const Eigen::VectorXd& residual,
                                 Eigen::VectorXd& step) const {
  if (!factored_ || jacobian.cols() != a_.cols()) return false;
  // No refinement: a chord step is approximate anyway, and the next iteration corrects it.
  step = -ldlt_.solve(jacobian.transpose() * residual);
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
  count_pivots(t);
  return t;
}

NullSpaceVelocity LeastNormSolver::project_with_last_factor(const Eigen::VectorXd& desired) const {
  if (!factored_ || desired.size() != a_.cols())
    throw std::logic_error("LeastNormSolver::project_with_last_factor: no factorisation of this size");
  NullSpaceVelocity t;
  t.velocity = eps_ * solve(desired);
  count_pivots(t);
  return t;
}

void LeastNormSolver::count_pivots(NullSpaceVelocity& t) const {
  const Eigen::VectorXd d = ldlt_.vectorD();
  const double top = d.maxCoeff();
  double smallest_kept = std::numeric_limits<double>::infinity();
  t.rank = 0;
  for (Eigen::Index k = 0; k < d.size(); ++k)
    if (d[k] > rank_tolerance_ * top) {
      ++t.rank;
      smallest_kept = std::min(smallest_kept, d[k]);
    }
  t.pivot_ratio = t.rank > 0 ? std::sqrt(smallest_kept / top) : 1.0;
}

double RankDecision::gap() const {
  return smallest_kept / std::max(largest_zero, 1e-16 * sigma_max);
}

namespace {

// Counts singular values (ascending) above `tolerance` and records the two on either side of it.
void count(const Eigen::VectorXd& ascending, Eigen::Index columns, RankDecision& d) {
  d.nullity = 0;
  d.largest_zero = 0.0;
  d.smallest_kept = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < ascending.size(); ++i) {
    if (ascending[i] <= d.tolerance) {
      ++d.nullity;
      d.largest_zero = ascending[i];
    } else {
      d.smallest_kept = std::min(d.smallest_kept, ascending[i]);
    }
  }
  d.rank = static_cast<int>(columns) - d.nullity;
}

// The largest singular value of J, by power iteration on JᵀJ: to 1e-6 relative, or after 200
// iterations when the top of the spectrum is clustered. Then it is a little low (a lower bound, as
// every iterate is): Miura 100×100 flat stops at 2.23175 where Lanczos (Spectra, 500–3,500
// products, 4–15× the time) finds 2.23582, 1.8e-3 higher. It only scales the tolerance, and a
// decision must clear it by a factor 10 either way (decide_by_qr), so that error cannot flip one.
double largest_singular_value(const Eigen::SparseMatrix<double>& J) {
  Eigen::VectorXd x = Eigen::VectorXd::Ones(J.cols());
  for (Eigen::Index k = 0; k < x.size(); k += 3) x[k] = 0.5;  // not orthogonal to a sign-symmetric top vector
  double sigma = 0.0;
  for (int it = 0; it < 200; ++it) {
    const double norm = x.norm();
    if (!(norm > 0.0)) return 0.0;
    x /= norm;
    const Eigen::VectorXd y = J * x;
    const double next = y.norm();
    x = J.transpose() * y;
    if (std::abs(next - sigma) <= 1e-6 * next) return next;
    sigma = next;
  }
  return sigma;
}

Eigen::MatrixXd orthonormal(const Eigen::MatrixXd& z) {
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(z);
  return qr.householderQ() * Eigen::MatrixXd::Identity(z.rows(), z.cols());
}

Eigen::VectorXd ascending_singular_values(const Eigen::MatrixXd& m) {
  Eigen::BDCSVD<Eigen::MatrixXd> svd(m);
  return svd.singularValues().reverse();
}

// SuiteSparse QR's count when its bounds are clear of the tolerance by `margin` on both sides
// (LeastNormSolver::decide_rank, "sparse-qr"); false leaves the decision to the subspace iteration.
bool decide_by_qr(const Eigen::SparseMatrix<double>& jacobian, RankDecision& d) {
  constexpr double margin = 10.0;
  const detail::QrRank qr = detail::sparse_qr_rank(jacobian, d.tolerance / margin);
  if (!qr.ok) return false;
  const double kept = qr.rank > 0 ? qr.smallest_live - qr.dropped : std::numeric_limits<double>::infinity();
  if (qr.dropped > d.tolerance / margin || kept < margin * d.tolerance) return false;
  d.rank = qr.rank;
  d.nullity = static_cast<int>(jacobian.cols()) - qr.rank;
  d.largest_zero = d.nullity > 0 ? qr.dropped : 0.0;
  d.smallest_kept = kept;
  d.method = "sparse-qr";
  return true;
}

}  // namespace

RankDecision LeastNormSolver::decide_rank(const Eigen::SparseMatrix<double>& jacobian, double relative_tolerance,
                                          Eigen::Index dense_limit, double scale_floor, SparseRankMethod sparse) {
  RankDecision d;
  const Eigen::Index n = jacobian.cols();
  if (jacobian.rows() == 0 || jacobian.nonZeros() == 0) {
    d.nullity = static_cast<int>(n);
    d.method = "none";
    return d;
  }
  if (n <= dense_limit || jacobian.rows() <= 1) {
    const Eigen::VectorXd s = ascending_singular_values(Eigen::MatrixXd(jacobian));
    d.sigma_max = s.size() ? s[s.size() - 1] : 0.0;
    d.tolerance = relative_tolerance * std::max(d.sigma_max, scale_floor);
    // Columns beyond the rows have singular value 0.
    Eigen::VectorXd all = Eigen::VectorXd::Zero(n);
    all.tail(s.size()) = s;
    count(all, n, d);
    d.method = "dense-svd";
    return d;
  }
  d.sigma_max = largest_singular_value(jacobian);
  d.tolerance = relative_tolerance * std::max(d.sigma_max, scale_floor);
  if (d.sigma_max <= d.tolerance) {  // zero to rounding: nothing to iterate on
    d.method = "inverse-subspace";
    d.nullity = static_cast<int>(n);
    d.largest_zero = d.sigma_max;
    return d;
  }
  if (sparse == SparseRankMethod::QrCertified && decide_by_qr(jacobian, d)) return d;
  decide_by_inverse_subspace(jacobian, scale_floor, d);
  return d;
}

void LeastNormSolver::decide_by_inverse_subspace(const Eigen::SparseMatrix<double>& jacobian, double scale_floor,
                                                 RankDecision& d) {
  d.method = "inverse-subspace";
  const Eigen::Index n = jacobian.cols();
  // ε relative to this J's own scale (floored at the caller's), not the solver's floor of 1: the
  // inverse iteration separates singular values only above √ε.
  if (!factor(jacobian, scale_floor * scale_floor)) throw std::runtime_error("decide_rank: factorisation failed");
  NullSpaceVelocity screen;
  count_pivots(screen);
  Eigen::Index block = std::min<Eigen::Index>(n, std::max<Eigen::Index>(n - screen.rank + 4, 6));
  std::mt19937 rng(20101);
  auto random_block = [&](Eigen::Index rows, Eigen::Index cols) {
    Eigen::MatrixXd z(rows, cols);
    for (Eigen::Index c = 0; c < cols; ++c)
      for (Eigen::Index r = 0; r < rows; ++r) z(r, c) = static_cast<double>(rng()) / 4294967296.0 - 0.5;
    return z;
  };
  Eigen::MatrixXd q = orthonormal(random_block(n, block));
  Eigen::VectorXd previous;
  for (int it = 1;; ++it) {
    Eigen::MatrixXd z(n, q.cols());
    for (Eigen::Index c = 0; c < q.cols(); ++c) z.col(c) = ldlt_.solve(q.col(c));
    q = orthonormal(z);
    const Eigen::MatrixXd jq = jacobian * q;
    Eigen::VectorXd s = Eigen::VectorXd::Zero(q.cols());  // fewer rows than the block: the rest are 0
    const Eigen::VectorXd some = ascending_singular_values(jq);
    s.tail(some.size()) = some;
    count(s, n, d);
    if ((d.nullity == q.cols() || d.rank > jacobian.rows()) && q.cols() < n) {
      // Every Ritz value is below the tolerance (the null space may be larger than the block), or
      // fewer are than J's shape forces (n − rows at least): widen the block.
      const Eigen::Index grow = std::min<Eigen::Index>(n, 2 * q.cols()) - q.cols();
      Eigen::MatrixXd wider(n, q.cols() + grow);
      wider << q, random_block(n, grow);
      q = orthonormal(wider);
      previous.resize(0);
      continue;
    }
    // Stop when the Ritz values on both sides of the tolerance have settled.
    if (previous.size() == s.size() && it >= 3) {
      const Eigen::Index k = std::min<Eigen::Index>(d.nullity, s.size() - 1);
      const bool settled = std::abs(s[k] - previous[k]) <= 1e-3 * s[k] &&
                           (d.nullity == 0 || std::abs(s[d.nullity - 1] - previous[d.nullity - 1]) <= 1e-3 * d.tolerance + 1e-3 * s[d.nullity - 1]);
      if (settled || it >= 60) return;
    }
    previous = s;
  }
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
