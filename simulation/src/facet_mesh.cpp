#include "facet_mesh.hpp"

#include <unordered_map>

namespace foldkit::simulation::detail {

FacetMesh facet_mesh(const geometry::CreasePattern& pattern, int actor) {
  FacetMesh m;
  std::unordered_map<int, int> local;
  for (const auto& t : pattern.actors()[actor].triangles) {
    std::array<int, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      const auto [it, fresh] = local.emplace(t.v[k], static_cast<int>(m.points.size()));
      if (fresh) {
        const geometry::Vec2& v = pattern.vertices()[t.v[k]];
        m.points.emplace_back(v.x(), v.y(), 0.0);
        m.vertices.push_back(t.v[k]);
      }
      tri[k] = it->second;
    }
    m.triangles.push_back(tri);
  }
  return m;
}

}  // namespace foldkit::simulation::detail
