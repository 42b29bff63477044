#pragma once
#include <string>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/null_space.hpp"

namespace foldkit::geometry {

// Instantaneous degrees of freedom at a state: creases − numerical rank of the closure Jacobian.
struct Mobility {
  int dof = 0;
  int rank = 0;
  int creases = 0;
  double tolerance = 0.0;  // absolute: singular values at or below it count as zero
  std::string method;      // "dense-svd", "inverse-subspace" (LeastNormSolver::decide_rank) or "none" (no loop)
  RankDecision decision;   // the singular values behind the count, with their gap
};

// The rank is decided by singular values (LeastNormSolver::decide_rank): relative_tolerance scales
// with the largest singular value, floored at 1; a dense SVD up to dense_limit creases, inverse subspace
// iteration on the sparse Jacobian above.
Mobility mobility(const ClosureSystem& system, const FoldState& state, double relative_tolerance = 1e-8,
                  Eigen::Index dense_limit = 400);

}  // namespace foldkit::geometry
