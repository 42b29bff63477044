#pragma once
/// @file
/// Pictures of a folded sheet as SVG.
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "foldkit/geometry/crease_pattern.hpp"

namespace foldkit::simulation {

/// Viewpoint, size and marks of snapshot_svg(). The default view is isometric.
struct SnapshotOptions {
  double azimuth = -0.5235987755982988;  ///< radians about +z, applied first
  double elevation = 0.6154797086703873; ///< radians above the sheet's plane, applied second
  double size = 600.0;                   ///< pixels, the larger side of the drawing
  std::vector<int> marked;               ///< actor indices drawn as colliding (in red)
  std::string caption;                   ///< text under the drawing; none when empty
};

/// An orthographic view of the folded sheet as SVG: triangles drawn back to front, shaded by
/// depth (nearer is lighter) and by how squarely they face the viewer, facets in `marked` in red.
/// @param pattern  the pattern
/// @param poses    rigid motion of each actor from the flat sheet (geometry::facet_poses)
/// @param options  view and marks
/// @throws std::invalid_argument when `poses` does not hold one pose per actor
std::string snapshot_svg(const geometry::CreasePattern& pattern, const std::vector<Eigen::Isometry3d>& poses,
                         const SnapshotOptions& options = {});

}  // namespace foldkit::simulation
