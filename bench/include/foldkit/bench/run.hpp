#pragma once
// Running a benchmark: the work list and its shards, one OMPL log per scene, our per-run
// properties, and the error reached against the time allowed.
#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "foldkit/bench/scenes.hpp"
#include "foldkit/geometry/fold_state.hpp"

namespace foldkit::bench {

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

}  // namespace foldkit::bench
