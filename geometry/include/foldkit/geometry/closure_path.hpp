#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/fold_state.hpp"

// Paths of closed states: what the planners, the benchmark scenes and the CLI build around a
// planner's output. Every state returned closes to the projection's tolerance; the rank they
// refer to is geometry::mobility's (singular values).
namespace foldkit::geometry {

// Inserts closed states (straight-line points projected onto the closure manifold, signs kept)
// until no joint changes more than `max_step` (radians) between neighbours. Nothing when a
// projection fails or lands farther than `max_step` from its straight-line point (a jump).
std::optional<std::vector<FoldState>> densify(const ClosureSystem& system, const std::vector<FoldState>& waypoints,
                                              double max_step);

// A short closed path out of a singular start (e.g. the flat sheet): projections of
// start + s·(goal − start) for growing s, signs kept, ending at a state where the closure
// Jacobian has rank `rank` (geometry::mobility). Empty when none is found.
std::vector<FoldState> lead_in(const ClosureSystem& system, const FoldState& start, const FoldState& goal,
                               Eigen::Index rank, double max_step);

// The straight joint-angle line from `from` to `to`, each point projected onto the closure
// manifold (signs kept), no joint moving more than `step` between neighbours; the plain line
// when the pattern has no loop. Empty when a projection fails or jumps.
std::vector<FoldState> projected_line(const ClosureSystem& system, const FoldState& from, const FoldState& to,
                                      double step);

// The closed state nearest to the flat sheet in which the given creases (joint indices) have the
// given angles (radians): the other creases move, the named ones are held. Nothing, with the
// projection's message in `why`, when none is found.
std::optional<FoldState> goal_from_angles(const ClosureSystem& system, const std::vector<std::pair<int, double>>& angles,
                                          std::string& why);

}  // namespace foldkit::geometry
