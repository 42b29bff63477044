#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <ompl/base/Planner.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/planners/plan.hpp"
#include "foldkit/statespaces/validity.hpp"

// `foldkit bench` (docs/BENCHMARKING.md): built-in scenes, suites of scenes × planners, the runs
// through ompl::tools::Benchmark with our own per-run properties, OMPL benchmark logs (read,
// written, merged across shards) and the error reached against the time allowed.
namespace foldkit::planners {

// ---- scenes and suites (bench_suite.cpp) ----

// A pattern with a closed start and a closed goal, reachable from the start, and how to plan on
// it (space, assignment bounds, search margin; `request.pattern` points into `pattern`).
struct BenchScene {
  std::string name, description;
  std::shared_ptr<const geometry::CreasePattern> pattern;
  PlanRequest request;  // pattern, goal, start (flat when empty), space, bounds, collisions, …
};

struct BenchSuite {
  std::string name, description;
  std::vector<std::string> scenes, planners;
};

// "quick" (a few small scenes, 2 planners: seconds) and "full" (every scene, sampling and
// deterministic planners).
const std::vector<BenchSuite>& bench_suites();
// std::invalid_argument naming the known suites for any other name.
const BenchSuite& bench_suite(const std::string& name);
// Every built-in scene: vertex4-random … vertex32-symmetric, boat, miura4x4, miura10x10,
// waterbomb, cube-sheet, corner-cube.
std::vector<std::string> bench_scene_names();
// The scene with its goal drawn from `seed` (std::mt19937: the same seed gives the same goal on
// every machine). std::invalid_argument for an unknown name.
BenchScene make_bench_scene(const std::string& name, unsigned int seed);

// ---- deterministic planners inside ompl::tools::Benchmark (bench_suite_deterministic.cpp) ----

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

// ---- OMPL benchmark logs (bench_log.cpp) ----

// One log as ompl::tools::Benchmark writes it (OMPL 1.5), kept close to the text so that it can
// be written back unchanged; `ompl_benchmark_statistics` reads what write_bench_log writes.
struct BenchLog {
  struct Planner {
    std::string name;
    std::vector<std::string> common;      // "key = value"
    std::vector<std::string> properties;  // "name TYPE"
    std::vector<std::vector<std::string>> runs;  // one value per property ("" when missing)
    std::vector<std::string> progress_properties;
    std::vector<std::string> progress_runs;  // one line per run
  };
  std::string version = "OMPL 1.5.2";  // library and version (Debian's OMPL writes none)
  std::string experiment;
  std::vector<std::pair<std::string, std::string>> parameters;  // "name TYPE", value
  std::string host, start_time, setup, cpu_info, seed;
  double max_time = 0.0, max_mem = 0.0, total_duration = 0.0;
  long run_count = 0;
  std::vector<std::string> enums;  // "name|value0|value1|…"
  std::vector<Planner> planners;

  const std::string* parameter(const std::string& name_and_type) const;
};

// std::invalid_argument "FILE:LINE: what is wrong" for text that is not such a log.
BenchLog parse_bench_log(const std::string& text, const std::string& file = "log");
std::string write_bench_log(const BenchLog& log);
// Joins shard logs of one scene: runs concatenated per planner (ordered by "run index" when
// present), the header of the first, durations summed. std::invalid_argument when the logs are
// not shards of one experiment (experiment, planners, properties, settings, seed, time limit or
// shard count differ; a shard twice or missing).
BenchLog merge_bench_logs(const std::vector<BenchLog>& shards, const std::vector<std::string>& files);

// ---- running (bench_run*.cpp) ----

// One planner run of the work list: scene and planner index into the suite's (filtered) lists.
struct BenchWorkItem {
  std::size_t scene = 0, planner = 0;
  unsigned int run = 0;
};
// The (scene, planner, run) items in that order; shard K of N (1-based) takes every N-th,
// starting at the K-th: the N shards together hold each item exactly once.
std::vector<BenchWorkItem> bench_work(std::size_t scenes, std::size_t planners, unsigned int runs, unsigned int shard,
                                      unsigned int shards);

struct BenchProgress {
  std::size_t done = 0, total = 0;  // runs
  std::string scene, planner;
  double elapsed = 0.0;     // seconds since the benchmark began
  bool scene_done = false;  // the scene's log was just written
};

struct BenchOptions {
  std::string suite = "quick";
  std::vector<std::string> scenes, planners;  // empty: the suite's
  double time = 1.0;                          // seconds per run
  unsigned int runs = 10, seed = 1, shard = 1, shards = 1;
  // Simplify each solution with OMPL's simplifier before it is measured (what `foldkit plan` does);
  // off, the properties describe the planner's own path.
  bool simplify = false;
  std::string output_dir;
  std::function<void(const BenchProgress&)> progress;
};

struct BenchSceneResult {
  std::string scene, log;  // the log's path ("" when the shard holds no run of the scene)
  std::size_t runs = 0, solved = 0;
  std::map<std::string, std::pair<std::size_t, std::size_t>> planners;  // name → (runs, solved)
};

// Resolves the suite, scene and planner filters (std::invalid_argument for unknown names or
// shard numbers out of range), runs the shard's work list scene by scene and writes one log per
// scene into output_dir: SCENE.log, or SCENE.shard-K-of-N.log.
std::vector<BenchSceneResult> run_bench(const BenchOptions& options);

// Our per-run properties, for a solution path given as fold states from the scene's start.
struct PathMetrics {
  double final_closure_error = 0.0, max_closure_error = 0.0;  // radians
  double min_clearance = 0.0;  // smallest distance between facets that share no vertex, along the path
  double path_length = 0.0;    // Σ Euclidean joint-angle distance, radians
  double goal_distance = 0.0;  // largest joint difference between the path's end and the goal, radians
  std::size_t replay_collisions = 0, cmml_events = 0;
  bool replay_ok = false;
};
PathMetrics measure_path(const BenchScene& scene, const std::vector<geometry::FoldState>& waypoints);


// Error against the time allowed: every planner of the options on every scene, `runs` runs per
// time limit; a run stops at its first exact solution, as in the benchmark. What is measured is
// the best (possibly approximate) solution within the limit. One CSV row per run
// (docs/BENCHMARKING.md). Sharding does not apply.
struct ErrorVsTimeRow {
  std::string scene, planner;
  double time_limit = 0.0, time = 0.0;
  unsigned int run = 0;
  std::string solution;  // "exact", "approximate", "none"
  double goal_distance = 0.0, final_closure_error = 0.0, max_closure_error = 0.0, path_length = 0.0;
};
std::vector<ErrorVsTimeRow> run_error_vs_time(const BenchOptions& options, const std::vector<double>& time_limits);
std::string error_vs_time_csv(const std::vector<ErrorVsTimeRow>& rows);

}  // namespace foldkit::planners
