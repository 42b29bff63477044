#pragma once
#include <string>

#include "foldkit/geometry/closure.hpp"

namespace foldkit::geometry {

// Instantaneous degrees of freedom at a state: creases − numerical rank of the closure Jacobian.
struct Mobility {
  int dof = 0;
  int rank = 0;
  int creases = 0;
  double tolerance = 0.0;  // absolute: singular values (or R's diagonal) at or below it count as zero
  std::string method;      // "svd" (dense, small systems) or "sparse-qr"
};

// relative_tolerance scales with the largest singular value (SVD) or the largest column norm
// (sparse rank-revealing QR, used above dense_limit creases).
Mobility mobility(const ClosureSystem& system, const FoldState& state, double relative_tolerance = 1e-8,
                  Eigen::Index dense_limit = 800);

}  // namespace foldkit::geometry
