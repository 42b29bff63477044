#pragma once
// What a benchmark run and the error-versus-time sweep share (run.cpp, error_vs_time.cpp),
// private to foldkit::bench: the suite resolved to scenes and planner entries, each scene's
// setups by space, the planners of the entries, and the solution's fold states.
#include <chrono>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <ompl/base/Planner.h>
#include <ompl/base/ProblemDefinition.h>

#include "foldkit/bench/run.hpp"
#include "foldkit/bench/scenes.hpp"
#include "foldkit/planners/objectives.hpp"
#include "foldkit/planners/plan_setup.hpp"

namespace foldkit::bench::run_detail {

// A number as a log or CSV value; empty (NULL for ompl_benchmark_statistics) when not finite.
std::string num(double v);

// The planner of a list entry, "NAME" or "NAME@SPACE" (`setup` is the scene's in that space),
// named as the entry; "X+Carpenter" gives X a quarter of `time` (planners::kSamplerShare) before
// the single-vertex fallback, as plan() does.
ompl::base::PlannerPtr entry_planner(const std::string& entry, const BenchScene& scene, const planners::PlanSetup& setup,
                                     const std::vector<std::pair<std::string, std::string>>& params, double time);
// The objective an entry's planner gets on its problem: for the default objective (length, no
// threshold) planners::informed_objective of the planner (X's for "X+Carpenter"), null for the
// rest; any other objective (the run's, Resolved::objective) for every sampling planner; null
// for the deterministic planners.
ompl::base::OptimizationObjectivePtr entry_objective(const std::string& entry, const planners::PlanSetup& setup,
                                                     const planners::Objective& objective, std::optional<double> threshold);

// The fold states of the problem definition's best solution, from the scene's start.
std::optional<std::vector<geometry::FoldState>> solution_states(const planners::PlanSetup& setup, const BenchScene& scene,
                                                                const ompl::base::ProblemDefinitionPtr& pdef);

// The suite of the options, its scenes and planner entries, and the run's objective: the
// options', else the suite's, else the default (checked: names, spaces, parameters, objective,
// time, runs, shard).
struct Resolved {
  const BenchSuite* suite = nullptr;
  std::vector<std::string> scenes, planners;
  planners::Objective objective;
};
Resolved resolve(const BenchOptions& o);

// A scene of the run (its goal drawn once) and its setup in each space that the planner entries
// name, made when first asked for.
class SceneSpaces {
 public:
  /// The scene and its setup in one space.
  struct InSpace {
    BenchScene scene;
    planners::PlanSetup setup;
  };
  SceneSpaces(const BenchOptions& o, const std::string& name);
  const BenchScene& scene() const { return base_; }
  // In the space of the planner entry ("NAME@SPACE"; the options' or the scene's own without '@').
  const InSpace& for_entry(const std::string& entry);

 private:
  BenchScene base_;
  std::map<std::string, InSpace> spaces_;
};

// "X+Carpenter" needs each scene in the single-vertex space: checked on every scene before
// anything is written (std::invalid_argument).
void check_fallback_entries(const BenchOptions& o, const Resolved& r);

// Seconds since t0.
double since(std::chrono::steady_clock::time_point t0);

}  // namespace foldkit::bench::run_detail
