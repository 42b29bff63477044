#include "foldkit/statespaces/single_vertex_chain.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

namespace foldkit::statespaces {

namespace {

Eigen::Matrix3d rot(const Eigen::Vector3d& axis, double angle) { return Eigen::AngleAxisd(angle, axis).toRotationMatrix(); }

}  // namespace

SingleVertexChain::SingleVertexChain(const geometry::CreasePattern& pattern, std::size_t vertex) : pattern_(&pattern) {
  const auto& stars = pattern.interior_vertices();
  if (vertex >= stars.size())
    throw std::invalid_argument("single-vertex space: the pattern has no interior vertex " + std::to_string(vertex));
  if (stars.size() != 1)
    throw std::invalid_argument("single-vertex space: the pattern has " + std::to_string(stars.size()) +
                                " interior vertices (use a constrained space)");
  const geometry::VertexStar& star = stars[vertex];
  const std::size_t n = star.joints.size();
  if (n < 4) throw std::invalid_argument("single-vertex space: a vertex of degree " + std::to_string(n) + " is rigid");
  joints_ = star.joints;
  for (double d : star.directions) axes_.emplace_back(std::cos(d), std::sin(d), 0.0);

  // The passive triple: consecutive creases whose sectors α, β are far from 0 and π (the root
  // interval of C has length 2 sin α sin β) and whose outer axes are far from parallel
  // (sin(α + β): at the flat state R(u₂, 0)u₃ = u₃ must not lie along u₁). With α = β the outer
  // axes line up at b = ±π (R(u₂, π)u₃ = u₁: a and c are then undetermined, e.g. the flap of the
  // corner cube folded shut), so a triple with unequal sectors is preferred. (Only exact ties:
  // near-equal sectors are merely ill-conditioned near b = ±π, and the choice stays as it was.)
  double best = -1.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double alpha = star.sectors[k], beta = star.sectors[(k + 1) % n];
    const double lock = std::abs(alpha - beta) < 1e-9 ? 0.5 : 1.0;
    const double score = lock * std::abs(std::sin(alpha)) * std::abs(std::sin(beta)) * std::abs(std::sin(alpha + beta));
    if (score > best + 1e-12) {
      best = score;
      first_passive_ = k;
    }
  }
  for (std::size_t i = 0; i < 3; ++i) {
    passive_[i] = joints_[(first_passive_ + i) % n];
    u_[i] = axes_[(first_passive_ + i) % n];
  }
  for (std::size_t i = 3; i < n; ++i) {
    active_.push_back(joints_[(first_passive_ + i) % n]);
    active_axes_.push_back(axes_[(first_passive_ + i) % n]);
  }
  K_ = u_[0].dot(u_[1]) * u_[1].dot(u_[2]);
  A_ = u_[0].dot(u_[2]) - K_;
}

Eigen::Matrix3d SingleVertexChain::active_product(const geometry::FoldState& state) const {
  Eigen::Matrix3d m = Eigen::Matrix3d::Identity();
  for (std::size_t i = 0; i < active_.size(); ++i) m = m * rot(active_axes_[i], -state.angles[active_[i]]);
  return m;
}

double SingleVertexChain::cos_middle(const geometry::FoldState& state) const {
  if (std::abs(A_) < 1e-12) return 2.0;
  const Eigen::Matrix3d q = active_product(state).transpose();
  return (u_[0].dot(q * u_[2]) - K_) / A_;
}

bool SingleVertexChain::solve(geometry::FoldState& state, int branch) const {
  if (std::abs(A_) < 1e-12) return false;
  const Eigen::Matrix3d q = active_product(state).transpose();
  const double cb = (u_[0].dot(q * u_[2]) - K_) / A_;
  if (!(std::abs(cb) <= 1.0 + 1e-12)) return false;
  // φ of the middle crease is b; its fold angle −b has the sign of the branch.
  const double b = -(branch >= 0 ? 1.0 : -1.0) * std::acos(std::clamp(cb, -1.0, 1.0));
  const Eigen::Vector3d v = rot(u_[1], b) * u_[2];
  const Eigen::Vector3d w = q * u_[2];
  const Eigen::Vector3d vp = v - u_[0].dot(v) * u_[0];
  const Eigen::Vector3d wp = w - u_[0].dot(w) * u_[0];
  if (vp.norm() < 1e-9 || wp.norm() < 1e-9) return false;  // a is undetermined: a singular state
  const double a = std::atan2(u_[0].dot(vp.cross(wp)), vp.dot(wp));
  const Eigen::Matrix3d s = (rot(u_[0], a) * rot(u_[1], b)).transpose() * q;
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();  // perpendicular to every crease axis
  const Eigen::Vector3d sz = s * z;
  const double c = std::atan2(u_[2].dot(z.cross(sz)), z.dot(sz));
  // Guard against the remaining ill-conditioned cases: the triple must reproduce Q.
  if ((rot(u_[0], a) * rot(u_[1], b) * rot(u_[2], c) - q).cwiseAbs().maxCoeff() > 1e-9) return false;
  state.angles[passive_[0]] = -a;
  state.angles[passive_[1]] = -b;
  state.angles[passive_[2]] = -c;
  return true;
}

int SingleVertexChain::branch_of(const geometry::FoldState& state) const { return state.angles[passive_[1]] < 0.0 ? -1 : 1; }

double SingleVertexChain::meeting_distance(const geometry::FoldState& state) const { return std::abs(state.angles[passive_[1]]); }

}  // namespace foldkit::statespaces
