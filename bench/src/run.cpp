// Runs a suite: one ompl::tools::Benchmark per (scene, planner) of the shard's work list, our
// properties added after every run (setPostRunEvent), the planners' logs joined into one log per
// scene.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/tools/benchmark/Benchmark.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "foldkit/io/atomic_write.hpp"
#include "foldkit/bench/deterministic_planner.hpp"
#include "foldkit/bench/log.hpp"
#include "foldkit/bench/run.hpp"
#include "foldkit/planners/objectives.hpp"
#include "foldkit/planners/plan_setup.hpp"
#include "foldkit/simulation/clearance.hpp"
#include "foldkit/simulation/simulate.hpp"
#include "run_scenes.hpp"

namespace foldkit::bench {

using planners::PlanSetup;

namespace ob = ompl::base;
namespace og = ompl::geometric;
using geometry::FoldState;

std::vector<BenchWorkItem> bench_work(std::size_t scenes, std::size_t planners, unsigned int runs, unsigned int shard,
                                      unsigned int shards) {
  if (shards == 0 || shard == 0 || shard > shards)
    throw std::invalid_argument("shard " + std::to_string(shard) + "/" + std::to_string(shards) + " is not K/N with 1 ≤ K ≤ N");
  std::vector<BenchWorkItem> items;
  std::size_t i = 0;
  for (std::size_t s = 0; s < scenes; ++s)
    for (std::size_t p = 0; p < planners; ++p)
      for (unsigned int r = 0; r < runs; ++r, ++i)
        if (i % shards == shard - 1) items.push_back({s, p, r});
  return items;
}

PathMetrics measure_path(const BenchScene& scene, const std::vector<FoldState>& waypoints) {
  PathMetrics m;
  if (waypoints.empty()) return m;
  const geometry::CreasePattern& p = *scene.pattern;
  const geometry::ClosureSystem system(p);
  for (std::size_t i = 0; i < waypoints.size(); ++i) {
    m.max_closure_error = std::max(m.max_closure_error, system.max_error(waypoints[i]));
    if (i > 0) m.path_length += (waypoints[i].angles - waypoints[i - 1].angles).norm();
    if (i > 0) m.rotation += (waypoints[i].angles - waypoints[i - 1].angles).lpNorm<1>();
  }
  m.final_closure_error = system.max_error(waypoints.back());
  m.goal_distance = (waypoints.back().angles - scene.goal.angles).cwiseAbs().maxCoeff();
  // Clearance on at most 65 states along the path (its ends included): FCL distances are costly.
  std::vector<FoldState> sample;
  const std::size_t stride = std::max<std::size_t>(1, (waypoints.size() + 63) / 64);
  for (std::size_t i = 0; i < waypoints.size(); i += stride) sample.push_back(waypoints[i]);
  if (sample.size() == 0 || (sample.back().angles - waypoints.back().angles).cwiseAbs().maxCoeff() > 0.0)
    sample.push_back(waypoints.back());
  m.min_clearance = simulation::min_clearance(p, sample);
  const geometry::FoldSequence seq = geometry::path_sequence(p, waypoints, scene.options.speed, p.title());
  m.cmml_events = seq.events.size();
  simulation::SimulationOptions so;
  so.collisions = true;
  const simulation::SimulationReport replay = simulation::simulate(p, seq, so);
  m.replay_collisions = replay.collision_count;
  m.replay_ok = replay.status.ok();
  return m;
}

namespace {

using run_detail::num;

// OMPL records some run properties only for some runs (the solution's, when there is one); the
// list is fixed here so that every log of a planner, and so every shard, has the same columns.
std::vector<std::string> ompl_run_properties(bool simplify) {
  std::vector<std::string> p = {
      "approximate solution BOOLEAN", "correct solution BOOLEAN", "correct solution strict BOOLEAN",
      "graph motions INTEGER", "graph states INTEGER", "memory REAL", "solution clearance REAL",
      "solution difference REAL", "solution length REAL", "solution segments INTEGER", "solution smoothness REAL",
      "solved BOOLEAN", "status ENUM", "time REAL", "valid segment fraction REAL", "approx goal distance REAL"};
  if (simplify)
    for (const char* s : {"simplification time REAL", "simplified correct solution BOOLEAN",
                          "simplified correct solution strict BOOLEAN", "simplified solution clearance REAL",
                          "simplified solution length REAL", "simplified solution segments INTEGER",
                          "simplified solution smoothness REAL"})
      p.emplace_back(s);
  return p;
}

const std::vector<std::string>& our_run_properties() {
  static const std::vector<std::string> p = {
      "run index INTEGER",         "final closure error REAL", "max closure error REAL", "min clearance REAL",
      "replay collisions INTEGER", "replay valid BOOLEAN",     "joint path length REAL", "cmml events INTEGER",
      "goal distance REAL",        "path jumps BOOLEAN",       "joint rotation REAL",    "objective cost REAL",
      "solution cost REAL"};
  return p;
}

void normalise_properties(BenchLog::Planner& p, bool simplify) {
  std::vector<std::string> all = p.properties;
  const std::vector<std::string> ompl = ompl_run_properties(simplify);
  for (const auto* list : {&ompl, &our_run_properties()})
    for (const auto& name : *list)
      if (std::find(all.begin(), all.end(), name) == all.end()) all.push_back(name);
  std::sort(all.begin(), all.end());
  for (auto& run : p.runs) {
    std::vector<std::string> values;
    for (const auto& name : all) {
      const auto it = std::find(p.properties.begin(), p.properties.end(), name);
      values.push_back(it == p.properties.end() ? "" : run[static_cast<std::size_t>(it - p.properties.begin())]);
    }
    run = std::move(values);
  }
  p.properties = std::move(all);
}

std::string clean(std::string v) {
  // A value must not hold "; " (the run separator) nor a line break.
  for (std::size_t i; (i = v.find("; ")) != std::string::npos;) v.replace(i, 2, ", ");
  std::replace(v.begin(), v.end(), '\n', ' ');
  return v;
}

// SimpleSetup::print, which Benchmark writes into every log header, estimates the space's
// properties by sampling (valid-state probability, motion length, sampling speed): seconds on a
// constrained space with collision checks, for each Benchmark. The logs keep the settings, the
// start and the goal.
class BenchSetup : public og::SimpleSetup {
 public:
  using og::SimpleSetup::SimpleSetup;
  void print(std::ostream& out) const override {
    out << "foldkit bench: the space's properties are not estimated\n";
    si_->printSettings(out);
    pdef_->print(out);
  }
};

}  // namespace

namespace {

using namespace run_detail;  // NOLINT: the scenes, planners and helpers every run shares

// Our per-run properties, added to the run's row after each run (OMPL's post-run event).
void add_path_properties(const PlanSetup& setup, const BenchScene& scene, const planners::Objective& objective,
                         const ob::PlannerPtr& planner, ompl::tools::Benchmark::RunProperties& run) {
  const ob::ProblemDefinitionPtr& pdef = planner->getProblemDefinition();
  const auto states = solution_states(setup, scene, pdef);
  if (pdef->hasSolution()) run["path jumps BOOLEAN"] = states ? "0" : "1";
  // The solution's cost as the planner counts it (the objective on its own states, as its "best
  // cost" progress property): the last point of the run's cost against time, and the only one
  // for a planner that reports no best cost while it runs (FMT). Exact solutions only: an
  // approximate one (AIT* keeps the state nearest the goal) costs next to nothing.
  if (pdef->hasExactSolution() && pdef->hasOptimizationObjective())
    run["solution cost REAL"] = num(pdef->getSolutionPath()->cost(pdef->getOptimizationObjective()).value());
  if (!states) return;
  const PathMetrics m = measure_path(scene, *states);
  run["final closure error REAL"] = num(m.final_closure_error);
  run["max closure error REAL"] = num(m.max_closure_error);
  run["min clearance REAL"] = num(m.min_clearance);
  run["replay collisions INTEGER"] = std::to_string(m.replay_collisions);
  run["replay valid BOOLEAN"] = m.replay_ok ? "1" : "0";
  run["joint path length REAL"] = num(m.path_length);
  run["joint rotation REAL"] = num(m.rotation);
  // The objective's cost on the whole path, every crease counted (planners::path_cost); for
  // clearance the same as "min clearance" but on every state.
  run["objective cost REAL"] = num(planners::path_cost(objective, *scene.pattern, *states));
  run["cmml events INTEGER"] = std::to_string(m.cmml_events);
  run["goal distance REAL"] = num(m.goal_distance);
}

// One scene of a benchmark shard: its planners' runs, grouped by run count into Benchmarks, and
// its log.
class SceneRun {
 public:
  SceneRun(const BenchOptions& o, const Resolved& res, const std::vector<BenchWorkItem>& work, std::size_t si,
           std::chrono::steady_clock::time_point t0, std::size_t& done)
      : o_(o), res_(res), work_(work), t0_(t0), done_(done), runs_of_(res.planners.size()),
        objective_(res.objective) {
    result_.scene = res.scenes[si];
    for (const auto& w : work)
      if (w.scene == si) runs_of_[w.planner].push_back(w.run);
  }

  BenchSceneResult run() {
    if (std::all_of(runs_of_.begin(), runs_of_.end(), [](const auto& v) { return v.empty(); })) return result_;
    scenes_.emplace(o_, result_.scene);
    // The planners, in the suite's order; those of one space with as many runs in this shard
    // share one Benchmark (each Benchmark estimates the space's properties for its log header).
    std::vector<std::string> space_names;
    for (const auto& entry : res_.planners) {
      const SceneSpaces::InSpace& in = scenes_->for_entry(entry);
      objects_.push_back(entry_planner(entry, in.scene, in.setup, o_.params, o_.time));
      names_ += (names_.empty() ? "" : ",") + objects_.back()->getName();
      const std::string name = in.setup.plan_space->name();
      if (std::find(space_names.begin(), space_names.end(), name) == space_names.end()) space_names.push_back(name);
    }
    std::string spaces;
    for (const auto& n : space_names) spaces += (spaces.empty() ? "" : ",") + n;
    std::map<std::pair<std::string, std::size_t>, std::vector<std::size_t>> groups;  // (space, run count) → planners
    for (std::size_t pi = 0; pi < res_.planners.size(); ++pi)
      if (!runs_of_[pi].empty()) groups[{planner_and_space(res_.planners[pi]).second, runs_of_[pi].size()}].push_back(pi);
    for (const auto& [key, members] : groups)
      add_part(run_group(scenes_->for_entry(res_.planners[members.front()]), key.second, members, spaces), members);
    write_log();
    return result_;
  }

 private:
  BenchLog run_group(const SceneSpaces::InSpace& in, std::size_t count, const std::vector<std::size_t>& members,
                     const std::string& spaces) {
    const BenchScene& scene = in.scene;
    const PlanSetup& setup = in.setup;
    BenchSetup ss(setup.si);
    set_start_and_goal(setup, ss, scene.goal);
    // OMPL's Benchmark sets every planner up on one problem before the first run: when one of the
    // group draws informed samples, the whole group gets its objective (PRM and LazyPRM then run
    // their whole time, as PRM* does; docs/PLANNING.md, "Planners").
    for (std::size_t pi : members)
      if (auto objective = entry_objective(res_.planners[pi], setup, objective_, o_.cost_threshold)) {
        ss.setOptimizationObjective(objective);
        break;
      }
    ompl::tools::Benchmark bench(ss, scene.name);
    bench.addExperimentParameter("suite", "STRING", clean(res_.suite->name));
    bench.addExperimentParameter("scene", "STRING", clean(scene.name));
    bench.addExperimentParameter("description", "STRING", clean(scene.description));
    bench.addExperimentParameter("space", "STRING", spaces);
    bench.addExperimentParameter("creases", "INTEGER", std::to_string(scene.pattern->joints().size()));
    bench.addExperimentParameter("scene_seed", "INTEGER", std::to_string(o_.seed));
    bench.addExperimentParameter("shard", "STRING", std::to_string(o_.shard) + "/" + std::to_string(o_.shards));
    bench.addExperimentParameter("planners", "STRING", names_);
    bench.addExperimentParameter("simplify", "BOOLEAN", o_.simplify ? "1" : "0");
    bench.addExperimentParameter("objective", "STRING", objective_.name());
    // Only when given: ompl_benchmark_statistics cannot read an experiment property without a value.
    if (o_.cost_threshold) bench.addExperimentParameter("cost_threshold", "REAL", num(*o_.cost_threshold));
    std::map<const ob::Planner*, std::size_t> index_of, next;
    for (std::size_t pi : members) {
      bench.addPlanner(objects_[pi]);
      index_of[objects_[pi].get()] = pi;
    }
    // A planner loop that ignores the termination condition (RRTConnect's connect loop with a tiny
    // `range`) still ends: every state is invalid from twice the time limit on (FoldValidity::
    // expired), leaving the limit itself, and the simplification after it, undisturbed.
    std::optional<statespaces::FoldValidity::TimeLimit> limit;
    bench.setPreRunEvent([&](const ob::PlannerPtr&) {
      limit.reset();
      limit.emplace(*setup.validity, 2.0 * o_.time);
    });
    bench.setPostRunEvent([&](const ob::PlannerPtr& planner, ompl::tools::Benchmark::RunProperties& run) {
      limit.reset();
      const std::size_t pi = index_of.at(planner.get());
      const auto& indices = runs_of_[pi];
      const unsigned int index = indices[std::min(next[planner.get()]++, indices.size() - 1)];
      run["run index INTEGER"] = std::to_string(index);
      add_path_properties(setup, scene, objective_, planner, run);
      ++done_;
      if (o_.progress) o_.progress({done_, work_.size(), scene.name, res_.planners[pi], since(t0_), false});
    });
    const ompl::tools::Benchmark::Request req(o_.time, 4096.0, static_cast<unsigned int>(count), 0.05, false, false,
                                              o_.simplify);
    bench.benchmark(req);
    limit.reset();
    std::ostringstream text;
    bench.saveResultsToStream(text);
    return parse_bench_log(text.str(), scene.name);
  }

  // Counts the part's runs and solutions, and adds its planners to the scene's log (the first
  // part gives the header).
  void add_part(BenchLog part, const std::vector<std::size_t>& members) {
    for (std::size_t k = 0; k < part.planners.size(); ++k) {
      auto& p = part.planners[k];
      normalise_properties(p, o_.simplify);
      const auto col = static_cast<std::size_t>(
          std::find(p.properties.begin(), p.properties.end(), "solved BOOLEAN") - p.properties.begin());
      std::size_t solved = 0;
      for (const auto& run : p.runs) solved += col < run.size() && run[col] == "1";
      result_.planners[res_.planners[members[k]]] = {p.runs.size(), solved};
      result_.runs += p.runs.size();
      result_.solved += solved;
    }
    if (!have_header_) {
      auto planners = std::move(part.planners);
      log_ = std::move(part);
      log_.planners = std::move(planners);
      log_.run_count = o_.runs;
      have_header_ = true;
    } else {
      log_.total_duration += part.total_duration;
      for (auto& p : part.planners) log_.planners.push_back(std::move(p));
    }
  }

  void write_log() {
    // Back into the suite's order.
    std::vector<std::string> order;
    for (const auto& obj : objects_) order.push_back("geometric_" + obj->getName());
    std::stable_sort(log_.planners.begin(), log_.planners.end(), [&](const BenchLog::Planner& x, const BenchLog::Planner& y) {
      return std::find(order.begin(), order.end(), x.name) < std::find(order.begin(), order.end(), y.name);
    });
    const std::string file =
        o_.shards == 1 ? scenes_->scene().name + ".log"
                       : scenes_->scene().name + ".shard-" + std::to_string(o_.shard) + "-of-" + std::to_string(o_.shards) + ".log";
    result_.log = (std::filesystem::path(o_.output_dir) / file).string();
    io::write_file_atomic(result_.log, write_bench_log(log_));
    if (o_.progress) o_.progress({done_, work_.size(), scenes_->scene().name, "", since(t0_), true});
  }

  const BenchOptions& o_;
  const Resolved& res_;
  const std::vector<BenchWorkItem>& work_;
  const std::chrono::steady_clock::time_point t0_;
  std::size_t& done_;
  std::vector<std::vector<unsigned int>> runs_of_;  // per planner: the run indices of this shard
  const planners::Objective objective_;
  BenchSceneResult result_;
  std::optional<SceneSpaces> scenes_;
  std::vector<ob::PlannerPtr> objects_;
  std::string names_;
  BenchLog log_;
  bool have_header_ = false;
};

}  // namespace

std::vector<BenchSceneResult> run_bench(const BenchOptions& o) {
  const Resolved res = resolve(o);
  const auto work = bench_work(res.scenes.size(), res.planners.size(), o.runs, o.shard, o.shards);
  if (o.output_dir.empty()) throw std::invalid_argument("no output folder");
  check_fallback_entries(o, res);
  std::filesystem::create_directories(o.output_dir);
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  ompl::RNG::setSeed(std::max(1u, o.seed));  // takes effect once per process (OMPL's rule)
  const auto t0 = std::chrono::steady_clock::now();
  std::size_t done = 0;
  std::vector<BenchSceneResult> results;
  for (std::size_t si = 0; si < res.scenes.size(); ++si) results.push_back(SceneRun(o, res, work, si, t0, done).run());
  return results;
}

}  // namespace foldkit::bench
