#include "pair_budget.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace foldkit::simulation::detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

// Heights of `points` above the plane through `origin` with unit `normal`. Points within the
// tolerance of the apex stay there (the motion turns about it): they get a height that no budget
// minds (0, allowed to go π below).
void heights(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& normal, const Eigen::Vector3d& origin,
             const Motion& motion, Heights& h) {
  h.s.clear();
  h.g.clear();
  for (const auto& p : points) {
    const double z = normal.dot(p - origin);
    if (!motion.apex) {
      h.s.push_back(z);
      h.g.push_back(motion.tolerance);
      continue;
    }
    const double r = (p - *motion.apex).norm();
    if (r <= motion.tolerance) {
      h.s.push_back(0.0);
      h.g.push_back(kPi);
      continue;
    }
    h.s.push_back(std::asin(std::clamp(z / r, -1.0, 1.0)));
    h.g.push_back(std::asin(std::min(1.0, motion.tolerance / r)));
  }
}

// Budget within which every point stays at or above -tolerance (sign 1) or at or below +tolerance
// (sign -1): min over the points of sign·s + g.
template <class Points>
double stays_within(const Heights& h, double sign, const Points& points) {
  double b = kInf;
  for (int i : points) b = std::min(b, sign * h.s[i] + h.g[i]);
  return b;
}
double stays_within(const Heights& h, double sign) {
  double b = kInf;
  for (std::size_t i = 0; i < h.s.size(); ++i) b = std::min(b, sign * h.s[i] + h.g[i]);
  return b;
}
// Budget within which some point stays strictly beyond +tolerance (sign 1) or -tolerance (-1).
double some_beyond(const Heights& h, double sign) {
  double b = 0.0;
  for (std::size_t i = 0; i < h.s.size(); ++i) b = std::max(b, sign * h.s[i] - h.g[i]);
  return b;
}
// Budget within which a triangle's corners do not straddle the plane its heights are against.
double one_sided(const Heights& h, const std::array<int, 3>& t) {
  return std::max(stays_within(h, 1.0, t), stays_within(h, -1.0, t));
}

}  // namespace

double pair_budget(const PlacedPair& pair, const Motion& motion, int side, Heights& a_heights, Heights& b_heights) {
  const Eigen::Vector3d origin = motion.apex ? *motion.apex : Eigen::Vector3d::Zero();
  heights(pair.b_points, Eigen::Vector3d::UnitZ(), origin, motion, b_heights);  // b against a's plane z = 0
  double budget = 0.0;
  if (side == 1) budget = std::min(stays_within(b_heights, 1.0), some_beyond(b_heights, 1.0));
  if (side == -1) budget = std::min(stays_within(b_heights, -1.0), some_beyond(b_heights, -1.0));
  if (side != 2) return std::max(0.0, budget);
  if (!motion.apex) return 0.0;
  budget = std::min(some_beyond(b_heights, 1.0), some_beyond(b_heights, -1.0));
  // Every triangle of a planar facet lies in its plane (to round-off, which the caller's margin
  // covers), so each triangle's slack is against the other facet's plane; a pair of triangles
  // cannot cross while either of them stays on one side of the other's.
  heights(pair.a_points, pair.b_normal, origin, motion, a_heights);
  std::vector<double>& b_slack = b_heights.slack;
  b_slack.clear();
  for (const auto& y : pair.b_triangles) b_slack.push_back(one_sided(b_heights, y));
  for (const auto& x : pair.a_triangles) {
    const double a_slack = one_sided(a_heights, x);
    for (double y : b_slack) budget = std::min(budget, std::max(a_slack, y));
  }
  return std::max(0.0, budget);
}

void Travel::advance(const Eigen::VectorXd& angles) {
  if (last_.size() == angles.size()) {
    double most = 0.0;
    for (Eigen::Index i = 0; i < angles.size(); ++i) {
      double turn = std::abs(angles[i] - last_[i]);
      // A state that is not finite (a spring that blew up) moved every joint without bound: no
      // budget outlives it until reset().
      if (!std::isfinite(turn)) turn = std::numeric_limits<double>::infinity();
      joint_[static_cast<std::size_t>(i)] += turn;
      most = std::max(most, turn);
    }
    global_ += most;
  }
  last_ = angles;
}

Levers chain_levers(const geometry::CreasePattern& pattern, const std::vector<int>& steps, const std::vector<double>& diameters) {
  Levers l;
  const auto& joints = pattern.joints();
  for (int v : joints[static_cast<std::size_t>(steps[0] >> 1)].v)
    if (std::all_of(steps.begin(), steps.end(), [&](int s) {
          const auto& j = joints[static_cast<std::size_t>(s >> 1)];
          return j.v[0] == v || j.v[1] == v;
        }))
      l.apex = v;
  l.weights.assign(steps.size(), 1.0);
  double lever = 0.0;
  for (std::size_t i = steps.size(); l.apex < 0 && i-- > 0;) {
    const auto& j = joints[static_cast<std::size_t>(steps[i] >> 1)];
    l.weights[i] = lever += diameters[static_cast<std::size_t>(j.actors[steps[i] & 1])];
  }
  for (double w : l.weights) l.sum += w;
  return l;
}

}  // namespace foldkit::simulation::detail
