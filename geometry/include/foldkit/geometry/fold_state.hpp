#pragma once
/// @file
/// A configuration of a crease pattern: one fold angle per joint.
#include <Eigen/Core>

#include "foldkit/geometry/crease_pattern.hpp"

namespace foldkit::geometry {

/// One fold angle per joint (radians, indexed like CreasePattern::joints(); 0 = flat,
/// positive = mountain). Cheap to copy; meaningful only with the pattern it was made for.
struct FoldState {
  Eigen::VectorXd angles;  ///< fold angle of each joint, radians; size = pattern.joints().size()

  /// The flat sheet of `pattern`: every angle 0.
  static FoldState flat(const CreasePattern& pattern) {
    return FoldState{Eigen::VectorXd::Zero(static_cast<Eigen::Index>(pattern.joints().size()))};
  }
};

}  // namespace foldkit::geometry
