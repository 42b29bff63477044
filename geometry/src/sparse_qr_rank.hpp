#pragma once
// The rank of a sparse matrix by SuiteSparse QR, with bounds on the singular values on both sides
// of the count (LeastNormSolver::decide_rank's "sparse-qr" method). Private to foldkit::geometry:
// SuiteSparse is linked privately and appears in no public header.
#include <Eigen/SparseCore>

namespace foldkit::geometry::detail {

/// What a Q-less sparse QR with Heath's column threshold says about J's rank.
struct QrRank {
  bool ok = false;             ///< false: the factorisation failed or R is not in the expected form
  int rank = 0;                ///< SPQR's count of live columns
  double dropped = 0.0;        ///< Frobenius norm of the entries dropped as dead, an upper bound on σ_{rank+1}(J)
  double smallest_live = 0.0;  ///< an estimate of σ_min(R₁₁), the live columns' triangle (from above, converged to 1e-2)
};

/// Factors J·E = Q·R by SuiteSparse QR (Q discarded) with column threshold `column_tolerance`
/// and estimates σ_min of R's leading rank × rank triangle by block inverse iteration on R₁₁ᵀR₁₁
/// (two sparse triangular solves per column per iteration). Deterministic.
QrRank sparse_qr_rank(const Eigen::SparseMatrix<double>& jacobian, double column_tolerance);

}  // namespace foldkit::geometry::detail
