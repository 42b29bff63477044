// Where the tiles and cubes of a folded cube sheet (geometry::generators::cube_sheet: six actors
// per net, in net order) are, shared by the Fig. 5a and Fig. 10 experiments.
#pragma once
#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

#include "foldkit/geometry/crease_pattern.hpp"

namespace foldkit::experiments {

// Centre of each tile's bounding box under `poses` (the tiles are squares), in actor order.
inline std::vector<Eigen::Vector3d> tile_centres(const geometry::CreasePattern& p, const std::vector<Eigen::Isometry3d>& poses) {
  std::vector<Eigen::Vector3d> out;
  for (std::size_t k = 0; k < p.actors().size(); ++k) {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
    for (const auto& tri : p.actors()[k].triangles)
      for (int q : tri.v) {
        const auto& v = p.vertices()[static_cast<std::size_t>(q)];
        const Eigen::Vector3d x = poses[k] * Eigen::Vector3d(v.x(), v.y(), 0);
        lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
      }
    out.push_back((lo + hi) / 2);
  }
  return out;
}

// The mean of each net's six tile centres: the cube's centre once the net is folded shut.
inline std::vector<Eigen::Vector3d> cube_centres(const std::vector<Eigen::Vector3d>& tiles) {
  std::vector<Eigen::Vector3d> out(tiles.size() / 6, Eigen::Vector3d::Zero());
  for (std::size_t k = 0; k < tiles.size(); ++k) out[k / 6] += tiles[k] / 6.0;
  return out;
}

}  // namespace foldkit::experiments
