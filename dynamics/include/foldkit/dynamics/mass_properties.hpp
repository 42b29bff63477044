#pragma once
/// @file
/// Mass, centre of mass and inertia of a flat actor of uniform areal density, from its triangles.
#include <Eigen/Core>

#include "foldkit/geometry/crease_pattern.hpp"

namespace foldkit::dynamics {

/// The inertial properties of one rigid body, in the flat sheet's frame (z = 0).
struct MassProperties {
  double mass = 0.0;                                   ///< kilograms
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  ///< centre of mass, metres
  /// Inertia tensor about the centre of mass, axes of the flat sheet, kg·m².
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
};

/// Mass properties of actor index `actor` (which must be in range) as a lamina of `density`
/// kilograms per square metre, its lengths multiplied by `scale` (metres per pattern unit).
/// Each triangle's second moment is the closed form A/12·(Σ pᵢpᵢᵀ + s sᵀ), s = Σ pᵢ, summed over
/// the actor and moved to its centre of mass (parallel-axis theorem).
MassProperties mass_properties(const geometry::CreasePattern& pattern, int actor, double density, double scale = 1.0);

}  // namespace foldkit::dynamics
