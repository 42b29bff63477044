#pragma once
/// @file
/// `foldkit bench` (docs/BENCHMARKING.md): the built-in scenes (a pattern, a closed start and
/// goal, how to plan on it) and the suites of scenes × planners.
#include <memory>
#include <string>
#include <vector>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/planners/plan.hpp"

/// The benchmark suite of `foldkit bench`: scenes, deterministic methods run as OMPL planners,
/// runs, and OMPL benchmark logs.
namespace foldkit::bench {

/// A pattern with a closed start and a closed goal, reachable from the start, and how to plan on
/// it (space, assignment bounds, search margin).
struct BenchScene {
  std::string name,         ///< the scene's name, as bench_scene_names() lists it
      description;          ///< what the scene is, in words
  std::shared_ptr<const geometry::CreasePattern> pattern;  ///< the pattern
  geometry::FoldState goal;  ///< closed, one angle per joint, radians
  /// Start (flat when empty), space, bounds, collisions (on), replay (off), …
  planners::PlanOptions options;
};

/// A named set of scenes and planners run together.
struct BenchSuite {
  std::string name,         ///< the suite's name: "quick", "full", "spaces", "vertex-complete", "miura-scale" or "optimal"
      description;          ///< what it is for, in words
  std::vector<std::string> scenes,  ///< scene names (bench_scene_names())
      planners;                     ///< planner names: OMPL planners and deterministic methods
  /// What its sampling planners optimise unless BenchOptions::objective names another
  /// (planners::parse_objective()); empty: the default, path length.
  std::string objective;
};

/// The suites: "quick" (three small scenes, RRTConnect and ProjectedLine: seconds), "full"
/// (every scene but those of the issue-16 suites, seven sampling planners and every
/// deterministic method), "spaces" (the scenes of the side-by-side comparison of spaces),
/// "vertex-complete" (unfiltered single-vertex goals: RRTConnect, RRTConnect+Carpenter,
/// SphericalCarpenter), "miura-scale" (Miura 10x10 … 40x40 to zig-zags at ±80°) and "optimal"
/// (the optimising planners RRT*, PRM*, BIT*, ABIT*, AIT*, RRT#, FMT and CForest on Miura 10x10,
/// waterbomb 4x4, the Resch pattern and a degree-12 vertex, optimising total crease rotation).
const std::vector<BenchSuite>& bench_suites();
/// The suite named `name`.
/// @throws std::invalid_argument naming the known suites for any other name
const BenchSuite& bench_suite(const std::string& name);
/// Every built-in scene: vertex4-random … vertex32-symmetric (degrees 4, 8, 12, 16, 32), vertex6-any … vertex32-any (goals
/// not filtered for reachability), boat, miura4x4, miura10x10, waterbomb, cube-sheet,
/// corner-cube, miura20x20, waterbomb4x4, bird-base and resch (imported FOLD files), and
/// miura10x10-80 … miura40x40-80.
std::vector<std::string> bench_scene_names();
/// The scene with its goal drawn from `seed` and the scene's name (std::mt19937, seeded by a
/// hash that does not depend on the compiler; the distributions drawn from it are the standard
/// library's, so the same seed gives the same goal wherever the same standard library is used).
/// A goal is kept only when the straight way to it from the start is closed, within the bounds
/// and free of crossing facets. corner-cube's goal does not depend on the seed.
/// @throws std::invalid_argument for an unknown name
/// @throws std::runtime_error when no reachable goal is found within the scene's tries
BenchScene make_bench_scene(const std::string& name, unsigned int seed);

}  // namespace foldkit::bench
