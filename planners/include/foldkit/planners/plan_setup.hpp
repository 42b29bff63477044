#pragma once
/// @file
/// The pieces of planners::plan() that `foldkit bench` shares with it.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <ompl/base/SpaceInformation.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/SimpleSetup.h>

#include "foldkit/planners/plan.hpp"
#include "foldkit/statespaces/closure_constraint.hpp"
#include "foldkit/statespaces/driving_space.hpp"
#include "foldkit/statespaces/single_vertex_space.hpp"
#include "foldkit/statespaces/validity.hpp"

namespace foldkit::planners {

/// The pieces of plan() that `foldkit bench` shares with it: the checked problem, the space, its
/// SpaceInformation (validity checker and motion validator set) and the way out of a singular start.
struct PlanSetup {
  SpaceKind kind = SpaceKind::Auto;  ///< resolved; Auto only for `joint_space`
  std::string space_name;            ///< "single-vertex", "projected", … or "joint" (no loop)
  geometry::FoldState start;         ///< the request's start (flat when it gives none)
  std::vector<geometry::FoldState> prefix;  ///< start … the state the planner starts from
  std::shared_ptr<const geometry::ClosureSystem> system;  ///< the pattern's closure equations
  std::shared_ptr<statespaces::FoldValidity> validity;    ///< what a valid state is
  ompl::base::StateSpacePtr space;   ///< the space the planner searches
  ompl::base::SpaceInformationPtr si;  ///< its SpaceInformation, checkers set
  statespaces::StateReader reader;   ///< reads fold angles from a state of `space`
  std::shared_ptr<statespaces::SingleVertexStateSpace> single_vertex;  ///< the single-vertex space; null otherwise
  std::shared_ptr<statespaces::DrivingStateSpace> driving;            ///< the driving-crease space; null otherwise
  statespaces::ConstrainedSetup constrained;                          ///< constrained spaces only
  bool joint_space = false;  ///< a pattern without loops: a plain box over the fold angles
  std::string blocked;       ///< not empty: the way out of the start collides (no plan)
  /// Not empty: the space cannot reach the goal from the start, and why (a 1-DOF pattern whose
  /// start continues to another state at the goal's driving angle: the goal is on another branch).
  std::string unreachable;
  /// Driving space: the straight continuation from the start to the goal's driving angles ends at
  /// the goal, so a direct path exists (collisions aside) and a folded start is not planned
  /// through flat.
  bool reachable = false;

  /// Writes a closed fold state into a state of `space`.
  /// @return false when the space cannot hold it (a singular state of the single-vertex space)
  bool write(const geometry::FoldState& state, ompl::base::State* out) const;
  /// Start = prefix.back(), goal = `goal` (threshold 1e-9); anchors Atlas/TangentBundle charts.
  /// @throws std::invalid_argument when the goal is singular for the single-vertex space
  void set_start_and_goal(ompl::geometric::SimpleSetup& ss, const geometry::FoldState& goal) const;
  /// Runs `ss`'s planner (set up on `si`) until its first exact solution or `seconds`. The time
  /// holds even in planner loops that never consult their termination condition (RRTConnect's
  /// connect loop): `validity` is under a FoldValidity::TimeLimit meanwhile.
  ompl::base::PlannerStatus solve(ompl::geometric::SimpleSetup& ss, double seconds) const;
};

/// Checks the request as plan() does and builds the space: SpaceKind::Auto picks the
/// single-vertex space for a pattern with one interior vertex and no hole, else the driving-crease
/// one. A singular start (such as the flat sheet) is left along geometry::lead_in, giving the
/// prefix.
/// @param request         the planning problem
/// @param allow_no_loops  give a pattern without closed loops a joint-angle box (plan() refuses
///                        such patterns: nothing to plan on)
/// @throws std::invalid_argument for a request without a pattern, a start or goal that does not
///         hold one angle per joint, is not closed (to 1e-6 rad), breaks the assignment or
///         collides, a resolution, waypoint step or velocity that is not positive, a pattern
///         without loops (unless allowed), no closed way out of a singular start, or a space
///         that cannot be built (ClosureConstraint, SingleVertexChain)
PlanSetup make_plan_setup(const PlanRequest& request, bool allow_no_loops = false);

/// A solution path as fold states: the prefix, then the path densified along the space's own
/// interpolation (single-vertex: linear in the active angles; constrained: OMPL's geodesic), then,
/// with `to_goal`, the goal when the path ends short of it; finally densified onto the closure
/// manifold (densify()), no joint moving more than request.waypoint_step between waypoints.
/// @return the waypoints, or nothing, with `*why` set when `why` is not null, when the path jumps
std::optional<std::vector<geometry::FoldState>> path_waypoints(const PlanSetup& setup, ompl::geometric::PathGeometric path,
                                                               const PlanRequest& request, bool to_goal, std::string* why);

/// The CMML of `waypoints` from the flat sheet (geometry::path_sequence at request.velocity),
/// the request's start sequence first; titled after the pattern.
geometry::FoldSequence plan_sequence(const PlanRequest& request, const PlanSetup& setup,
                                     const std::vector<geometry::FoldState>& waypoints);

}  // namespace foldkit::planners
