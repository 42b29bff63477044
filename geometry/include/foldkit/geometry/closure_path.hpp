#pragma once
/// @file
/// Paths of closed states: what the planners, the benchmark scenes and the CLI build around a
/// planner's output. Every state a function here computes closes to the projection's tolerance
/// (geometry::project); the rank they refer to is geometry::mobility's (singular values).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/fold_state.hpp"

namespace foldkit::geometry {

/// Inserts closed states between consecutive waypoints until no joint changes more than about
/// `max_step` between neighbours: points of the straight line between two waypoints, each
/// projected onto the closure manifold (to 1e-10 rad, signs kept). The waypoints themselves are
/// kept as given.
/// @param system     the closure equations of the pattern
/// @param waypoints  states with one angle per joint, radians; may be empty
/// @param max_step   largest joint change between neighbours, radians (> 0)
/// @return the dense path (empty for no waypoints), or nothing when a projection fails, lands
///         farther than max_step / 2 from its straight-line point, or leaves two neighbours more
///         than 2 · max_step apart (a jump to another branch)
std::optional<std::vector<FoldState>> densify(const ClosureSystem& system, const std::vector<FoldState>& waypoints,
                                              double max_step);

/// A short closed path out of a singular start (such as the flat sheet): projections of
/// start + s·(goal − start) for growing s (signs kept), ending at a state where the closure
/// Jacobian has at least rank `rank` (geometry::mobility), densified to `max_step`.
/// @param system    the closure equations of the pattern
/// @param start     the singular state to leave, radians
/// @param goal      the state that gives the direction, radians
/// @param rank      the rank wanted at the path's end (the generic rank of the Jacobian)
/// @param max_step  largest joint change between neighbours, radians (> 0)
/// @return the path from `start`, or empty when none is found (or start = goal)
std::vector<FoldState> lead_in(const ClosureSystem& system, const FoldState& start, const FoldState& goal,
                               Eigen::Index rank, double max_step);

/// The straight joint-angle line from `from` to `to`, each point projected onto the closure
/// manifold (signs kept), no joint moving more than `step` (radians) between neighbours, as
/// densify() makes it; the plain line, both ends included, when the pattern has no loop.
/// @return the path, or empty when a projection fails or jumps
std::vector<FoldState> projected_line(const ClosureSystem& system, const FoldState& from, const FoldState& to,
                                      double step);

/// The closed state nearest to the flat sheet in which the given creases have the given
/// angles: the other creases move, the named ones are held.
/// @param system  the closure equations of the pattern
/// @param angles  pairs (joint index, angle in radians); every index must be in range
/// @param why     set to the projection's message when no state is found
/// @return the state, or nothing when the projection does not converge
std::optional<FoldState> goal_from_angles(const ClosureSystem& system, const std::vector<std::pair<int, double>>& angles,
                                          std::string& why);

}  // namespace foldkit::geometry
