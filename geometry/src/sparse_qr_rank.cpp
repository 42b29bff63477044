#include "sparse_qr_rank.hpp"

#include <algorithm>
#include <cmath>
#include <vector>
#include <random>

#include <Eigen/Dense>
#include <SuiteSparseQR.hpp>

namespace foldkit::geometry::detail {

namespace {

using LongSparse = Eigen::SparseMatrix<double, Eigen::ColMajor, SuiteSparse_long>;

// cholmod_common with its start and finish, so that no early return leaks it.
struct Cholmod {
  cholmod_common cc;
  Cholmod() {
    cholmod_l_start(&cc);
    // One thread: `dof` and the folders decide one rank at a time, and TBB/OpenMP threads would
    // compete with the planners' own.
    cc.SPQR_nthreads = 1;
  }
  ~Cholmod() { cholmod_l_finish(&cc); }
  Cholmod(const Cholmod&) = delete;
  Cholmod& operator=(const Cholmod&) = delete;
};

// J as a CHOLMOD matrix viewing `storage` (long indices, as the cholmod_l_ interface SPQR uses needs).
cholmod_sparse view(LongSparse& storage) {
  storage.makeCompressed();
  cholmod_sparse a{};
  a.nrow = static_cast<std::size_t>(storage.rows());
  a.ncol = static_cast<std::size_t>(storage.cols());
  a.nzmax = static_cast<std::size_t>(storage.nonZeros());
  a.p = storage.outerIndexPtr();
  a.i = storage.innerIndexPtr();
  a.x = storage.valuePtr();
  a.stype = 0;
  a.itype = CHOLMOD_LONG;
  a.xtype = CHOLMOD_REAL;
  a.dtype = CHOLMOD_DOUBLE;
  a.sorted = 1;
  a.packed = 1;
  return a;
}

// R's leading rank × rank block, checked to be upper triangular with a non-zero diagonal (what
// SPQR returns when the dead columns are permuted last); empty when it is not.
Eigen::SparseMatrix<double> leading_triangle(const cholmod_sparse& r, int rank) {
  const auto* p = static_cast<const SuiteSparse_long*>(r.p);
  const auto* i = static_cast<const SuiteSparse_long*>(r.i);
  const auto* x = static_cast<const double*>(r.x);
  std::vector<Eigen::Triplet<double>> entries;
  for (int c = 0; c < rank; ++c) {
    bool diagonal = false;
    for (SuiteSparse_long k = p[c]; k < p[c + 1]; ++k) {
      if (i[k] > c) return {};
      if (x[k] == 0.0) continue;
      diagonal |= i[k] == c;
      entries.emplace_back(static_cast<int>(i[k]), c, x[k]);
    }
    if (!diagonal) return {};
  }
  Eigen::SparseMatrix<double> t(rank, rank);
  t.setFromTriplets(entries.begin(), entries.end());
  return t;
}

// σ_min of an upper-triangular T by block inverse iteration on (TᵀT)⁻¹, a block of 4 (a cluster
// of small singular values converges as fast as a single one), to 1e-2 relative: the decision
// only needs its magnitude, which is compared with the tolerance with a margin of 10. The Ritz value σ_min(T·Q)
// is never below σ_min(T), so the estimate errs on the side of a larger σ until it settles.
double smallest_singular_value(const Eigen::SparseMatrix<double>& t) {
  const Eigen::Index n = t.cols(), k = std::min<Eigen::Index>(4, n);
  std::mt19937 rng(20101);
  Eigen::MatrixXd q(n, k);
  for (Eigen::Index c = 0; c < k; ++c)
    for (Eigen::Index r = 0; r < n; ++r) q(r, c) = static_cast<double>(rng()) / 4294967296.0 - 0.5;
  const auto upper = t.triangularView<Eigen::Upper>();
  double previous = -1.0, sigma = 0.0;
  for (int it = 0; it < 40; ++it) {
    Eigen::HouseholderQR<Eigen::MatrixXd> qr(q);
    q = qr.householderQ() * Eigen::MatrixXd::Identity(n, k);
    const Eigen::MatrixXd tq = t * q;
    sigma = Eigen::JacobiSVD<Eigen::MatrixXd>(tq).singularValues().minCoeff();
    // At least three iterations: a first step that barely moves the Ritz value has not converged.
    if (it >= 3 && std::abs(sigma - previous) <= 1e-2 * sigma) break;
    previous = sigma;
    Eigen::MatrixXd y = upper.transpose().solve(q);  // Tᵀy = q
    q = upper.solve(y);                              // T z = y: z = (TᵀT)⁻¹q
    if (!q.allFinite()) return 0.0;
  }
  return sigma;
}

}  // namespace

QrRank sparse_qr_rank(const Eigen::SparseMatrix<double>& jacobian, double column_tolerance) {
  QrRank out;
  LongSparse storage(jacobian);
  cholmod_sparse a = view(storage);
  Cholmod cholmod;
  cholmod_sparse* r = nullptr;
  SuiteSparse_long* e = nullptr;
  // econ 0: R has as many rows as the rank; Q is not formed.
  const SuiteSparse_long rank =
      SuiteSparseQR<double>(SPQR_ORDERING_DEFAULT, column_tolerance, 0, &a, &r, &e, &cholmod.cc);
  if (e != nullptr) cholmod_l_free(a.ncol, sizeof(SuiteSparse_long), e, &cholmod.cc);  // the count needs no E
  if (r == nullptr || rank < 0) return out;
  out.rank = static_cast<int>(rank);
  out.dropped = cholmod.cc.SPQR_norm_E_fro;
  const Eigen::SparseMatrix<double> triangle = leading_triangle(*r, out.rank);
  cholmod_l_free_sparse(&r, &cholmod.cc);
  if (out.rank > 0 && triangle.cols() != out.rank) return out;
  out.smallest_live = out.rank > 0 ? smallest_singular_value(triangle) : 0.0;
  out.ok = std::isfinite(out.dropped) && std::isfinite(out.smallest_live);
  return out;
}

}  // namespace foldkit::geometry::detail
