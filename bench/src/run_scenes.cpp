// The suite resolved, each scene's setups by space, the planners of the entries
// (run_scenes.hpp).
#include "run_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

#include <ompl/geometric/PathGeometric.h>

#include "foldkit/bench/deterministic_planner.hpp"
#include "foldkit/planners/carpenter_fallback.hpp"
#include "foldkit/planners/objectives.hpp"
#include "foldkit/planners/planner_factory.hpp"

namespace foldkit::bench::run_detail {

using geometry::FoldState;
using planners::make_plan_setup;
using planners::make_planner;
using planners::path_waypoints;
using planners::PlanSetup;
namespace ob = ompl::base;
namespace og = ompl::geometric;

std::string num(double v) {
  if (!std::isfinite(v)) return "";  // ompl_benchmark_statistics stores an empty value as NULL
  std::ostringstream s;
  s.precision(12);
  s << v;
  return s.str();
}

namespace {

// The planner named `name` for the scene; "X+Carpenter" gives X a quarter of `time`
// (planners::kSamplerShare) before the single-vertex fallback, as plan() does.
ob::PlannerPtr bench_planner(const std::string& name, const BenchScene& scene, const PlanSetup& setup,
                             const std::vector<std::pair<std::string, std::string>>& params, double time);

}  // namespace

// The planner of a list entry, "NAME" or "NAME@SPACE" (`setup` is the scene's in that space),
// named as the entry.
ob::PlannerPtr entry_planner(const std::string& entry, const BenchScene& scene, const PlanSetup& setup,
                             const std::vector<std::pair<std::string, std::string>>& params, double time) {
  ob::PlannerPtr p = bench_planner(planner_and_space(entry).first, scene, setup, params, time);
  p->setName(entry);
  return p;
}

// The objective an entry's planner gets on its problem (run_scenes.hpp); "X+Carpenter" is X's.
ob::OptimizationObjectivePtr entry_objective(const std::string& entry, const PlanSetup& setup,
                                             const planners::Objective& objective, std::optional<double> threshold) {
  std::string name = planner_and_space(entry).first;
  if (const std::string inner = fallback_inner(name); !inner.empty()) name = inner;
  if (is_deterministic_planner(name)) return nullptr;
  if (objective.is_default() && !threshold) return planners::informed_objective(name, setup.si, planners::sampling_stop(setup));
  return planners::make_objective(objective, setup, threshold);
}

namespace {

ob::PlannerPtr bench_planner(const std::string& name, const BenchScene& scene, const PlanSetup& setup,
                             const std::vector<std::pair<std::string, std::string>>& params, double time) {
  if (const std::string inner = fallback_inner(name); !inner.empty()) {
    ob::PlannerPtr p = make_planner(inner, setup.si);
    planners::set_planner_params(*p, inner, params);
    return planners::with_carpenter_fallback(setup, *scene.pattern, p, time, scene.options.waypoint_step);
  }
  if (!is_deterministic_planner(name)) {
    ob::PlannerPtr p = make_planner(name, setup.si);
    planners::set_planner_params(*p, name, params);
    return p;
  }
  std::shared_ptr<const planners::PlanSpace> space = setup.plan_space;
  return std::make_shared<DeterministicPlanner>(
      setup.si, name, deterministic_method(name), *scene.pattern, setup.reader,
      [space](const FoldState& f, ob::State* out) { return space->write(f, out); }, setup.prefix, scene.options.waypoint_step);
}

}  // namespace

// The fold states of the problem definition's best solution, from the scene's start.
std::optional<std::vector<FoldState>> solution_states(const PlanSetup& setup, const BenchScene& scene,
                                                      const ob::ProblemDefinitionPtr& pdef) {
  if (!pdef->hasSolution()) return std::nullopt;
  const auto path = std::dynamic_pointer_cast<og::PathGeometric>(pdef->getSolutionPath());
  if (!path || path->getStateCount() == 0) return std::nullopt;
  std::string why;
  return path_waypoints(setup, *path, scene.options, false, &why);
}

Resolved resolve(const BenchOptions& o) {
  Resolved r;
  r.suite = &bench_suite(o.suite);
  r.scenes = o.scenes.empty() ? r.suite->scenes : o.scenes;
  const auto known = bench_scene_names();
  for (const auto& s : r.scenes)
    if (std::find(known.begin(), known.end(), s) == known.end()) make_bench_scene(s, o.seed);  // throws, naming them
  std::vector<std::string> spaces;  // --space A,B,…: every planner in each, side by side in one log
  for (std::size_t i = 0, j; i <= o.space.size(); i = j + 1) {
    j = std::min(o.space.find(',', i), o.space.size());
    spaces.push_back(o.space.substr(i, j - i));
  }
  for (const auto& sp : spaces) planners::parse_space(sp);  // throws, naming the spaces
  for (const auto& p : o.planners.empty() ? r.suite->planners : o.planners) {
    if (spaces.size() == 1) r.planners.push_back(canonical_bench_planner(p));
    for (std::size_t k = 0; spaces.size() > 1 && k < spaces.size(); ++k)
      r.planners.push_back(canonical_bench_planner(p + "@" + spaces[k]));
  }
  if (!(o.time > 0.0) || !std::isfinite(o.time)) throw std::invalid_argument("the time per run must be positive");
  if (o.runs == 0) throw std::invalid_argument("at least one run per planner");
  r.objective = planners::parse_objective(
      !o.objective.empty() ? o.objective : !r.suite->objective.empty() ? r.suite->objective : planners::PlanOptions{}.objective);
  const planners::Objective& objective = r.objective;
  if (o.cost_threshold) planners::check_cost_threshold(*o.cost_threshold, "bench");
  for (const auto& entry : r.planners) {  // before anything is written
    const std::string p = planner_and_space(entry).first;
    if (is_deterministic_planner(p)) continue;
    const std::string sampling = fallback_inner(p).empty() ? p : fallback_inner(p);
    planners::check_planner_params(sampling, o.params);
    if (const std::string why = planners::objective_refusal(sampling, objective); !why.empty())
      throw planners::PlannerRefused(sampling, why);
  }
  if (o.shards == 0 || o.shard == 0 || o.shard > o.shards)
    throw std::invalid_argument("--shard " + std::to_string(o.shard) + "/" + std::to_string(o.shards) +
                                " is not K/N with 1 <= K <= N");
  return r;
}

namespace {

// The scene's space, planner setup and way out of its start; a scene whose way out collides is
// broken (std::runtime_error), since every built-in scene must be plannable.
PlanSetup scene_setup(const BenchScene& scene) {
  PlanSetup setup = make_plan_setup(*scene.pattern, scene.goal, scene.options, true);
  if (!setup.blocked.empty()) throw std::runtime_error("scene " + scene.name + ": " + setup.blocked);
  if (!setup.other_branch.empty()) throw std::runtime_error("scene " + scene.name + ": " + setup.other_branch);
  return setup;
}

}  // namespace

SceneSpaces::SceneSpaces(const BenchOptions& o, const std::string& name) : base_(make_bench_scene(name, o.seed)) {
  if (o.space.find(',') == std::string::npos && o.space != "auto") base_.options.space = planners::parse_space(o.space);
}

const SceneSpaces::InSpace& SceneSpaces::for_entry(const std::string& entry) {
  const std::string space = planner_and_space(entry).second;
  auto it = spaces_.find(space);
  if (it == spaces_.end()) {
    InSpace in{base_, {}};
    if (!space.empty()) in.scene.options.space = planners::parse_space(space);
    in.setup = scene_setup(in.scene);
    it = spaces_.emplace(space, std::move(in)).first;
  }
  return it->second;
}

// "X+Carpenter" needs each scene in the single-vertex space (the fallback is Carpenter's rule on
// the sphere): checked on every scene before anything is written, so that a run never stops
// half-way with some logs written.
void check_fallback_entries(const BenchOptions& o, const Resolved& r) {
  for (const auto& scene : r.scenes) {
    std::optional<SceneSpaces> spaces;
    for (const auto& entry : r.planners) {
      if (fallback_inner(planner_and_space(entry).first).empty()) continue;
      if (!spaces) spaces.emplace(o, scene);
      if (spaces->for_entry(entry).setup.plan_space->fallback() != planners::Fallback::Carpenter)
        throw std::invalid_argument("scene " + scene + ": " + entry +
                                    " needs the single-vertex space (the fallback is Carpenter's rule on the sphere)");
    }
  }
}

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace foldkit::bench::run_detail
