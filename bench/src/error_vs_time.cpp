// The error-versus-time sweep: each planner of the suite run to several time limits, the
// goal distance and closure error of what it returned (docs/BENCHMARKING.md).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <ompl/geometric/SimpleSetup.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "foldkit/bench/run.hpp"
#include "foldkit/geometry/closure.hpp"
#include "run_scenes.hpp"

namespace foldkit::bench {

using namespace run_detail;  // NOLINT: the scenes, planners and helpers every run shares
namespace og = ompl::geometric;
using planners::PlanSetup;

std::vector<ErrorVsTimeRow> run_error_vs_time(const BenchOptions& o, const std::vector<double>& limits) {
  const Resolved res = resolve(o);
  check_fallback_entries(o, res);
  if (limits.empty()) throw std::invalid_argument("no time limits");
  for (double t : limits)
    if (!(t > 0.0) || !std::isfinite(t)) throw std::invalid_argument("time limits must be positive");
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  ompl::RNG::setSeed(std::max(1u, o.seed));
  const auto t0 = std::chrono::steady_clock::now();
  const std::size_t total = res.scenes.size() * res.planners.size() * limits.size() * o.runs;
  std::size_t done = 0;
  std::vector<ErrorVsTimeRow> rows;
  for (const auto& scene_name : res.scenes) {
    SceneSpaces scenes(o, scene_name);
    for (const auto& name : res.planners) {
      const BenchScene& scene = scenes.for_entry(name).scene;
      const PlanSetup& setup = scenes.for_entry(name).setup;
      const double start_distance = (setup.start.angles - scene.goal.angles).cwiseAbs().maxCoeff();
      for (double limit : limits)
        for (unsigned int run = 0; run < o.runs; ++run) {
          og::SimpleSetup ss(setup.si);
          set_start_and_goal(setup, ss, scene.goal);
          ss.setPlanner(entry_planner(name, scene, setup, o.params, limit));
          if (auto objective = entry_objective(name, setup, res.objective, o.cost_threshold)) ss.setOptimizationObjective(objective);
          ss.setup();
          const auto t1 = std::chrono::steady_clock::now();
          run_planner(setup, ss, limit, o.cost_threshold.has_value());
          ErrorVsTimeRow row;
          row.scene = scene.name;
          row.planner = name;
          row.time_limit = limit;
          row.time = since(t1);
          row.run = run;
          const auto pdef = ss.getProblemDefinition();
          const auto states = solution_states(setup, scene, pdef);
          row.solution = !pdef->hasSolution() ? "none" : pdef->hasApproximateSolution() ? "approximate" : "exact";
          if (states) {
            const geometry::ClosureSystem& system = *setup.system;
            row.goal_distance = (states->back().angles - scene.goal.angles).cwiseAbs().maxCoeff();
            row.final_closure_error = system.max_error(states->back());
            for (std::size_t i = 0; i < states->size(); ++i) {
              row.max_closure_error = std::max(row.max_closure_error, system.max_error((*states)[i]));
              if (i > 0) row.path_length += ((*states)[i].angles - (*states)[i - 1].angles).norm();
            }
          } else {
            // No solution (or one that jumps): nothing gained; the error stays the start's.
            row.goal_distance = start_distance;
            row.final_closure_error = row.max_closure_error = row.path_length = std::numeric_limits<double>::quiet_NaN();
            if (pdef->hasSolution()) row.solution = "jumps";
          }
          rows.push_back(row);
          ++done;
          if (o.progress) o.progress({done, total, scene.name, name, since(t0), false});
        }
    }
    if (o.progress) o.progress({done, total, scene_name, "", since(t0), true});
  }
  return rows;
}

std::string error_vs_time_csv(const std::vector<ErrorVsTimeRow>& rows) {
  std::ostringstream out;
  out << "scene,planner,time_limit_s,run,solution,time_s,goal_distance_rad,final_closure_error_rad,"
         "max_closure_error_rad,path_length_rad\n";
  for (const auto& r : rows)
    out << r.scene << ',' << r.planner << ',' << num(r.time_limit) << ',' << r.run << ',' << r.solution << ','
        << num(r.time) << ',' << num(r.goal_distance) << ',' << num(r.final_closure_error) << ','
        << num(r.max_closure_error) << ',' << num(r.path_length) << '\n';
  return out.str();
}

}  // namespace foldkit::bench
