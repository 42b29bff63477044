#pragma once
#include <array>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <fcl/geometry/bvh/BVH_model.h>

#include "foldkit/geometry/crease_pattern.hpp"

namespace foldkit::simulation::detail {

// An actor's triangles as one mesh in its own flat frame (z = 0): each pattern vertex once, in the
// order the triangles first use it. Shared by the collision world and the clearance measure.
struct FacetMesh {
  std::vector<Eigen::Vector3d> points;
  std::vector<int> vertices;                  // the pattern vertex of each point
  std::vector<std::array<int, 3>> triangles;  // into points
};

FacetMesh facet_mesh(const geometry::CreasePattern& pattern, int actor);

// The mesh as an FCL model with bounding volumes BV (OBBRSS for collision, RSS for distance).
template <class BV>
std::shared_ptr<fcl::BVHModel<BV>> fcl_model(const FacetMesh& mesh) {
  std::vector<fcl::Vector3d> points(mesh.points.begin(), mesh.points.end());
  std::vector<fcl::Triangle> triangles;
  for (const auto& t : mesh.triangles) triangles.emplace_back(t[0], t[1], t[2]);
  auto model = std::make_shared<fcl::BVHModel<BV>>();
  model->beginModel(static_cast<int>(triangles.size()), static_cast<int>(points.size()));
  model->addSubModel(points, triangles);
  model->endModel();
  return model;
}

}  // namespace foldkit::simulation::detail
