#pragma once
// `foldkit bench` (docs/BENCHMARKING.md): the built-in scenes (a pattern, a closed start and
// goal, how to plan on it) and the suites of scenes × planners.
#include <memory>
#include <string>
#include <vector>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/planners/plan.hpp"

namespace foldkit::bench {

// A pattern with a closed start and a closed goal, reachable from the start, and how to plan on
// it (space, assignment bounds, search margin; `request.pattern` points into `pattern`).
struct BenchScene {
  std::string name, description;
  std::shared_ptr<const geometry::CreasePattern> pattern;
  planners::PlanRequest request;  // pattern, goal, start (flat when empty), space, bounds, collisions, …
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

}  // namespace foldkit::bench
