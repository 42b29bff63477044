#pragma once
/// @file
/// Rotation-vector calculus on SO(3).
#include <cmath>

#include <Eigen/Geometry>

/// Rotation-vector calculus on SO(3), shared by the closure equations (geometry) and the spring
/// model (analysis). A rotation vector φ is the unit axis times the angle in radians.
namespace foldkit::geometry::so3 {

/// A 3×3 matrix (a rotation, or a skew-symmetric generator).
using Mat3 = Eigen::Matrix3d;
/// A 3-vector (a rotation vector or an axis).
using V3 = Eigen::Vector3d;

/// The skew-symmetric matrix [w]× with [w]× v = w × v.
inline Mat3 hat(const V3& w) {
  Mat3 m;
  m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return m;
}

/// The rotation by `angle` (radians, right-hand rule) about `unit_axis`, which must have norm 1.
inline Mat3 rotation(const V3& unit_axis, double angle) { return Eigen::AngleAxisd(angle, unit_axis).toRotationMatrix(); }

/// exp of a rotation vector: the rotation by |φ| radians about φ / |φ| (the identity for φ ≈ 0).
inline Mat3 exp(const V3& phi) {
  const double angle = phi.norm();
  if (angle < 1e-300) return Mat3::Identity();
  return rotation(phi / angle, angle);
}

/// Rotation vector of R (angle in [0, π] times axis); Eigen's quaternion route stays accurate
/// near the identity, where closure residuals live.
inline V3 log(const Mat3& R) {
  const Eigen::AngleAxisd aa(R);
  return aa.angle() * aa.axis();
}

/// Rotation vector of a unit quaternion, on the short way round (angle in [0, π]); accurate to
/// rounding near the identity (series below a half-angle sine of 1e-8).
inline V3 log_quaternion(const Eigen::Quaterniond& q) {
  const double sign = q.w() < 0 ? -1.0 : 1.0;
  const V3 v = sign * q.vec();
  const double s = v.norm(), w = sign * q.w();
  if (s < 1e-8) return (2.0 / w) * (1.0 - s * s / (3.0 * w * w)) * v;  // atan series: exact to rounding here
  return (2.0 * std::atan2(s, w) / s) * v;
}

/// β(t) = 1/t² − (1 + cos t)/(2 t sin t) of the inverse left Jacobian, t ≥ 0 in radians; its
/// series below 1e-3 rad, where the closed form loses digits by cancellation (the series' error
/// there is 3e-17), and 1/t² within 1e-9 of π.
inline double beta(double t) {
  if (t < 1e-3) return 1.0 / 12.0 + t * t / 720.0;
  if (t > M_PI - 1e-9) return 1.0 / (t * t);
  return 1.0 / (t * t) - (1.0 + std::cos(t)) / (2.0 * t * std::sin(t));
}

/// Inverse of the left Jacobian of SO(3): d log(R) = J_l⁻¹(φ) δ for R ← exp(δ) R;
/// J_l⁻¹ = I − ½[φ]× + β(|φ|)[φ]×².
inline Mat3 left_jacobian_inverse(const V3& phi) {
  const Mat3 P = hat(phi);
  return Mat3::Identity() - 0.5 * P + beta(phi.norm()) * P * P;
}

}  // namespace foldkit::geometry::so3
