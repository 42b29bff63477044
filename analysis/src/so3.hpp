#pragma once
#include <cmath>

#include <Eigen/Geometry>

#include "foldkit/geometry/so3.hpp"

// What the spring model needs beyond geometry/so3.hpp: differences of rotated points without
// cancellation, the left Jacobian applied to a vector, and the derivative of J⁻ᵀm.
namespace foldkit::analysis::detail {

using geometry::so3::hat;
using geometry::so3::beta;
inline Eigen::Matrix3d exp_so3(const Eigen::Vector3d& phi) { return geometry::so3::exp(phi); }
inline Eigen::Vector3d log_so3(const Eigen::Matrix3d& r) { return geometry::so3::log(r); }
inline Eigen::Matrix3d inv_left_jacobian(const Eigen::Vector3d& theta) { return geometry::so3::left_jacobian_inverse(theta); }

// (exp(φ) − I)·r without forming exp(φ) − I, whose entries near 1 would cost absolute precision:
// the spring forces are K times differences of such terms.
inline Eigen::Vector3d rotate_minus_identity(const Eigen::Vector3d& phi, const Eigen::Vector3d& r) {
  const double t = phi.norm();
  const double a = t < 1e-4 ? 1.0 - t * t / 6.0 : std::sin(t) / t;
  const double h = std::sin(t / 2.0);
  const double b = t < 1e-4 ? 0.5 - t * t / 24.0 : 2.0 * h * h / (t * t);
  const Eigen::Vector3d pxr = phi.cross(r);
  return a * pxr + b * phi.cross(pxr);
}

// J(φ)·v with J the left Jacobian of SO(3): the displacement of a point that moves with velocity v
// under the screw motion exp of a twist with angular part φ.
inline Eigen::Vector3d left_jacobian_times(const Eigen::Vector3d& phi, const Eigen::Vector3d& v) {
  const double t = phi.norm();
  const double h = std::sin(t / 2.0);
  const double b = t < 1e-4 ? 0.5 - t * t / 24.0 : 2.0 * h * h / (t * t);
  const double c = t < 1e-4 ? 1.0 / 6.0 - t * t / 120.0 : (t - std::sin(t)) / (t * t * t);
  const Eigen::Vector3d pxv = phi.cross(v);
  return v + b * pxv + c * phi.cross(pxv);
}

// β′(t); series below 1e-3 rad like β.
inline double beta_prime(double t) {
  if (t < 1e-3) return t / 360.0 + t * t * t / 7560.0;
  const double s = std::sin(t / 2.0);
  return -2.0 / (t * t * t) + (t / (s * s) + 2.0 / std::tan(t / 2.0)) / (4.0 * t * t);
}

// ∂(J⁻ᵀ(θ)·m)/∂θ, with J⁻ᵀ m = m + ½ θ×m + β θ×(θ×m).
inline Eigen::Matrix3d d_inv_left_jacobian_t(const Eigen::Vector3d& theta, const Eigen::Vector3d& m) {
  const double t = theta.norm();
  const Eigen::Vector3d txm = theta.cross(m);
  Eigen::Matrix3d d = -0.5 * hat(m) - beta(t) * (hat(txm) + hat(theta) * hat(m));
  if (t > 0) d += (beta_prime(t) / t) * theta.cross(txm) * theta.transpose();
  return d;
}

}  // namespace foldkit::analysis::detail
