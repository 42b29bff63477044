#pragma once
#include <cmath>

#include <Eigen/Geometry>

namespace foldkit::geometry::detail {

using Mat3 = Eigen::Matrix3d;
using V3 = Eigen::Vector3d;

inline Mat3 hat(const V3& w) {
  Mat3 m;
  m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return m;
}

inline Mat3 rotation(const V3& unit_axis, double angle) { return Eigen::AngleAxisd(angle, unit_axis).toRotationMatrix(); }

// Rotation vector of R (angle in [0, π] times axis); Eigen's quaternion route stays accurate
// near the identity, where closure residuals live.
inline V3 log_so3(const Mat3& R) {
  const Eigen::AngleAxisd aa(R);
  return aa.angle() * aa.axis();
}

// Rotation vector of a unit quaternion, on the short way round (angle in [0, π]).
inline V3 log_quaternion(const Eigen::Quaterniond& q) {
  const double sign = q.w() < 0 ? -1.0 : 1.0;
  const V3 v = sign * q.vec();
  const double s = v.norm(), w = sign * q.w();
  if (s < 1e-8) return (2.0 / w) * (1.0 - s * s / (3.0 * w * w)) * v;  // atan series: exact to rounding here
  return (2.0 * std::atan2(s, w) / s) * v;
}

// Inverse of the left Jacobian of SO(3): d log(R) = J_l⁻¹(φ) δ for R ← exp(δ) R.
inline Mat3 left_jacobian_inverse(const V3& phi) {
  const double t = phi.norm();
  const Mat3 P = hat(phi);
  // 1/t² − (1 + cos t)/(2 t sin t), by its series below 1e-4 where the closed form cancels.
  const double c = t < 1e-4 ? 1.0 / 12.0 + t * t / 720.0
                   : t > M_PI - 1e-9 ? 1.0 / (t * t)
                                     : 1.0 / (t * t) - (1.0 + std::cos(t)) / (2.0 * t * std::sin(t));
  return Mat3::Identity() - 0.5 * P + c * P * P;
}

}  // namespace foldkit::geometry::detail
