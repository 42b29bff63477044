// Single vertices with goals not filtered for reachability (the bench scenes vertexN-any, issue
// 16 item 4): where the time of the complete planner goes. Side by side on the same goals:
//   BM_VertexFallback_Flatten    folding::flatten_single_vertex of the goal alone (the LPs);
//   BM_VertexFallback_Ours       planners::plan, RRTConnect with the Carpenter fallback;
//   BM_VertexFallback_Baseline   planners::plan, RRTConnect alone (fallback off), same limit.
// Counters: solved (share of goals), fallbacks (share that used it), steps (Carpenter LPs).
#include <benchmark/benchmark.h>

#include <string>

#include "foldkit/bench/scenes.hpp"
#include "foldkit/folding/carpenter_spherical.hpp"
#include "foldkit/planners/plan.hpp"

namespace {

constexpr unsigned kGoals = 5;  // seeds 1..kGoals of the scene
constexpr double kTime = 1.0;   // the target's limit, seconds

foldkit::bench::BenchScene scene(int degree, unsigned seed) {
  return foldkit::bench::make_bench_scene("vertex" + std::to_string(degree) + "-any", seed);
}

void BM_VertexFallback_Flatten(benchmark::State& state) {
  const int degree = static_cast<int>(state.range(0));
  double steps = 0.0, runs = 0.0;
  for (auto _ : state)
    for (unsigned g = 1; g <= kGoals; ++g) {
      state.PauseTiming();
      const auto s = scene(degree, g);
      state.ResumeTiming();
      const auto r = foldkit::folding::flatten_single_vertex(*s.pattern, s.goal);
      steps += r.steps;
      runs += 1.0;
    }
  state.counters["steps"] = steps / runs;
}

void plan_all(benchmark::State& state, bool fallback) {
  const int degree = static_cast<int>(state.range(0));
  double solved = 0.0, used = 0.0, runs = 0.0;
  for (auto _ : state)
    for (unsigned g = 1; g <= kGoals; ++g) {
      state.PauseTiming();
      auto s = scene(degree, g);
      s.options.time = kTime;
      s.options.fallback = fallback;
      s.options.seed = g;
      state.ResumeTiming();
      const auto r = foldkit::planners::plan(*s.pattern, s.goal, s.options);
      solved += r.status.ok();
      used += r.fallback;
      runs += 1.0;
    }
  state.counters["solved"] = solved / runs;
  state.counters["fallbacks"] = used / runs;
}

void BM_VertexFallback_Ours(benchmark::State& state) { plan_all(state, true); }
void BM_VertexFallback_Baseline(benchmark::State& state) { plan_all(state, false); }

}  // namespace

BENCHMARK(BM_VertexFallback_Flatten)->Arg(6)->Arg(8)->Arg(12)->Arg(32)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VertexFallback_Ours)->Arg(6)->Arg(8)->Arg(12)->Arg(32)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VertexFallback_Baseline)->Arg(6)->Arg(8)->Arg(12)->Arg(32)->Iterations(1)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
