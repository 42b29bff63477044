#pragma once
// Deterministic methods (projected line, projected folding, spherical Carpenter) run inside
// ompl::tools::Benchmark as OMPL planners, so that they are measured like the sampling planners.
#include <functional>
#include <string>
#include <vector>

#include <ompl/base/Planner.h>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/statespaces/validity.hpp"

namespace foldkit::bench {

struct DeterministicProblem {
  const geometry::CreasePattern* pattern = nullptr;
  geometry::FoldState start;  // where the planner starts: closed (after the way out of a singular state)
  geometry::FoldState goal;
  std::vector<geometry::FoldState> lead_in;  // the scene's own start … `start` (only `start` when none)
  double step = 0.02;  // largest joint change (radians) between the waypoints the method returns
};
// Start … goal (or as far as the method gets); empty when it finds nothing.
using DeterministicMethod =
    std::function<std::vector<geometry::FoldState>(const DeterministicProblem&, const ompl::base::PlannerTerminationCondition&)>;

// Runs a deterministic method as an OMPL planner: solve() asks the method for waypoints, writes
// them into states of the space and keeps the longest valid prefix (states and motions checked
// by the SpaceInformation), then adds it as the solution: exact when it reaches the goal,
// approximate (difference = distance to the goal) otherwise.
class DeterministicPlanner : public ompl::base::Planner {
 public:
  using Writer = std::function<bool(const geometry::FoldState&, ompl::base::State*)>;
  DeterministicPlanner(const ompl::base::SpaceInformationPtr& si, const std::string& name, DeterministicMethod method,
                       const geometry::CreasePattern& pattern, statespaces::StateReader reader, Writer writer,
                       std::vector<geometry::FoldState> lead_in, double step);
  ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition& ptc) override;
  void clear() override;

 private:
  DeterministicMethod method_;
  const geometry::CreasePattern* pattern_;
  statespaces::StateReader reader_;
  Writer writer_;
  std::vector<geometry::FoldState> lead_in_;
  double step_;
};

// Names of the deterministic methods available in this build (ProjectedLine always: the straight
// joint-angle line from start to goal, each point projected onto the closure manifold).
std::vector<std::string> deterministic_planner_names();
bool is_deterministic_planner(const std::string& name);
// std::invalid_argument for an unknown name.
DeterministicMethod deterministic_method(const std::string& name);
// A planner by name: an OMPL planner (make_planner) or a deterministic one.
std::string canonical_bench_planner(const std::string& name);

}  // namespace foldkit::bench
