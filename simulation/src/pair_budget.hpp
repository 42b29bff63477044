#pragma once
// How far a pair of facets may turn relative to each other before CollisionWorld's verdict on it
// can change, so that the world can skip the pair until then. Private to foldkit::simulation.
#include <algorithm>
#include <array>
#include <vector>

#include <Eigen/Core>

#include "foldkit/geometry/crease_pattern.hpp"

namespace foldkit::simulation::detail {

/// The pair as check() sees it: a's points in its own (flat) coordinates, b's placed there.
struct PlacedPair {
  const std::vector<Eigen::Vector3d>& a_points;
  const std::vector<std::array<int, 3>>& a_triangles;
  const std::vector<Eigen::Vector3d>& b_points;  ///< b's points in a's coordinates
  const std::vector<std::array<int, 3>>& b_triangles;
  Eigen::Vector3d b_normal;  ///< the normal of b's plane in a's coordinates (unit)
};

/// How b can move in a's coordinates until the pair is tested again.
///
/// With an apex (every crease of the pair's chain passes through one vertex of both facets), b
/// only turns about that vertex, by at most the sum of the chain's turns, and budgets are angles
/// (radians): a point's elevation above a plane through the apex changes by at most that much.
/// Without one, a point of b moves by at most Σ |Δθ_i| L_i (L_i: the diameters of the facets from
/// crease i on, which bound its distance from that crease's axis in any state), and budgets are
/// lengths. Both bounds hold between any two states, not only along a motion.
struct Motion {
  const Eigen::Vector3d* apex = nullptr;  ///< the common vertex in a's coordinates, or none
  double tolerance = 0.0;                 ///< the world's touching distance (pattern units)
};

/// Per point: its height above a plane as a budget measures it (the elevation angle seen from the
/// apex, or the distance), and how far below zero it may go and still count as touching (the
/// angle the tolerance subtends there, or the tolerance). Scratch kept between calls.
struct Heights {
  std::vector<double> s, g;
  std::vector<double> slack;  // pair_budget's scratch: per triangle
};

/// The budget within which b stays on the side of a's plane it is on now, as CollisionWorld
/// classes it (side: -1 wholly below, 1 wholly above, 2 across; touching within the tolerance
/// allowed), and, for a pair across, no pair of a's and b's triangles straddles both planes (the
/// first test of triangles_cross), so that none can cross. 0 when it may change at once. The
/// second needs an apex: without one, a's plane seen from b moves by a lever that depends on a's
/// points too, so a pair across gets 0.
double pair_budget(const PlacedPair& pair, const Motion& motion, int side, Heights& a_scratch, Heights& b_scratch);

/// How far each joint has turned over the checks of one motion, Σ |Δθ| (radians; it bounds |Δθ|
/// between any two of them), and the sum over the checks of the largest turn of any joint, by
/// which a chain's weighted travel grows by at most its weights' sum.
class Travel {
 public:
  explicit Travel(std::size_t joints) : joint_(joints, 0.0) {}
  /// Adds the turns from the last state to `angles` (one per joint); the first state after
  /// construction or reset() is only remembered.
  void advance(const Eigen::VectorXd& angles);
  /// A new motion starts: nothing turned yet (the sums start again, so that they neither grow
  /// without bound over many motions nor keep a past infinite turn).
  void reset() {
    last_.resize(0);
    std::fill(joint_.begin(), joint_.end(), 0.0);
    global_ = 0.0;
  }
  double joint(int j) const { return joint_[static_cast<std::size_t>(j)]; }  ///< joint j's travel
  double global() const { return global_; }                  ///< Σ of the largest turns

 private:
  std::vector<double> joint_;
  Eigen::VectorXd last_;
  double global_ = 0.0;
};

/// A chain's apex and its steps' levers (Motion): with an apex (every crease passes through one
/// vertex) each step weighs 1; without, a step weighs the diameters of the facets from the one it
/// enters to the chain's end.
struct Levers {
  int apex = -1;                ///< the vertex, or -1
  std::vector<double> weights;  ///< per step
  double sum = 0.0;             ///< of the weights
};
/// The levers of `steps` (as detail::chain_steps gives them, not {kNoChain}); `diameters` per actor.
Levers chain_levers(const geometry::CreasePattern& pattern, const std::vector<int>& steps, const std::vector<double>& diameters);

}  // namespace foldkit::simulation::detail
