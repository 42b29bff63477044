#pragma once
/// @file
/// Basic vector types and the mountain/valley assignment of a crease.
#include <Eigen/Core>
#include <Eigen/Geometry>

/// Crease patterns and their rigid-folding kinematics: the pattern model, fold states, the
/// loop-closure equations, projection onto the closure manifold, and parametric generators.
/// Angles are radians; lengths are in the pattern's own units.
namespace foldkit::geometry {

/// A point or direction in the plane of the flat sheet (pattern units).
using Vec2 = Eigen::Vector2d;
/// A point or direction in space (pattern units).
using Vec3 = Eigen::Vector3d;

/// Mountain/valley label of a crease. Fold angles are signed (positive = mountain), so an
/// assignment only matters where a pattern states an intent before any angle is known.
enum class Assignment {
  Unassigned,  ///< no intent stated ("U")
  Mountain,    ///< folds to positive angles ("M")
  Valley,      ///< folds to negative angles ("V")
  Flat         ///< stays flat ("F")
};

/// The one-letter code of an assignment, as written in PMML: "U", "M", "V" or "F".
const char* to_string(Assignment a);

}  // namespace foldkit::geometry
