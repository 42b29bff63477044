#include "foldkit/simulation/corner_motion.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>

#include <Eigen/SVD>

namespace foldkit::simulation {

CornerMotion::CornerMotion(const geometry::CreasePattern& pattern) {
  for (const auto& actor : pattern.actors()) {
    std::vector<Eigen::Vector3d> corners;
    std::set<int> seen;
    for (const auto& t : actor.triangles)
      for (int v : t.v)
        if (seen.insert(v).second) corners.emplace_back(pattern.vertices()[v].x(), pattern.vertices()[v].y(), 0.0);
    corners_.push_back(std::move(corners));
  }
}

double CornerMotion::largest(const std::vector<Eigen::Isometry3d>& from, const std::vector<Eigen::Isometry3d>& to) const {
  if (from.size() != corners_.size() || to.size() != corners_.size())
    throw std::invalid_argument("CornerMotion: " + std::to_string(from.size()) + " and " + std::to_string(to.size()) +
                                " poses for " + std::to_string(corners_.size()) + " actors");
  std::vector<Eigen::Vector3d> x, y;
  double plain = 0.0;
  for (std::size_t a = 0; a < corners_.size(); ++a)
    for (const auto& p : corners_[a]) {
      x.push_back(from[a] * p);
      y.push_back(to[a] * p);
      plain = std::max(plain, (y.back() - x.back()).norm());
    }
  if (x.size() < 3) return plain;
  // Kabsch: the rotation r and the centroids' offset that best map x onto y in least squares.
  Eigen::Vector3d cx = Eigen::Vector3d::Zero(), cy = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) {
    cx += x[i];
    cy += y[i];
  }
  cx /= static_cast<double>(x.size());
  cy /= static_cast<double>(y.size());
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) h += (x[i] - cx) * (y[i] - cy).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d flip = Eigen::Matrix3d::Identity();
  if ((svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0) flip(2, 2) = -1.0;  // a rotation, not a reflection
  const Eigen::Matrix3d r = svd.matrixV() * flip * svd.matrixU().transpose();
  double aligned = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) aligned = std::max(aligned, (r * (x[i] - cx) + cy - y[i]).norm());
  return std::min(plain, aligned);
}

}  // namespace foldkit::simulation
