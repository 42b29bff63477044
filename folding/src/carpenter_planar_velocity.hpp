#pragma once
// The LP of one Carpenter's-rule step: a strictly expansive infinitesimal motion of a (merged)
// planar chain, with struts added by constraint generation.
#include <cstddef>
#include <cstdint>
#include <set>
#include <unordered_map>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace foldkit::folding::detail {

namespace struts {
class StrutModel;
}

struct ExpansiveVelocity {
  std::vector<Eigen::Vector2d> v;  // one per vertex; vertices 0 and 1 (bar 0) are pinned
  double t = 0.0;                  // smallest weighted strut rate over all pairs, capped at 2 (≥ 1 when solved)
  std::size_t lp_solves = 0;
  std::size_t struts = 0;                    // strut rows in the last LP
  std::vector<std::pair<int, int>> binding;  // struts within a factor 2 of the bound (vertex indices)
  bool solved = false;
  const char* status = "optimal";  // the LP's status when not solved
};

// The optimal basis of the last step's LP, by input vertex, so that the next step's LP (the same
// structure on slightly moved points, perhaps with joints merged) starts the dual simplex near
// its optimum. Statuses are Clp's codes; 0 = unknown.
struct BasisMemo {
  std::vector<unsigned char> vx, vy, plus, minus, bar_row, joint_row;  // per input vertex
  std::unordered_map<std::int64_t, unsigned char> strut_row;             // key_a · n + key_b
  bool valid = false;
};

// Ends of an open chain held rigid (issue 36's spirals): the first `prefix` vertices move as
// one body with bar 0, and so do the last `suffix` ones; their joints keep their angles and pairs
// inside one such body keep their distance, so they get no strut. Fewer than 3 holds nothing.
struct RigidEnds {
  int prefix = 0;
  int suffix = 0;
  bool probe = false;  // a failed LP is not solved again from scratch (the caller tries other holds)
  bool any() const { return prefix >= 3 || suffix >= 3; }
  // Joint k (a vertex) is held.
  bool holds_joint(int k, int m) const { return (prefix >= 3 && k < prefix - 1) || (suffix >= 3 && k > m - suffix); }
  // Pair (a < b) lies inside one held body.
  bool holds_pair(int a, int b, int m) const { return (prefix >= 3 && b < prefix) || (suffix >= 3 && a >= m - suffix); }
};

// The pairs (a < b, not bars) that a step's first LP starts with: those closer than `radius`,
// or, where the median distance from a vertex to its nearest non-bar vertex is shorter than
// radius / 2, closer than twice that median. The callers' radius follows the mean bar, which
// is the vertices' spacing on a lattice walk but not on a star-shaped polygon, where long spokes
// crowd the centre: on random_star(1000, 1) (mean bar 12.7, median nearest distance 1.41) one
// mean bar put 31,892 pairs into the first LP, which took 199 s; twice the median puts in 1,731.
std::vector<std::pair<int, int>> near_pairs(const struts::StrutModel& model, const std::vector<Eigen::Vector2d>& p,
                                            double radius);

// Minimise Σ|θ̇| over the joints subject to bars (v_{a+1} − v_a)·(p_{a+1} − p_a) = 0 (and the
// closing bar when `closed`), bar 0 pinned, and w_ab·(v_b − v_a)·(p_b − p_a) ≥ 1 on every other
// pair (positive weights, see the source). The LP starts with the struts in `seed` and the
// pairs closer than `near_radius`, and adds the most violated of all pairs until none is
// violated; `all_struts` puts every pair in at once. With `key` (input vertex of each vertex,
// all below the memo's size) and `memo`, the first LP starts from the basis in `memo`, which is
// then replaced by this step's. With `rigid`, held joints keep their angles, pairs inside a
// held body get no strut and v is rebuilt from the joint speeds. Not solved when no strictly expansive
// motion exists (straight / convex) or the LP fails.
ExpansiveVelocity expansive_velocity(const std::vector<Eigen::Vector2d>& p, bool closed,
                                     const std::vector<std::pair<int, int>>& seed, double near_radius,
                                     bool all_struts, const std::vector<int>* key = nullptr,
                                     BasisMemo* memo = nullptr, const RigidEnds& rigid = {});

// Velocities of an open chain whose joints turn at `speed` (per vertex), bar 0 fixed: bar a turns
// at ω_a = Σ_{k ≤ a} speed_k, and v_{a+1} = v_a + ω_a·J(p_{a+1} − p_a).
std::vector<Eigen::Vector2d> open_chain_velocities(const std::vector<Eigen::Vector2d>& p,
                                                   const std::vector<double>& speed);

// The window LP of carried_velocity(), for its tests: the speeds of the joints k with in[k] that
// minimise their Σ|θ̇ₖ| with every pair in `rows` (a < b, no bar) at weighted rate ≥ 1, the other
// joints at `speed` (an open chain, bar 0 fixed). False, `speed` unchanged, when there are none.
bool window_speeds(const std::vector<Eigen::Vector2d>& p, const std::set<std::pair<int, int>>& rows,
                   const std::vector<char>& in, std::vector<double>& speed);

// A field carried over from the last step (CarpenterPlanarMethod::CarriedField), mended.
struct CarriedVelocity {
  std::vector<Eigen::Vector2d> v;  // bar 0 fixed
  std::vector<double> speed;       // joint speeds, per vertex
  double t = 0.0;                  // smallest weighted rate over all pairs, capped at 2
  std::size_t lp_solves = 0;       // window LPs solved
  std::size_t struts = 0;          // rows of the last window LP
  bool solved = false;
};

// The open chain p with joints turning at `speed` (per vertex; the chain's ends 0), checked on
// all pairs: where some pair's weighted rate is below `floor`, only the joints near the ends of
// such pairs (inside them) and near the bars in `dropped` (bars a, between vertices a and a + 1,
// that have lost a joint since the field was solved: every pair across such a bar lost that
// joint's share of its rate) change, by an LP that minimises their Σ|θ̇| with every such pair's
// weighted rate ≥ 1 and the other joints at their speeds; pairs found weak after it are added
// and the window widened (doubled when its LP is infeasible) until the all-pairs check passes.
// Not solved when that takes more than `max_window` joints or 30 rounds: the caller then solves
// the global LP.
CarriedVelocity carried_velocity(const std::vector<Eigen::Vector2d>& p, std::vector<double> speed,
                                 const std::vector<int>& dropped, double floor, int max_window);

}  // namespace foldkit::folding::detail
