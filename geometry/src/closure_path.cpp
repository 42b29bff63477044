#include "foldkit/geometry/closure_path.hpp"

#include <algorithm>
#include <cmath>

#include "foldkit/geometry/mobility.hpp"
#include "foldkit/geometry/projection.hpp"

namespace foldkit::geometry {

std::optional<std::vector<FoldState>> densify(const ClosureSystem& system, const std::vector<FoldState>& waypoints,
                                              double max_step) {
  if (waypoints.empty()) return std::vector<FoldState>{};
  std::vector<FoldState> out{waypoints.front()};
  ProjectionOptions po;
  po.tolerance = 1e-10;
  for (std::size_t i = 1; i < waypoints.size(); ++i) {
    const FoldState& a = waypoints[i - 1];
    const FoldState& b = waypoints[i];
    const double longest = (b.angles - a.angles).cwiseAbs().maxCoeff();
    const int parts = std::max(1, static_cast<int>(std::ceil(longest / max_step - 1e-9)));
    for (int k = 1; k < parts; ++k) {
      const FoldState line{a.angles + (static_cast<double>(k) / parts) * (b.angles - a.angles)};
      const ProjectionResult p = project(system, line, po);
      if (!p.status.ok() || (p.state.angles - line.angles).cwiseAbs().maxCoeff() > 0.5 * max_step) return std::nullopt;
      out.push_back(p.state);
    }
    out.push_back(b);
  }
  // A projected point may still sit a little farther from its neighbours than max_step.
  for (std::size_t i = 1; i < out.size(); ++i)
    if ((out[i].angles - out[i - 1].angles).cwiseAbs().maxCoeff() > 2.0 * max_step) return std::nullopt;
  return out;
}

std::vector<FoldState> lead_in(const ClosureSystem& system, const FoldState& start, const FoldState& goal,
                               Eigen::Index rank, double max_step) {
  Eigen::VectorXd dir = goal.angles - start.angles;
  const double norm = dir.cwiseAbs().maxCoeff();
  if (!(norm > 0.0)) return {};
  dir /= norm;
  ProjectionOptions po;
  po.tolerance = 1e-12;
  for (double scale : {0.02, 0.05, 0.1, 0.2, 0.4}) {
    const int parts = std::max(2, static_cast<int>(std::ceil(scale / max_step)));
    std::vector<FoldState> pts{start};
    bool ok = true;
    for (int k = 1; k <= parts && ok; ++k) {
      const ProjectionResult p = project(system, FoldState{start.angles + (scale * k / parts) * dir}, po);
      ok = p.status.ok();
      pts.push_back(p.state);
    }
    if (!ok || mobility(system, pts.back()).rank < rank) continue;
    if (auto dense = densify(system, pts, max_step)) return *dense;
  }
  return {};
}

std::vector<FoldState> projected_line(const ClosureSystem& system, const FoldState& from, const FoldState& to,
                                      double step) {
  if (system.rows() == 0) {
    const double longest = (to.angles - from.angles).cwiseAbs().maxCoeff();
    const int parts = std::max(1, static_cast<int>(std::ceil(longest / step - 1e-9)));
    std::vector<FoldState> out;
    for (int k = 0; k <= parts; ++k)
      out.push_back(FoldState{from.angles + (static_cast<double>(k) / parts) * (to.angles - from.angles)});
    return out;
  }
  auto dense = densify(system, {from, to}, step);
  return dense ? *dense : std::vector<FoldState>{};
}

std::optional<FoldState> goal_from_angles(const ClosureSystem& system, const std::vector<std::pair<int, double>>& angles,
                                          std::string& why) {
  FoldState rough{Eigen::VectorXd::Zero(system.cols())};
  ProjectionOptions o;
  o.held.assign(static_cast<std::size_t>(system.cols()), false);
  for (const auto& [j, a] : angles) {
    rough.angles[j] = a;
    o.held[static_cast<std::size_t>(j)] = true;
  }
  const ProjectionResult r = project(system, rough, o);
  if (!r.status.ok()) {
    why = r.status.message;
    return std::nullopt;
  }
  return r.state;
}

}  // namespace foldkit::geometry
