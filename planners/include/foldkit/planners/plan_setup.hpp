#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <ompl/base/SpaceInformation.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/SimpleSetup.h>

#include "foldkit/planners/plan.hpp"
#include "foldkit/statespaces/closure_constraint.hpp"
#include "foldkit/statespaces/single_vertex_space.hpp"
#include "foldkit/statespaces/validity.hpp"

namespace foldkit::planners {

// The pieces of plan() that `foldkit bench` shares with it: the checked problem, the space, its
// SpaceInformation (validity checker and motion validator set) and the way out of a singular start.
struct PlanSetup {
  SpaceKind kind = SpaceKind::Auto;  // resolved; Auto only for `joint_space`
  std::string space_name;            // "single-vertex", "projected", … or "joint" (no loop)
  geometry::FoldState start;
  std::vector<geometry::FoldState> prefix;  // start … the state the planner starts from
  std::shared_ptr<const geometry::ClosureSystem> system;
  std::shared_ptr<statespaces::FoldValidity> validity;
  ompl::base::StateSpacePtr space;
  ompl::base::SpaceInformationPtr si;
  statespaces::StateReader reader;
  std::shared_ptr<statespaces::SingleVertexStateSpace> single_vertex;  // null otherwise
  statespaces::ConstrainedSetup constrained;                          // constrained spaces only
  bool joint_space = false;  // a pattern without loops: a plain box over the fold angles
  std::string blocked;       // not empty: the way out of the start collides (no plan)

  // Writes a closed fold state into a state of `space`; false when the space cannot hold it
  // (a singular state of the single-vertex space).
  bool write(const geometry::FoldState& state, ompl::base::State* out) const;
  // Start = prefix.back(), goal = `goal` (threshold 1e-9); anchors Atlas/TangentBundle charts.
  // std::invalid_argument when the goal is singular for the single-vertex space.
  void set_start_and_goal(ompl::geometric::SimpleSetup& ss, const geometry::FoldState& goal) const;
};

// Checks the request as plan() does (std::invalid_argument for a start or goal that is not closed,
// breaks the assignment or collides) and builds the space. `allow_no_loops`: a pattern without
// closed loops gets a joint-angle box (plan() refuses such patterns: nothing to plan on).
PlanSetup make_plan_setup(const PlanRequest& request, bool allow_no_loops = false);

// A solution path as fold states: the prefix, then the path densified along the space's own
// interpolation (single-vertex: linear in the active angles; constrained: OMPL's geodesic), then,
// with `to_goal`, the goal when the path ends short of it; finally densified onto the closure
// manifold (densify()). Empty, with `why`, when the path jumps.
std::optional<std::vector<geometry::FoldState>> path_waypoints(const PlanSetup& setup, ompl::geometric::PathGeometric path,
                                                               const PlanRequest& request, bool to_goal, std::string* why);

// The CMML of `waypoints` from the flat sheet, the request's start sequence first.
geometry::FoldSequence plan_sequence(const PlanRequest& request, const PlanSetup& setup,
                                     const std::vector<geometry::FoldState>& waypoints);

}  // namespace foldkit::planners
