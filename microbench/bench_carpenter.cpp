// Planar Carpenter's rule: straighten seeded random 100–1,000-link chains and pivot-algorithm
// lattice walks of 100–1,000 links (3,000 ran over half an hour) (constraint generation:
// the LP starts with near pairs and takes violated struts as they show, warm-started; the closed-
// form end takes over once the chain is monotone; docs/CARPENTER.md has the figures), and, side by
// side on smaller chains, the same planner with all O(n²) struts in every LP
// (BM_Carpenter_Ours vs BM_Carpenter_AllStruts on identical chains). The 1,000-link case used to
// look like a planner that never finished: it was the chain generator, which restarted from
// scratch at every dead end (see random_chain).
#include <benchmark/benchmark.h>

#include "carpenter_inputs.hpp"
#include "foldkit/folding/carpenter.hpp"

namespace {

using namespace foldkit::folding;

void run(benchmark::State& state, const PlanarChain& input, bool all_struts) {
  CarpenterPlanarOptions options;
  options.all_struts = all_struts;
  options.frame_stride = 10;  // the per-frame O(n²) distance bookkeeping is not the planner
  CarpenterPlanarResult r;
  for (auto _ : state) {
    r = carpenter_planar(input, options);
    benchmark::DoNotOptimize(r.frames.data());
  }
  if (!r.status.ok()) state.SkipWithError(r.status.message.c_str());
  state.counters["steps"] = static_cast<double>(r.steps);
  state.counters["lp_solves"] = static_cast<double>(r.lp_solves);
  state.counters["max_struts"] = static_cast<double>(r.max_struts);
  state.counters["max_length_error"] = r.max_length_error;
  state.counters["min_distance_growth"] = r.min_distance_growth;
}

void run(benchmark::State& state, bool all_struts) {
  run(state, {foldkit::microbench::random_chain(static_cast<int>(state.range(0)), 1), false}, all_struts);
}

void BM_Carpenter_Straighten(benchmark::State& state) { run(state, false); }

// Issue 20's own input: self-avoiding lattice walks by the pivot algorithm, jittered by 0.1.
void BM_Carpenter_StraightenLatticeWalk(benchmark::State& state) {
  run(state, {foldkit::microbench::random_lattice_walk(static_cast<int>(state.range(0)), 1), false}, false);
}

void BM_Carpenter_Convexify(benchmark::State& state) {
  run(state, {foldkit::microbench::random_star(static_cast<int>(state.range(0)), 1), true}, false);
}
// Issue 20's polygon to convexify, 100–1,000 vertices (carpenter_inputs.hpp).
BENCHMARK(BM_Carpenter_Convexify)->Arg(100)->Arg(200)->Arg(400)->Arg(1000)->Iterations(1)->Unit(benchmark::kSecond);
void BM_Carpenter_Ours(benchmark::State& state) { run(state, false); }
void BM_Carpenter_AllStruts(benchmark::State& state) { run(state, true); }

BENCHMARK(BM_Carpenter_Straighten)->Arg(100)->Arg(200)->Arg(400)->Arg(1000)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_Carpenter_StraightenLatticeWalk)->Arg(100)->Arg(300)->Arg(1000)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_Carpenter_Ours)->Arg(50)->Arg(100)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Carpenter_AllStruts)->Arg(50)->Arg(100)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
