#include "foldkit/dynamics/mass_properties.hpp"

namespace foldkit::dynamics {

MassProperties mass_properties(const geometry::CreasePattern& pattern, int actor, double density, double scale) {
  MassProperties out;
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();  // ∫ρ x xᵀ dA about the origin
  Eigen::Vector3d first = Eigen::Vector3d::Zero();   // ∫ρ x dA
  const auto& V = pattern.vertices();
  for (const auto& t : pattern.actors()[actor].triangles) {
    Eigen::Vector3d p[3];
    for (int k = 0; k < 3; ++k) p[k] = scale * Eigen::Vector3d(V[t.v[k]].x(), V[t.v[k]].y(), 0.0);
    const double m = density * 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
    const Eigen::Vector3d s = p[0] + p[1] + p[2];
    second += m / 12.0 * (p[0] * p[0].transpose() + p[1] * p[1].transpose() + p[2] * p[2].transpose() + s * s.transpose());
    first += m * s / 3.0;
    out.mass += m;
  }
  if (out.mass > 0.0) out.centroid = first / out.mass;
  const Eigen::Matrix3d central = second - out.mass * out.centroid * out.centroid.transpose();
  out.inertia = central.trace() * Eigen::Matrix3d::Identity() - central;
  return out;
}

}  // namespace foldkit::dynamics
