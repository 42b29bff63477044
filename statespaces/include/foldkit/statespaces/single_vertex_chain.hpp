#pragma once
/// @file
/// The closed-form kinematics of a single interior vertex.
#include <array>
#include <vector>

#include <Eigen/Core>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"

namespace foldkit::statespaces {

/// The degree-n spherical closed chain of one interior vertex, solved in closed form
/// (docs/PLANNING.md). With fold angles ρ and φ = −ρ, closure is
///
///     R(d₁, φ₁) R(d₂, φ₂) ··· R(dₙ, φₙ) = I   (creases counter-clockwise, as in ClosureSystem).
///
/// Three consecutive creases are passive (u₁, u₂, u₃); the other n − 3 are active. Given the active
/// angles, R(u₁, a) R(u₂, b) R(u₃, c) = Q is a Davenport-angle problem: since all axes lie in the
/// sheet's plane, u₁·R(u₂, b)u₃ = u₁·Q u₃ reduces to A cos b = C − K, whose roots ±b are the two
/// branches; then a turns R(u₂, b)u₃ into Q u₃ about u₁, and c is what is left.
/// The branch is the sign of the middle passive crease's fold angle (+1 mountain, −1 valley); both
/// roots meet where that crease is flat (b = 0), the only place a continuous motion can change it.
/// Every state passed in holds one angle per joint of the pattern (radians).
class SingleVertexChain {
 public:
  /// The chain of interior vertex `vertex` (an index into pattern.interior_vertices()). The
  /// passive triple is chosen for good conditioning. The pattern must outlive this.
  /// @throws std::invalid_argument when the pattern has no such vertex, has more than one
  ///         interior vertex (multi-vertex patterns need the constrained space), or the vertex
  ///         has fewer than 4 creases (it is rigid)
  explicit SingleVertexChain(const geometry::CreasePattern& pattern, std::size_t vertex = 0);
  /// Deleted: the chain keeps a reference to its pattern, so a temporary one is refused.
  SingleVertexChain(geometry::CreasePattern&&, std::size_t = 0) = delete;

  /// The pattern the chain belongs to.
  const geometry::CreasePattern& pattern() const { return *pattern_; }
  /// n, the number of creases round the vertex.
  std::size_t degree() const { return joints_.size(); }
  /// n − 3, the number of active creases: the dimension of the closed configurations.
  std::size_t dimension() const { return joints_.size() - 3; }
  /// Joint indices (into pattern.joints()) of the active creases, in product order after the
  /// passive triple.
  const std::vector<int>& active_joints() const { return active_; }
  /// Joint indices of the passive creases u₁, u₂, u₃; the middle one carries the branch.
  const std::array<int, 3>& passive_joints() const { return passive_; }

  /// Completes `state` (one angle per joint of the pattern) from its active angles on `branch`
  /// (+1 / −1; 0 counts as +1).
  /// @return false when no root exists or the state is singular (the passive angles are then
  ///         left unchanged)
  bool solve(geometry::FoldState& state, int branch) const;
  /// cos b of the middle passive crease for the active angles of `state`, before clamping: a root
  /// exists iff it lies in [−1, 1]. Exposed for samplers and tests.
  double cos_middle(const geometry::FoldState& state) const;
  /// The branch of a closed state: the sign of its middle passive crease (0 counts as +1).
  int branch_of(const geometry::FoldState& state) const;
  /// |fold angle| of the middle passive crease, radians: 0 where both branches meet.
  double meeting_distance(const geometry::FoldState& state) const;

 private:
  Eigen::Matrix3d active_product(const geometry::FoldState& state) const;

  const geometry::CreasePattern* pattern_;
  std::vector<int> joints_;               // counter-clockwise
  std::vector<Eigen::Vector3d> axes_;     // unit direction of each crease leaving the vertex
  std::size_t first_passive_ = 0;         // position of u₁ in joints_
  std::vector<int> active_;               // joint indices, in product order after the passive triple
  std::vector<Eigen::Vector3d> active_axes_;
  std::array<int, 3> passive_{};
  std::array<Eigen::Vector3d, 3> u_;
  double A_ = 0.0, K_ = 0.0;              // A cos b = C − K
};

}  // namespace foldkit::statespaces
