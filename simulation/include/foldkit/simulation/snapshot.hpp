#pragma once
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "foldkit/geometry/crease_pattern.hpp"

namespace foldkit::simulation {

struct SnapshotOptions {
  double azimuth = -0.5235987755982988;  // radians about +z, then
  double elevation = 0.6154797086703873; // radians above the sheet's plane (an isometric view)
  double size = 600.0;                   // pixels, the larger side
  std::vector<int> marked;               // actor indices drawn as colliding
  std::string caption;
};

// An orthographic view of the folded sheet as SVG: triangles drawn back to front, shaded by
// depth (nearer is lighter) and by how squarely they face the viewer, facets in `marked` in red.
std::string snapshot_svg(const geometry::CreasePattern& pattern, const std::vector<Eigen::Isometry3d>& poses,
                         const SnapshotOptions& options = {});

}  // namespace foldkit::simulation
