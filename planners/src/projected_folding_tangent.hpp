#pragma once
// The null-space projection of projected-velocity folding, kept apart so that it can be read
// (and benchmarked) on its own.
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace foldkit::planners::detail {

struct Tangent {
  Eigen::VectorXd velocity;  // the desired velocity's orthogonal projection onto null(J)
  int rank = 0;              // numerical rank of J
  double pivot_ratio = 1.0;  // √(smallest / largest kept pivot of JᵀJ): ≈ σ_min / σ_max of J
};

// v = ε·(JᵀJ + εI)⁻¹·w, the limit of which as ε → 0 is w's orthogonal projection onto null(J):
// components of w along right singular vectors of J with singular value σ are scaled by
// ε / (σ² + ε), so with ε = 1e-4 · rank_tolerance · max diag(JᵀJ) the range part vanishes (the
// corrector removes what is left) and the null part is kept. One sparse LDLᵀ (AMD ordering) of an
// n × n matrix with the Jacobian's sparsity squared, one step of iterative refinement; no dense SVD,
// no rank decision needed for the velocity. The rank is counted from the pivots of the same
// factorisation: every Schur complement of JᵀJ + εI is at least ε, a null direction leaves a pivot
// near ε, so pivots below rank_tolerance × the largest count as zero (σ below √rank_tolerance·σ_max).
Tangent project_onto_null_space(const Eigen::SparseMatrix<double>& jacobian, const Eigen::VectorXd& desired,
                                double rank_tolerance);

// The Gauss–Newton step toward the closure manifold of least norm, Δ = −J⁺r, computed as
// −(JᵀJ + εI)⁻¹Jᵀr with the same ε and factorisation as above. False when the factorisation fails.
bool min_norm_step(const Eigen::SparseMatrix<double>& jacobian, const Eigen::VectorXd& residual, double rank_tolerance,
                   Eigen::VectorXd& step);

}  // namespace foldkit::planners::detail
