#pragma once
/// @file
/// Running a benchmark: the work list and its shards, one OMPL log per scene, our per-run
/// properties, and the error reached against the time allowed.
#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "foldkit/bench/scenes.hpp"
#include "foldkit/geometry/fold_state.hpp"

namespace foldkit::bench {

/// One planner run of the work list: scene and planner index into the suite's (filtered) lists.
struct BenchWorkItem {
  std::size_t scene = 0,    ///< index into the scene list
      planner = 0;          ///< index into the planner list
  unsigned int run = 0;     ///< the run's index for its scene and planner, from 0
};
/// The (scene, planner, run) items in that order; shard K of N (1-based) takes every N-th,
/// starting at the K-th: the N shards together hold each item exactly once.
/// @throws std::invalid_argument unless 1 ≤ shard ≤ shards
std::vector<BenchWorkItem> bench_work(std::size_t scenes, std::size_t planners, unsigned int runs, unsigned int shard,
                                      unsigned int shards);

/// How far a benchmark has got, as passed to BenchOptions::progress after every run and after
/// every scene.
struct BenchProgress {
  std::size_t done = 0,   ///< runs done
      total = 0;          ///< runs in all (of this shard)
  std::string scene,      ///< the current scene
      planner;            ///< the planner of the run just done; "" when `scene_done`
  double elapsed = 0.0;     ///< seconds since the benchmark began
  bool scene_done = false;  ///< the scene is finished (run_bench: its log was just written)
};

/// Options of run_bench() and run_error_vs_time().
struct BenchOptions {
  std::string suite = "quick";  ///< the suite (bench_suite())
  std::vector<std::string> scenes,  ///< scenes to run instead of the suite's; empty: the suite's
      planners;                     ///< planners to run instead of the suite's; empty: the suite's
  /// The space every scene is planned in (planners::parse_space: auto, single-vertex, driving,
  /// projected, atlas, tangent-bundle); "auto" keeps each scene's own. Several, comma-separated:
  /// every planner runs in each, as the entry "PLANNER@SPACE", side by side in the scene's log.
  std::string space = "auto";
  /// Parameters of the sampling planners by OMPL's names ("range", "0.3"), set through each
  /// planner's ParamSet; a planner without one of them is an error.
  std::vector<std::pair<std::string, std::string>> params;
  /// What the sampling planners optimise (planners::parse_objective(), as PlanOptions::objective);
  /// empty: the suite's (BenchSuite::objective), else the default. The default, "length"
  /// without a threshold, is set only on the planners that sample informed; any other on every
  /// sampling planner of the run. Recorded as the log's "objective" property, each run's cost as
  /// "objective cost".
  std::string objective;
  /// The objective's cost threshold (PlanOptions::cost_threshold): an optimising planner stops
  /// once its path meets it (OMPL's planners check it themselves); empty: none is ever met, and
  /// an optimising planner runs its whole time, unless it proves its path optimal (BIT* whose path
  /// costs its admissible heuristic's bound).
  std::optional<double> cost_threshold;
  double time = 1.0;                ///< seconds per run; positive and finite
  unsigned int runs = 10,  ///< runs per planner and scene (per time limit for run_error_vs_time()); at least 1
      seed = 1,            ///< the scenes' goal seed (make_bench_scene()) and OMPL's random seed (0 counts as 1)
      shard = 1,           ///< this shard's number K, 1 ≤ K ≤ shards (run_bench() only)
      shards = 1;          ///< the number of shards N (run_bench() only)
  /// Simplify each solution with OMPL's simplifier before it is measured (what `foldkit plan` does);
  /// off, the properties describe the planner's own path.
  bool simplify = false;
  std::string output_dir;  ///< where run_bench() writes the logs (created when missing); required there
  std::function<void(const BenchProgress&)> progress;  ///< called after every run and every scene; may be empty
};

/// What run_bench() did for one scene.
struct BenchSceneResult {
  std::string scene,  ///< the scene's name
      log;            ///< the log's path ("" when the shard holds no run of the scene)
  std::size_t runs = 0,  ///< runs of the scene in this shard
      solved = 0;        ///< those that solved the problem (OMPL's "solved", exact or approximate)
  /// Planner name → (runs, solved), for the planners that ran.
  std::map<std::string, std::pair<std::size_t, std::size_t>> planners;
};

/// Resolves the suite, scene and planner filters, runs the shard's work list scene by scene
/// (one ompl::tools::Benchmark per group of planners with as many runs; a run stops at its first
/// exact solution or the time limit) and writes one log per scene into output_dir: SCENE.log, or
/// SCENE.shard-K-of-N.log. Silences OMPL's console and seeds its random numbers (OMPL takes the
/// seed once per process).
/// @throws std::invalid_argument for unknown names, a time that is not positive, no runs, shard
///         numbers out of range or no output folder
/// @throws std::runtime_error when a scene has no reachable goal or its way out of the start
///         collides
/// @throws io::WriteError when a log cannot be written
std::vector<BenchSceneResult> run_bench(const BenchOptions& options);

/// Our per-run properties, for a solution path given as fold states from the scene's start.
struct PathMetrics {
  double final_closure_error = 0.0,  ///< loop error of the path's last state, radians
      max_closure_error = 0.0;       ///< largest loop error along the path, radians
  /// Smallest distance (pattern units) between facets that share no vertex, on at most 65 states
  /// along the path (its ends included); +∞ when no pair of facets qualifies
  /// (simulation::min_clearance).
  double min_clearance = 0.0;
  double path_length = 0.0;    ///< Σ Euclidean joint-angle distance, radians
  double rotation = 0.0;       ///< Σ|Δθ| over every crease, radians (the rotation objective's cost)
  double goal_distance = 0.0;  ///< largest joint difference between the path's end and the goal, radians
  std::size_t replay_collisions = 0,  ///< collisions the simulator found replaying the path's CMML
      cmml_events = 0;                ///< events of that CMML (geometry::path_sequence at the scene's PlanOptions::speed)
  bool replay_ok = false;  ///< whether the replay (motor model, collisions on) is valid
};
/// The PathMetrics of `waypoints` (one angle per joint each) on `scene`; all zero for an empty
/// path.
PathMetrics measure_path(const BenchScene& scene, const std::vector<geometry::FoldState>& waypoints);

/// One run of run_error_vs_time(): one CSV row.
struct ErrorVsTimeRow {
  std::string scene,    ///< the scene
      planner;          ///< the planner
  double time_limit = 0.0,  ///< the time allowed, seconds
      time = 0.0;           ///< the time taken, seconds
  unsigned int run = 0;     ///< the run's index for its scene, planner and limit, from 0
  /// "exact", "approximate", "none", or "jumps" (a solution whose path leaves the manifold: not
  /// measured).
  std::string solution;
  double goal_distance = 0.0,        ///< largest joint difference, end to goal, radians (start's without one)
      final_closure_error = 0.0,     ///< loop error at the solution's end, radians; NaN without a usable solution
      max_closure_error = 0.0,       ///< largest loop error along the solution, radians; NaN without one
      path_length = 0.0;             ///< Σ Euclidean joint-angle distance, radians; NaN without one
};
/// Error against the time allowed: every planner of the options on every scene, `runs` runs per
/// time limit; a run stops at its first exact solution, as in the benchmark. What is measured is
/// the best (possibly approximate) solution within the limit. One row per run
/// (docs/BENCHMARKING.md). Sharding does not apply and nothing is written.
/// @param options      suite, scenes, planners, runs, seed and progress (time, shard and shards
///                     are checked as by run_bench() but not used; output_dir is not used)
/// @param time_limits  the limits, seconds, each positive and finite
/// @throws std::invalid_argument for unknown names, a time that is not positive, no runs, shard
///         numbers out of range, no time limits or one that is not positive
/// @throws std::runtime_error when a scene has no reachable goal or its way out of the start
///         collides
std::vector<ErrorVsTimeRow> run_error_vs_time(const BenchOptions& options, const std::vector<double>& time_limits);
/// The rows as CSV: "scene,planner,time_limit_s,run,solution,time_s,goal_distance_rad,
/// final_closure_error_rad,max_closure_error_rad,path_length_rad", non-finite numbers empty.
std::string error_vs_time_csv(const std::vector<ErrorVsTimeRow>& rows);

}  // namespace foldkit::bench
