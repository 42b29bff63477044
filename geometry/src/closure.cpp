#include "foldkit/geometry/closure.hpp"

#include <algorithm>
#include <array>

#include <boost/graph/connected_components.hpp>

#include "foldkit/geometry/so3.hpp"

namespace foldkit::geometry {
namespace {

using so3::Mat3;
using so3::V3;

// A joint's motion in the world: unit axis ω and a point q on it, for the actor on `side`.
struct Twist {
  V3 w, v;  // v = q × ω
};

Twist joint_twist(const CreasePattern& p, int joint, double side, const Eigen::Isometry3d& parent) {
  const JointAxis axis = joint_axis(p, joint);
  const V3 w = parent.linear() * (side * axis.direction);
  const V3 q = parent * axis.point;
  return {w, q.cross(w)};
}

}  // namespace

int hole_count(const CreasePattern& pattern) {
  std::size_t triangles = 0;
  for (const Actor& a : pattern.actors()) triangles += a.triangles.size();
  const long edges = static_cast<long>((3 * triangles + pattern.boundary_edges().size()) / 2);
  const long euler = static_cast<long>(pattern.vertices().size()) - edges + static_cast<long>(triangles);
  std::vector<int> component(pattern.actors().size());
  const long components = pattern.actors().empty() ? 0 : boost::connected_components(pattern.facet_graph(), component.data());
  return static_cast<int>(std::max(0L, components - euler));
}

ClosureSystem::ClosureSystem(const CreasePattern& pattern, int root) : pattern_(&pattern), tree_(make_tree(pattern, root)) {
  for (const VertexStar& star : pattern.interior_vertices()) {
    if (star.joints.empty()) continue;
    VertexLoop loop{star.vertex, star.joints, {}};
    for (double angle : star.directions) loop.axes.emplace_back(std::cos(angle), std::sin(angle), 0.0);
    loops_.push_back(std::move(loop));
  }
  size_ = std::max(pattern.diagonal(), 1e-300);
  // Around a hole no vertex loop closes the chain of facets: add every fundamental cycle.
  if (hole_count(pattern) > 0) {
    for (std::size_t j = 0; j < pattern.joints().size(); ++j) {
      if (tree_.in_tree[j]) continue;
      const auto& actors = pattern.joints()[j].actors;
      cycles_.push_back({static_cast<int>(j), actors[0], actors[1], side_of(pattern, static_cast<int>(j), actors[1])});
    }
  }
  rows_ = static_cast<Eigen::Index>(3 * loops_.size() + 6 * cycles_.size());

  // Lay out the Jacobian once, at the flat state (the structure does not depend on the state).
  std::vector<Eigen::Triplet<double>> entries;
  Sink collect{&entries};
  Eigen::VectorXd r(rows_);
  evaluate_into(FoldState::flat(pattern), r, &collect);
  layout_.resize(rows_, cols());
  std::vector<Eigen::Triplet<double>> ones;
  ones.reserve(entries.size());
  for (const auto& t : entries) ones.emplace_back(t.row(), t.col(), 1.0);
  layout_.setFromTriplets(ones.begin(), ones.end());
  layout_.makeCompressed();
  slots_.reserve(entries.size());
  for (const auto& t : entries) {
    const int* begin = layout_.innerIndexPtr() + layout_.outerIndexPtr()[t.col()];
    const int* end = layout_.innerIndexPtr() + layout_.outerIndexPtr()[t.col() + 1];
    slots_.push_back(static_cast<int>(std::lower_bound(begin, end, static_cast<int>(t.row())) - layout_.innerIndexPtr()));
  }
}

void ClosureSystem::evaluate_vertex(const VertexLoop& loop, const FoldState& state, Eigen::Index row, Eigen::VectorXd& r,
                                    Sink* jac) const {
  // Crossing crease k counter-clockwise enters the facet on its left, which turns by −angle.
  // Quaternions: the product of n rotations is the whole cost of a residual.
  const std::size_t n = loop.joints.size();
  constexpr std::size_t kOnStack = 32;
  std::array<V3, kOnStack> on_stack;
  std::vector<V3> on_heap;
  V3* current_axes = nullptr;
  if (jac) current_axes = n <= kOnStack ? on_stack.data() : (on_heap.resize(n), on_heap.data());
  Eigen::Quaterniond A = Eigen::Quaterniond::Identity();
  for (std::size_t k = 0; k < n; ++k) {
    if (jac) current_axes[k] = A * loop.axes[k];
    const double half = -0.5 * state.angles[loop.joints[k]];
    const double c = std::cos(half), s = std::sin(half);
    A = A * Eigen::Quaterniond(c, s * loop.axes[k].x(), s * loop.axes[k].y(), s * loop.axes[k].z());
  }
  const V3 phi = so3::log_quaternion(A);
  r.segment<3>(row) = phi;
  if (!jac) return;
  // ∂A/∂ρ_k · A⁻¹ = −[P_k d_k]×, with P_k the product before crease k (Eq. 3).
  const Mat3 Jinv = so3::left_jacobian_inverse(phi);
  for (std::size_t k = 0; k < n; ++k) {
    const V3 column = -(Jinv * current_axes[k]);
    for (int i = 0; i < 3; ++i) jac->add(row + i, loop.joints[k], column[i]);
  }
}

void ClosureSystem::evaluate_cycles(const FoldState& state, Eigen::VectorXd& r, Sink* jac) const {
  if (cycles_.empty()) return;
  const CreasePattern& p = *pattern_;
  const std::vector<Eigen::Isometry3d> pose = facet_poses(p, tree_, state);
  Eigen::Index row = static_cast<Eigen::Index>(3 * loops_.size());
  for (const HoleCycle& c : cycles_) {
    // W = T_from · G · T_to⁻¹ is the identity when the two ways round agree.
    const Eigen::Isometry3d G = joint_motion(joint_axis(p, c.joint), c.side * state.angles[c.joint]);
    const Eigen::Isometry3d W = pose[c.from] * G * pose[c.to].inverse();
    const V3 phi = so3::log(W.linear());
    r.segment<3>(row) = phi;
    r.segment<3>(row + 3) = W.translation() / size_;
    if (jac) {
      const Mat3 Jinv = so3::left_jacobian_inverse(phi);
      const V3 t = W.translation();
      // dW·W⁻¹ = Σ ξ (joints above `from`, and the cycle's joint) − Σ Ad_W ξ (joints above `to`).
      auto add = [&](int joint, const Twist& xi, double sign) {
        const V3 w = sign * xi.w, v = sign * xi.v;
        const V3 rot = Jinv * w, trans = (v + w.cross(t)) / size_;
        for (int i = 0; i < 3; ++i) {
          jac->add(row + i, joint, rot[i]);
          jac->add(row + 3 + i, joint, trans[i]);
        }
      };
      add(c.joint, joint_twist(p, c.joint, c.side, pose[c.from]), 1.0);
      for (int x = c.from; tree_.parent[x] >= 0; x = tree_.parent[x])
        add(tree_.parent_joint[x], joint_twist(p, tree_.parent_joint[x], tree_.side[x], pose[tree_.parent[x]]), 1.0);
      for (int x = c.to; tree_.parent[x] >= 0; x = tree_.parent[x]) {
        const Twist xi = joint_twist(p, tree_.parent_joint[x], tree_.side[x], pose[tree_.parent[x]]);
        const V3 w = W.linear() * xi.w;
        add(tree_.parent_joint[x], {w, W.linear() * xi.v + t.cross(w)}, -1.0);
      }
    }
    row += 6;
  }
}

void ClosureSystem::evaluate_into(const FoldState& state, Eigen::VectorXd& r, Sink* jac) const {
  for (std::size_t i = 0; i < loops_.size(); ++i) evaluate_vertex(loops_[i], state, static_cast<Eigen::Index>(3 * i), r, jac);
  evaluate_cycles(state, r, jac);
}

Eigen::VectorXd ClosureSystem::residual(const FoldState& state) const {
  Eigen::VectorXd r(rows_);
  evaluate_into(state, r, nullptr);
  return r;
}

void ClosureSystem::evaluate(const FoldState& state, Eigen::VectorXd& r, Eigen::SparseMatrix<double>& jacobian) const {
  r.resize(rows_);
  const bool same_layout =
      jacobian.isCompressed() && jacobian.rows() == rows_ && jacobian.cols() == cols() &&
      jacobian.nonZeros() == layout_.nonZeros() &&
      std::equal(layout_.outerIndexPtr(), layout_.outerIndexPtr() + cols() + 1, jacobian.outerIndexPtr()) &&
      std::equal(layout_.innerIndexPtr(), layout_.innerIndexPtr() + layout_.nonZeros(), jacobian.innerIndexPtr());
  if (!same_layout) jacobian = layout_;
  std::fill(jacobian.valuePtr(), jacobian.valuePtr() + jacobian.nonZeros(), 0.0);  // a straight crease adds twice
  Sink sink{nullptr, jacobian.valuePtr(), slots_.data()};
  evaluate_into(state, r, &sink);
}

namespace {

// One error per loop of a residual laid out as ClosureSystem's: 3 rows per vertex loop, then 6
// (rotation, translation) per hole cycle.
std::vector<double> errors_of(const Eigen::VectorXd& r, std::size_t loops, std::size_t cycles) {
  std::vector<double> out;
  out.reserve(loops + cycles);
  for (std::size_t i = 0; i < loops; ++i) out.push_back(r.segment<3>(static_cast<Eigen::Index>(3 * i)).norm());
  for (std::size_t i = 0; i < cycles; ++i) {
    const Eigen::Index row = static_cast<Eigen::Index>(3 * loops + 6 * i);
    out.push_back(std::max(r.segment<3>(row).norm(), r.segment<3>(row + 3).norm()));
  }
  return out;
}

}  // namespace

std::vector<double> ClosureSystem::loop_errors(const FoldState& state) const {
  return errors_of(residual(state), loops_.size(), cycles_.size());
}

double ClosureSystem::max_error(const FoldState& state) const { return residual_error(residual(state)); }

double ClosureSystem::residual_error(const Eigen::VectorXd& residual) const {
  const std::vector<double> e = errors_of(residual, loops_.size(), cycles_.size());
  return e.empty() ? 0.0 : *std::max_element(e.begin(), e.end());
}

}  // namespace foldkit::geometry
