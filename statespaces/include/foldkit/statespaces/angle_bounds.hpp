#pragma once
/// @file
/// Per-joint angle bounds, which every state space samples within and the validity checks use.
#include <Eigen/Core>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"

namespace foldkit::statespaces {

/// Per-joint angle bounds (radians): [−π, π], narrowed to [0, π] for a mountain and [−π, 0] for a
/// valley when `use_assignment` and the pattern assigns the crease.
struct AngleBounds {
  Eigen::VectorXd lower,  ///< lower bound of each joint, radians
      upper;              ///< upper bound of each joint, radians
  /// The bounds of `pattern`'s joints, narrowed by their assignments when `use_assignment`.
  static AngleBounds of(const geometry::CreasePattern& pattern, bool use_assignment);
  /// Whether `state` has one angle per joint, each within its bounds widened by `slack` (radians).
  bool contains(const geometry::FoldState& state, double slack = 1e-12) const;
};

}  // namespace foldkit::statespaces
