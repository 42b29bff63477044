#include "foldkit/simulation/corner_motion.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>

#include <Eigen/SVD>

namespace foldkit::simulation {

CornerMotion::CornerMotion(const geometry::CreasePattern& pattern) {
  first_.push_back(0);
  for (const auto& actor : pattern.actors()) {
    std::set<int> seen;
    for (const auto& t : actor.triangles)
      for (int v : t.v)
        if (seen.insert(v).second) corners_.emplace_back(pattern.vertices()[v].x(), pattern.vertices()[v].y(), 0.0);
    first_.push_back(corners_.size());
  }
}

double CornerMotion::largest(const std::vector<Eigen::Isometry3d>& from, const std::vector<Eigen::Isometry3d>& to) const {
  const std::size_t actors = first_.size() - 1;
  if (from.size() != actors || to.size() != actors)
    throw std::invalid_argument("CornerMotion: " + std::to_string(from.size()) + " and " + std::to_string(to.size()) +
                                " poses for " + std::to_string(actors) + " actors");
  // The placed corners, in buffers kept per thread: two allocations of every corner per step were
  // a fifth of this function at Miura 40 × 40.
  thread_local std::vector<Eigen::Vector3d> x, y;
  x.resize(corners_.size());
  y.resize(corners_.size());
  double plain = 0.0;
  for (std::size_t a = 0; a < actors; ++a)
    for (std::size_t i = first_[a]; i < first_[a + 1]; ++i) {
      x[i] = from[a] * corners_[i];
      y[i] = to[a] * corners_[i];
      plain = std::max(plain, (y[i] - x[i]).norm());
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
