// CollisionWorld answers only "do facets cross"; the distance is FCL's, between facets that share
// no vertex of the pattern (facets that do share one touch there: their distance is 0 whatever
// the fold).
#include "foldkit/simulation/clearance.hpp"

#include <algorithm>
#include <limits>
#include <memory>

#include <fcl/narrowphase/distance.h>

#include "facet_mesh.hpp"
#include "foldkit/geometry/kinematics.hpp"

namespace foldkit::simulation {

double min_clearance(const geometry::CreasePattern& pattern, const std::vector<geometry::FoldState>& states) {
  using Mesh = fcl::BVHModel<fcl::RSSd>;
  const auto& actors = pattern.actors();
  std::vector<std::shared_ptr<Mesh>> meshes;
  std::vector<std::vector<Eigen::Vector3d>> corners(actors.size());
  std::vector<std::vector<int>> vertices(actors.size());
  for (std::size_t a = 0; a < actors.size(); ++a) {
    const detail::FacetMesh mesh = detail::facet_mesh(pattern, static_cast<int>(a));
    corners[a] = mesh.points;
    vertices[a] = mesh.vertices;
    std::sort(vertices[a].begin(), vertices[a].end());
    meshes.push_back(detail::fcl_model<fcl::RSSd>(mesh));
  }
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t a = 0; a < actors.size(); ++a)
    for (std::size_t b = a + 1; b < actors.size(); ++b) {
      std::vector<int> common;
      std::set_intersection(vertices[a].begin(), vertices[a].end(), vertices[b].begin(), vertices[b].end(),
                            std::back_inserter(common));
      if (common.empty()) pairs.emplace_back(a, b);
    }
  double best = std::numeric_limits<double>::infinity();
  if (pairs.empty()) return best;
  const geometry::KinematicTree tree = geometry::make_tree(pattern);
  fcl::DistanceRequestd request;
  for (const auto& state : states) {
    const auto poses = geometry::facet_poses(pattern, tree, state);
    std::vector<Eigen::AlignedBox3d> boxes(actors.size());
    for (std::size_t a = 0; a < actors.size(); ++a)
      for (const auto& c : corners[a]) boxes[a].extend(poses[a] * c);
    // Nearest boxes first: once a small distance is known, most pairs are ruled out by their boxes.
    std::vector<std::pair<double, std::size_t>> order;
    for (std::size_t i = 0; i < pairs.size(); ++i)
      order.emplace_back(std::sqrt(boxes[pairs[i].first].squaredExteriorDistance(boxes[pairs[i].second])), i);
    std::sort(order.begin(), order.end());
    for (const auto& [lower, i] : order) {
      if (lower >= best) break;
      const auto [a, b] = pairs[i];
      fcl::DistanceResultd result;
      fcl::distance(meshes[a].get(), poses[a], meshes[b].get(),
                    poses[b], request, result);
      best = std::min(best, std::max(0.0, result.min_distance));
    }
  }
  return best;
}

}  // namespace foldkit::simulation
