#pragma once
/// @file
/// Instantaneous degrees of freedom of a folded state.
#include <string>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/null_space.hpp"

namespace foldkit::geometry {

/// Instantaneous degrees of freedom at a state: creases − numerical rank of the closure Jacobian.
struct Mobility {
  int dof = 0;             ///< creases − rank
  int rank = 0;            ///< numerical rank of the closure Jacobian
  int creases = 0;         ///< number of joints (columns of the Jacobian)
  double tolerance = 0.0;  ///< absolute: singular values at or below it count as zero
  std::string method;      ///< "dense-svd", "sparse-qr", "inverse-subspace" (LeastNormSolver::decide_rank) or "none" (no loop)
  RankDecision decision;   ///< the singular values behind the count, with their gap
};

/// The default relative tolerance of mobility(), which `foldkit dof` and Python's `dof` take too.
inline constexpr double kMobilityTolerance = 1e-8;

/// The mobility of `system` at `state`. The rank is decided by singular values
/// (LeastNormSolver::decide_rank): singular values above relative_tolerance · max(σ_max, 1)
/// count (σ_max is floored at 1, the size of a closure Jacobian's entries, so that a Jacobian
/// zero to rounding has rank 0); a dense SVD up to `dense_limit` creases; above, SuiteSparse QR's
/// count where its bounds are clear of the tolerance, else inverse subspace iteration on the
/// sparse Jacobian.
/// @param system              the closure equations of the pattern
/// @param state               one angle per joint, radians
/// @param relative_tolerance  relative threshold on the singular values
/// @param dense_limit         largest number of creases decided by a dense SVD
/// @throws std::runtime_error when the sparse factorisation of the subspace iteration fails
Mobility mobility(const ClosureSystem& system, const FoldState& state, double relative_tolerance = kMobilityTolerance,
                  Eigen::Index dense_limit = 400);

}  // namespace foldkit::geometry
