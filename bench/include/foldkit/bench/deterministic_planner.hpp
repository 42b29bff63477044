#pragma once
/// @file
/// Deterministic methods (projected line, projected folding, spherical Carpenter) run inside
/// ompl::tools::Benchmark as OMPL planners, so that they are measured like the sampling planners.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <ompl/base/Planner.h>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/statespaces/validity.hpp"

namespace foldkit::bench {

/// What a deterministic method is asked to solve.
struct DeterministicProblem {
  const geometry::CreasePattern* pattern = nullptr;  ///< the pattern
  /// Where the planner starts: closed (after the way out of a singular state), one angle per
  /// joint, radians.
  geometry::FoldState start;
  geometry::FoldState goal;  ///< the goal: closed, one angle per joint, radians
  std::vector<geometry::FoldState> lead_in;  ///< the scene's own start … `start` (only `start` when none)
  double step = 0.02;  ///< largest joint change (radians) between the waypoints the method returns
};
/// A deterministic method: start … goal (or as far as the method gets); empty when it finds
/// nothing. The built-in methods run to completion without polling the termination condition.
using DeterministicMethod =
    std::function<std::vector<geometry::FoldState>(const DeterministicProblem&, const ompl::base::PlannerTerminationCondition&)>;

/// Runs a deterministic method as an OMPL planner: solve() asks the method for waypoints, writes
/// them into states of the space and keeps the longest valid prefix (states and motions checked
/// by the SpaceInformation), then adds it as the solution: exact when it reaches the goal,
/// approximate (difference = distance to the goal) otherwise.
class DeterministicPlanner : public ompl::base::Planner {
 public:
  /// Writes a fold state into a state of the space; false when the space cannot hold it.
  using Writer = std::function<bool(const geometry::FoldState&, ompl::base::State*)>;
  /// A planner named `name` that runs `method` on `pattern`.
  /// @param si       the space information (validity checker and motion validator set)
  /// @param name     the planner's name in logs
  /// @param method   the deterministic method
  /// @param pattern  the pattern (must outlive the planner)
  /// @param reader   reads fold angles from a state of the space
  /// @param writer   writes fold angles into a state of the space
  /// @param lead_in  the scene's start … the planner's start (DeterministicProblem::lead_in); may be empty
  /// @param step     largest joint change between waypoints, radians
  DeterministicPlanner(const ompl::base::SpaceInformationPtr& si, const std::string& name, DeterministicMethod method,
                       const geometry::CreasePattern& pattern, statespaces::StateReader reader, Writer writer,
                       std::vector<geometry::FoldState> lead_in, double step);
  /// Runs the method once from the problem's start to its goal (a ompl::base::GoalState).
  /// @return EXACT_SOLUTION or APPROXIMATE_SOLUTION when a path was added; INVALID_START or
  ///         INVALID_GOAL when a state cannot be read, UNRECOGNIZED_GOAL_TYPE for another goal
  ///         type; TIMEOUT (the condition had fired) or ABORT when the method found nothing
  ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition& ptc) override;
  /// Forgets the previous problem's state (ompl::base::Planner::clear()); the method keeps none.
  void clear() override;

 private:
  DeterministicMethod method_;
  const geometry::CreasePattern* pattern_;
  statespaces::StateReader reader_;
  Writer writer_;
  std::vector<geometry::FoldState> lead_in_;
  double step_;
};

/// Names of the deterministic methods: ProjectedLine (the straight joint-angle line from start
/// to goal, each point projected onto the closure manifold), ProjectedFolding (projected-velocity
/// folding towards the goal) and SphericalCarpenter (single vertices: the goal flattened, the
/// frames reversed).
std::vector<std::string> deterministic_planner_names();
/// Whether `name` names a deterministic method (case-insensitive).
bool is_deterministic_planner(const std::string& name);
/// The deterministic method named `name` (case-insensitive).
/// @throws std::invalid_argument for an unknown name
DeterministicMethod deterministic_method(const std::string& name);
/// The OMPL planner X of a name "X+Carpenter" (case-insensitive): X with the single-vertex
/// fallback (planners::CarpenterFallbackPlanner); empty for any other name.
std::string fallback_inner(const std::string& name);
/// A planner entry "NAME@SPACE" split into NAME and SPACE (planners::parse_space), for runs of
/// several spaces side by side in one log; SPACE is empty for an entry without '@'.
std::pair<std::string, std::string> planner_and_space(const std::string& entry);
/// The canonical name of a planner given by name, case-insensitive: a deterministic method, an
/// OMPL planner (planners::canonical_planner), or an OMPL planner followed by "+Carpenter"; each
/// optionally followed by "@SPACE" (the space's name as planners::to_string() gives it).
/// @throws std::invalid_argument for an unknown name (the message lists the known ones)
std::string canonical_bench_planner(const std::string& name);

}  // namespace foldkit::bench
