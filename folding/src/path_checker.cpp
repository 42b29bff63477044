#include "path_checker.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "foldkit/simulation/simulate.hpp"

namespace foldkit::folding {
namespace {

constexpr double kPi = 3.14159265358979323846;

simulation::CollisionOptions with_margin(double margin) {
  simulation::CollisionOptions o;
  o.margin = margin;
  return o;
}

}  // namespace

double fraction_of(const geometry::FoldState& s) { return s.angles.size() ? s.angles.cwiseAbs().maxCoeff() / kPi : 0.0; }

PathChecker::PathChecker(const geometry::CreasePattern& pattern)
    : pattern_(pattern), tree_(geometry::make_tree(pattern)), margin_(0.25 * simulation::smallest_feature(pattern)),
      world_(pattern, with_margin(margin_)), motion_(pattern) {}

std::string PathChecker::crossing(const geometry::FoldState& a, const geometry::FoldState& b) {
  const auto pa = geometry::facet_poses(pattern_, tree_, a), pb = geometry::facet_poses(pattern_, tree_, b);
  const double moved = motion_.largest(pa, pb);
  const int parts = std::max(1, static_cast<int>(std::ceil(moved / margin_)));
  for (int k = first_ ? 0 : 1; k <= parts; ++k) {
    const geometry::FoldState s{a.angles + (static_cast<double>(k) / parts) * (b.angles - a.angles)};
    const auto crossings = world_.check(geometry::facet_poses(pattern_, tree_, s), s);
    if (!crossings.empty()) {
      const auto& c = crossings.front();
      std::ostringstream out;
      out << "actors " << pattern_.actors()[c.actors[0]].id << " and " << pattern_.actors()[c.actors[1]].id << " cross ("
          << simulation::to_string(c.kind);
      if (c.kind == simulation::CrossingKind::Mesh) out << ", depth " << c.depth;
      out << ") at largest fold angle " << fraction_of(s) * 180.0 << " deg";
      return out.str();
    }
  }
  first_ = false;
  return {};
}

void PathChecker::restart(const geometry::FoldState& x) {
  world_ = simulation::CollisionWorld(pattern_, with_margin(margin_));
  first_ = true;
  crossing(x, x);
}

}  // namespace foldkit::folding
