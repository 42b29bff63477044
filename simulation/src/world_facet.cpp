#include "world_facet.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/narrowphase/collision.h>

#include "facet_mesh.hpp"

namespace foldkit::simulation::detail {

Facet make_facet(const geometry::CreasePattern& pattern, int actor) {
  const FacetMesh mesh = facet_mesh(pattern, actor);
  Facet f;
  f.points = mesh.points;
  f.triangles = mesh.triangles;
  for (const auto& t : mesh.triangles)
    f.flat.push_back({pattern.vertices()[mesh.vertices[t[0]]], pattern.vertices()[mesh.vertices[t[1]]],
                      pattern.vertices()[mesh.vertices[t[2]]]});
  auto model = fcl_model<fcl::OBBRSSd>(mesh);
  model->computeLocalAABB();
  f.object = std::make_unique<FacetObject>(model);
  f.object->setUserData(reinterpret_cast<void*>(static_cast<std::intptr_t>(actor)));
  return f;
}

Side side_of(const Facet& b, const Eigen::Isometry3d& rel, double tol) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& p : b.points) {
    const double z = (rel * p).z();
    lo = std::min(lo, z);
    hi = std::max(hi, z);
  }
  if (lo >= -tol && hi <= tol) return On;
  if (lo >= -tol) return Above;
  if (hi <= tol) return Below;
  return Across;
}

bool overlap_in_plane(const Facet& a, const Facet& b, const Eigen::Isometry3d& rel, double tol) {
  for (const auto& t : b.triangles) {
    geometry::Tri2 shadow;
    for (int k = 0; k < 3; ++k) shadow[k] = (rel * b.points[t[k]]).head<2>();
    for (const auto& s : a.flat)
      if (geometry::triangles_overlap(s, shadow, tol)) return true;
  }
  return false;
}

std::optional<TriangleCrossing> deepest_crossing(const Facet& fa, const Facet& fb, const Eigen::Isometry3d& rel, double tol) {
  const std::size_t most = fa.triangles.size() * fb.triangles.size();
  std::optional<TriangleCrossing> deepest;
  auto judge = [&](std::size_t ta, std::size_t tb) {
    Tri3 x, y;
    for (int k = 0; k < 3; ++k) {
      x[k] = fa.points[fa.triangles[ta][k]];
      y[k] = rel * fb.points[fb.triangles[tb][k]];
    }
    if (auto cut = triangles_cross(x, y, tol); cut && (!deepest || cut->depth > deepest->depth)) deepest = cut;
  };
  if (most <= kDirectTrianglePairs) {
    for (std::size_t ta = 0; ta < fa.triangles.size(); ++ta)
      for (std::size_t tb = 0; tb < fb.triangles.size(); ++tb) judge(ta, tb);
    return deepest;
  }
  fcl::CollisionRequestd request(most, true);
  fcl::CollisionResultd result;
  fcl::collide(fa.object->collisionGeometry().get(), fcl::Transform3d::Identity(), fb.object->collisionGeometry().get(),
               fcl::Transform3d(rel.matrix()), request, result);
  for (std::size_t c = 0; c < result.numContacts(); ++c) {
    const auto& contact = result.getContact(c);
    const bool swapped = contact.o1 != fa.object->collisionGeometry().get();
    judge(static_cast<std::size_t>(swapped ? contact.b2 : contact.b1), static_cast<std::size_t>(swapped ? contact.b1 : contact.b2));
  }
  return deepest;
}

}  // namespace foldkit::simulation::detail
