#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace foldkit::geometry {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

// Mountain/valley label of a crease. Fold angles are signed (positive = mountain), so an
// assignment only matters where a pattern states an intent before any angle is known.
enum class Assignment { Unassigned, Mountain, Valley, Flat };

const char* to_string(Assignment a);

}  // namespace foldkit::geometry
