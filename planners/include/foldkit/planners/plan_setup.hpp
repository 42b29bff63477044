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
#include "foldkit/planners/plan_space.hpp"
#include "foldkit/statespaces/state_reader.hpp"
#include "foldkit/statespaces/validity.hpp"

namespace foldkit::planners {

/// The pieces of plan() that `foldkit bench` shares with it: the checked problem, the space, its
/// SpaceInformation (validity checker and motion validator set) and the way out of a singular
/// start. Plain data; what differs between the kinds of space is in `plan_space`.
struct PlanSetup {
  const geometry::CreasePattern* pattern = nullptr;  ///< the pattern (make_plan_setup's; must outlive the setup)
  std::shared_ptr<PlanSpace> plan_space;   ///< the space's kind, built: its name, states, paths and fallback
  geometry::FoldState start;               ///< where the plan starts (PlanOptions::start; flat when it gives none)
  geometry::FoldState goal;                ///< where it ends
  std::vector<geometry::FoldState> prefix;  ///< start … the state the planner starts from (the lead-in)
  std::shared_ptr<const geometry::ClosureSystem> system;  ///< the pattern's closure equations
  std::shared_ptr<statespaces::FoldValidity> validity;    ///< what a valid state is
  ompl::base::StateSpacePtr space;   ///< the space the planner searches
  ompl::base::SpaceInformationPtr si;  ///< its SpaceInformation, checkers set
  statespaces::StateReader reader;   ///< reads fold angles from a state of `space`
  std::string blocked;               ///< not empty: the way out of the start collides (no plan)
  /// Driving space, not empty: the goal lies on another branch than the start, and why (a 1-DOF
  /// pattern whose start continues to another state at the goal's driving angle): no motion of
  /// the space joins them.
  std::string other_branch;
  /// Driving space: the straight continuation from the start to the goal's driving angles ends at
  /// the goal, so a direct path exists (collisions aside) and a folded start is not planned
  /// through flat.
  bool continues_to_goal = false;
};

/// Sets `ss`'s start to setup.prefix.back() and its goal to `goal` (threshold 1e-9), anchored in
/// the space (PlanSpace::anchor).
/// @throws PlanInputError when the goal is a singular state of the space
void set_start_and_goal(const PlanSetup& setup, ompl::geometric::SimpleSetup& ss, const geometry::FoldState& goal);

/// Runs `ss`'s planner (set up on setup.si) until its first exact solution (`until_threshold`:
/// its first solution whose cost satisfies the problem's objective, OMPL's "optimized"
/// solution) or `seconds`. The time holds even in planner loops that never consult their
/// termination condition (RRTConnect's connect loop): setup.validity is under a
/// FoldValidity::TimeLimit meanwhile.
ompl::base::PlannerStatus run_planner(const PlanSetup& setup, ompl::geometric::SimpleSetup& ss, double seconds,
                                      bool until_threshold = false);

/// Checks the problem as plan() does and builds the space: SpaceKind::Auto picks the
/// single-vertex space for a pattern with one interior vertex and no hole, else the driving-crease
/// one. A start below the rank the space needs (PlanSpace::lead_in_rank; the flat sheet) is left
/// along geometry::lead_in, giving the prefix.
/// @param pattern         the pattern (must outlive the setup)
/// @param goal            closed, one angle per joint, radians
/// @param options         the plan's settings (PlanOptions)
/// @param allow_no_loops  give a pattern without closed loops a joint-angle box (plan() refuses
///                        such patterns: nothing to plan on)
/// @throws std::invalid_argument for a start or goal that does not hold one angle per joint, is
///         not closed (to 1e-6 rad), breaks the assignment or collides, a resolution, waypoint
///         step or speed that is not positive, a pattern without loops (unless allowed), no
///         closed way out of a singular start, or a space that cannot be built
///         (ClosureConstraint, SingleVertexChain)
PlanSetup make_plan_setup(const geometry::CreasePattern& pattern, const geometry::FoldState& goal, const PlanOptions& options,
                          bool allow_no_loops = false);

/// A solution path as fold states: the prefix, then the path densified along the space's own
/// motion (PlanSpace::path_states), then, with `to_goal`, the goal when the path ends short of it;
/// finally densified onto the closure manifold (densify()), no joint moving more than
/// options.waypoint_step between waypoints. Each pair of neighbours is densified as soon as both
/// are known, so `sink` (when set) gets the waypoints in order while the later ones are still
/// being computed (the plan's replay starts on them); it gets none after a jump. `stop`, when
/// set, is asked between the expensive steps: once it returns true (it must stay true) the
/// waypoints are dropped; with a `stop`, a path that needs the driving space's halving
/// (PlanSpace::path_states) gives none either.
/// @return the waypoints, or nothing, with `*why` set when `why` is not null, when the path jumps,
///         was stopped or needs halving under a stop
std::optional<std::vector<geometry::FoldState>> path_waypoints(const PlanSetup& setup, ompl::geometric::PathGeometric path,
                                                               const PlanOptions& options, bool to_goal, std::string* why,
                                                               const PlanSpace::StateSink& sink = {},
                                                               const PlanSpace::Stop& stop = {});

/// The CMML of `waypoints` from the flat sheet (geometry::path_sequence at options.speed), the
/// options' start sequence first; titled after the pattern.
geometry::FoldSequence plan_sequence(const PlanSetup& setup, const PlanOptions& options,
                                     const std::vector<geometry::FoldState>& waypoints);

}  // namespace foldkit::planners
