#pragma once
/// @file
/// Sparse null-space projection and least-norm Gauss–Newton steps for closure Jacobians: used by
/// projected-velocity folding (folding::fold_projected) and by the constrained planning space's
/// projection (statespaces::ClosureConstraint), neither of which may factor a dense Jacobian on
/// patterns with hundreds of creases.
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace foldkit::geometry {

/// A velocity projected onto the null space of a Jacobian J, with the rank estimate of the same
/// factorisation (LeastNormSolver::project_onto_null_space).
struct NullSpaceVelocity {
  Eigen::VectorXd velocity;  ///< the desired velocity's orthogonal projection onto null(J); one entry per column
  int rank = 0;              ///< numerical rank of J (an estimate from LDLᵀ pivots)
  double pivot_ratio = 1.0;  ///< √(smallest / largest kept pivot of JᵀJ): ≈ σ_min / σ_max of J
};

/// A rank decision on J's smallest singular values, with the numbers behind it.
struct RankDecision {
  int rank = 0;               ///< columns − nullity
  int nullity = 0;            ///< columns − rank: the instantaneous degrees of freedom of a closure Jacobian
  double sigma_max = 0.0;     ///< largest singular value of J
  double tolerance = 0.0;     ///< absolute: singular values at or below it count as zero
  double largest_zero = 0.0;  ///< largest singular value counted as zero (0 when none is)
  double smallest_kept = std::numeric_limits<double>::infinity();  ///< smallest counted as non-zero (∞ when none is)
  /// "dense-svd", "sparse-qr", "inverse-subspace", or "none" for a Jacobian without rows or
  /// entries. For "sparse-qr", largest_zero is an upper bound (the norm of what the QR dropped)
  /// and smallest_kept an estimate: σ_min of R's live triangle by inverse iteration (converged
  /// to 1e-2, from above) less that norm, a lower bound on σ_rank once converged
  /// (LeastNormSolver::decide_rank).
  std::string method;
  /// smallest_kept / largest_zero (largest_zero floored at 1e-16·σ_max): how far the decision is
  /// from the tolerance on both sides; a decision with a gap near 1 is a guess.
  double gap() const;
};

/// How LeastNormSolver::decide_rank counts the rank of a Jacobian wider than its dense limit.
enum class SparseRankMethod {
  /// SuiteSparse QR's count, accepted when its bounds are a factor 10 clear of the tolerance on
  /// both sides, else InverseSubspace (the default: 20–40× faster at 10,000+ creases)
  QrCertified,
  /// subspace iteration with (JᵀJ + εI)⁻¹ only: the singular values themselves, at any distance
  /// from the tolerance
  InverseSubspace,
};

/// Least-norm linear algebra on a sparse Jacobian J (rows × creases). Both operations factor
/// JᵀJ + εI, ε = 1e-4 · rank_tolerance · max diag(JᵀJ) (that maximum floored at 1), by a
/// sparse LDLᵀ (AMD ordering) with one step of iterative refinement (the matrix is
/// deliberately ill-conditioned, 1/ε); no dense SVD. The ordering and symbolic analysis are kept
/// between calls and redone only when the Jacobian's sparsity pattern changes — a closure
/// Jacobian keeps its pattern, and the ordering was a fifth of a constrained planner's time when
/// redone each step. Not thread-safe: one solver per thread.
class LeastNormSolver {
 public:
  /// A solver whose pivots below `rank_tolerance` × the largest count as zero (singular values
  /// below √rank_tolerance · σ_max); `rank_tolerance` also scales ε.
  explicit LeastNormSolver(double rank_tolerance = 1e-8) : rank_tolerance_(rank_tolerance) {}

  /// v = ε·(JᵀJ + εI)⁻¹·w, the limit of which as ε → 0 is w's orthogonal projection onto null(J):
  /// components of w along right singular vectors of J with singular value σ are scaled by
  /// ε / (σ² + ε), so the range part vanishes (a corrector removes what is left) and the null part
  /// is kept, with no rank decision. The rank is counted from the pivots of the same
  /// factorisation: every Schur complement of JᵀJ + εI is at least ε, a null direction leaves a
  /// pivot near ε, so pivots below rank_tolerance × the largest count as zero (σ below
  /// √rank_tolerance·σ_max). An estimate: LDLᵀ pivots are not rank revealing, and on random sparse
  /// matrices the count ran 1–3 above the SVD rank (test/geometry/null_space_test.cpp).
  /// @param jacobian  J, rows × n
  /// @param desired   w, size n
  /// @return the projection; `desired` itself (rank 0) when J has no rows or no entries, and a
  ///         zero velocity with rank n and pivot_ratio 0 when the factorisation fails
  NullSpaceVelocity project_onto_null_space(const Eigen::SparseMatrix<double>& jacobian, const Eigen::VectorXd& desired);

  /// The Gauss–Newton step toward the closure manifold of least norm, Δ = −J⁺r, computed as
  /// −(JᵀJ + εI)⁻¹Jᵀr.
  /// @param jacobian  J, rows × n
  /// @param residual  r, size rows
  /// @param step      set to Δ, size n
  /// @param refine    one step of iterative refinement on the solve (the default). Without it,
  ///                  the error is mostly along J's near-null directions, a move along the
  ///                  manifold to first order: enough for a corrector that goes on with chord
  ///                  steps, one triangular-solve pair cheaper.
  /// @return false when the factorisation fails or the step is not finite
  bool min_norm_step(const Eigen::SparseMatrix<double>& jacobian, const Eigen::VectorXd& residual, Eigen::VectorXd& step,
                     bool refine = true);

  /// project_onto_null_space() of the Jacobian last factored (by project_onto_null_space,
  /// min_norm_step or decide_rank), not factoring again: for a caller whose last factorisation
  /// was at a point close enough to the one it needs the projection at (a path follower's
  /// prediction of the state it then corrected to).
  /// @param desired  w, size = the factored Jacobian's columns
  /// @throws std::logic_error when nothing is factored or the size differs
  NullSpaceVelocity project_with_last_factor(const Eigen::VectorXd& desired) const;
  /// A chord step: the least-norm step with the factorisation the last call made, not factoring
  /// again, −(J₀ᵀJ₀ + εI)⁻¹Jᵀr where J₀ is the Jacobian last factored (by project_onto_null_space,
  /// min_norm_step or decide_rank) and `jacobian` should be J₀. Newton's method with its Jacobian
  /// frozen converges linearly near J₀'s point instead of quadratically, for two triangular solves
  /// per iteration instead of a factorisation.
  /// @param jacobian  J₀, rows × n
  /// @param residual  r at the current iterate, size rows
  /// @param step      set to the step, size n
  /// @return false when nothing is factored yet or the step is not finite
  bool chord_step(const Eigen::SparseMatrix<double>& jacobian, const Eigen::VectorXd& residual, Eigen::VectorXd& step) const;
  /// J's numerical rank: singular values above relative_tolerance·max(σ_max, scale_floor) count
  /// (scale_floor: the size of an entry of J that is not rounding, so that a J zero to rounding
  /// has rank 0; 0 leaves the tolerance purely relative); σ_max by power iteration above the
  /// dense limit. Up to dense_limit columns, a dense SVD ("dense-svd"). Above:
  /// - "sparse-qr" (SparseRankMethod::QrCertified): SuiteSparse QR of J with Heath's column
  ///   threshold at tolerance / 10 counts r live columns. The entries it drops bound σ_{r+1}(J)
  ///   from above (Weyl), and σ_min of R's live triangle, estimated by inverse iteration, bounds
  ///   σ_r(J) from below once the dropped norm is subtracted. The count is accepted only when the
  ///   first is at most tolerance / 10 and the second at least 10 × tolerance, so a QR that
  ///   misjudges a near-deficient J (Heath's threshold can) is never taken at its word.
  /// - "inverse-subspace", near the threshold or when asked for: subspace iteration with
  ///   (JᵀJ + εI)⁻¹ through this solver's factorisation, a block that starts at the LDLᵀ
  ///   estimate's nullity + 4 columns and doubles until some of its Ritz values are kept, then
  ///   the SVD of J times that block: its singular values bound J's smallest ones from above and
  ///   converge to them. A block method, not Lanczos, because the decision counts a multiple
  ///   singular value.
  /// Deterministic.
  /// @param jacobian            J, rows × n
  /// @param relative_tolerance  threshold relative to max(σ_max, scale_floor)
  /// @param dense_limit         most columns decided by a dense SVD
  /// @param scale_floor         floor of the scale the tolerance is relative to
  /// @param sparse              how a J wider than dense_limit is decided
  /// @return the decision; rank 0 and method "none" when J has no rows or no entries
  /// @throws std::runtime_error when the sparse factorisation of the subspace iteration fails
  RankDecision decide_rank(const Eigen::SparseMatrix<double>& jacobian, double relative_tolerance = 1e-8,
                           Eigen::Index dense_limit = 400, double scale_floor = 0.0,
                           SparseRankMethod sparse = SparseRankMethod::QrCertified);

  /// How many times the ordering and symbolic analysis were computed (for tests).
  int analyses() const { return analyses_; }

 private:
  // Factors JᵀJ + εI with ε = 1e-4 · rank_tolerance · max(max diag(JᵀJ), eps_floor): the floor
  // of 1 suits closure Jacobians (entries of order 1); decide_rank passes its own scale.
  bool factor(const Eigen::SparseMatrix<double>& jacobian, double eps_floor = 1.0);
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  // The rank estimate and pivot ratio of the last factorisation (project_onto_null_space).
  void count_pivots(NullSpaceVelocity& t) const;
  // decide_rank's inverse subspace iteration, with d.sigma_max and d.tolerance set.
  void decide_by_inverse_subspace(const Eigen::SparseMatrix<double>& jacobian, double scale_floor, RankDecision& d);

  double rank_tolerance_;
  Eigen::SparseMatrix<double> a_;  // JᵀJ + εI
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
  double eps_ = 0.0;
  std::vector<int> outer_, inner_;  // the pattern ldlt_ was analysed for
  int analyses_ = 0;
  bool factored_ = false;  // ldlt_ holds a successful factorisation
};

/// One-off form of LeastNormSolver::project_onto_null_space (a fresh analysis each call).
NullSpaceVelocity project_onto_null_space(const Eigen::SparseMatrix<double>& jacobian, const Eigen::VectorXd& desired,
                                          double rank_tolerance);
/// One-off form of LeastNormSolver::min_norm_step (a fresh analysis each call).
bool min_norm_step(const Eigen::SparseMatrix<double>& jacobian, const Eigen::VectorXd& residual, double rank_tolerance,
                   Eigen::VectorXd& step);

}  // namespace foldkit::geometry
