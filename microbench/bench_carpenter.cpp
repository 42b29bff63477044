// Planar Carpenter's rule: straighten seeded random 100–1,000-link chains and pivot-algorithm
// lattice walks, each by the global LP per step (`--method lp`, the baseline: 100–1,000 links;
// 3,000 ran over half an hour) and by the carried field (`--method carried`), side by side at
// 100–1,000 links, and by Streinu's pseudo-triangulation mechanism (`--method pseudo`) (constraint generation:
// the LP starts with near pairs and takes violated struts as they show, warm-started; the closed-
// form end takes over once the chain is monotone; docs/CARPENTER.md has the figures), and, side by
// side on smaller chains, the same planner with all O(n²) struts in every LP
// (BM_Carpenter_Ours vs BM_Carpenter_AllStruts on identical chains). The 1,000-link case used to
// look like a planner that never finished: it was the chain generator, which restarted from
// scratch at every dead end (see random_chain). Also, side by side, what recording one frame
// costs: two generic check_motion() calls (before) against the planner's own figures
// (BM_RecordFrame_Ours: bar lengths alone, vectorised pairs on two threads).
#include <benchmark/benchmark.h>

#include <utility>

#include "../folding/src/carpenter_planar_chain.hpp"
#include "carpenter_inputs.hpp"
#include "foldkit/folding/carpenter.hpp"

namespace {

using namespace foldkit::folding;

void run(benchmark::State& state, const PlanarChain& input, CarpenterPlanarOptions options) {
  options.frame_stride = 10;  // the per-frame O(n²) distance bookkeeping is not the planner
  CarpenterPlanarResult r;
  for (auto _ : state) {
    r = carpenter_planar(input, options);
    benchmark::DoNotOptimize(r.frames.data());
  }
  if (!r.status.ok()) state.SkipWithError(r.status.message.c_str());
  state.counters["steps"] = static_cast<double>(r.steps);
  state.counters["lp_solves"] = static_cast<double>(r.lp_solves);
  state.counters["window_lps"] = static_cast<double>(r.window_lp_solves);
  state.counters["carried_steps"] = static_cast<double>(r.carried_steps);
  state.counters["max_struts"] = static_cast<double>(r.max_struts);
  state.counters["flips"] = static_cast<double>(r.flips);
  state.counters["straightenings"] = static_cast<double>(r.straightenings);
  state.counters["certificate_s"] = r.certificate_seconds;
  state.counters["max_length_error"] = r.max_length_error;
  state.counters["min_distance_growth"] = r.min_distance_growth;
}

CarpenterPlanarOptions with(CarpenterPlanarMethod method, bool all_struts = false) {
  CarpenterPlanarOptions options;
  options.method = method;
  options.all_struts = all_struts;
  return options;
}

constexpr auto kLp = CarpenterPlanarMethod::Lp;
constexpr auto kCarried = CarpenterPlanarMethod::CarriedField;
constexpr auto kPseudo = CarpenterPlanarMethod::PseudoTriangulation;

PlanarChain walk(const benchmark::State& state) {
  return {foldkit::microbench::random_lattice_walk(static_cast<int>(state.range(0)), 1), false};
}
PlanarChain chain(const benchmark::State& state) {
  return {foldkit::microbench::random_chain(static_cast<int>(state.range(0)), 1), false};
}

// Issue 20's and 36's input: self-avoiding lattice walks by the pivot algorithm, jittered by 0.1,
// by the global LP per step (the baseline) and by the carried field.
void BM_Carpenter_StraightenLatticeWalk(benchmark::State& state) { run(state, walk(state), with(kLp)); }
void BM_Carpenter_StraightenLatticeWalkCarried(benchmark::State& state) { run(state, walk(state), with(kCarried)); }
// Streinu's pseudo-triangulation mechanism (one sparse solve per step, flips at events).
void BM_Carpenter_StraightenLatticeWalkPseudo(benchmark::State& state) { run(state, walk(state), with(kPseudo)); }
void BM_Carpenter_ConvexifyPseudo(benchmark::State& state) {
  run(state, {foldkit::microbench::random_star(static_cast<int>(state.range(0)), 1), true}, with(kPseudo));
}
void BM_Carpenter_Straighten(benchmark::State& state) { run(state, chain(state), with(kLp)); }
void BM_Carpenter_StraightenCarried(benchmark::State& state) { run(state, chain(state), with(kCarried)); }

// Closed chains: both methods solve the global LP at every step (a carried field would not keep
// the polygon closed), so one benchmark.
void BM_Carpenter_Convexify(benchmark::State& state) {
  run(state, {foldkit::microbench::random_star(static_cast<int>(state.range(0)), 1), true}, with(kLp));
}
// Issue 20's polygon to convexify, 100–1,000 vertices (carpenter_inputs.hpp).
BENCHMARK(BM_Carpenter_Convexify)->Arg(100)->Arg(200)->Arg(400)->Arg(1000)->Iterations(1)->Unit(benchmark::kSecond);
void BM_Carpenter_Ours(benchmark::State& state) { run(state, chain(state), with(kLp)); }
void BM_Carpenter_AllStruts(benchmark::State& state) { run(state, chain(state), with(kLp, true)); }

BENCHMARK(BM_Carpenter_Straighten)->Arg(100)->Arg(200)->Arg(400)->Arg(1000)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_Carpenter_StraightenCarried)->Arg(100)->Arg(200)->Arg(400)->Arg(1000)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_Carpenter_StraightenLatticeWalk)->Arg(100)->Arg(300)->Arg(1000)->Iterations(1)->Unit(benchmark::kSecond);
// Not registered beyond 1,000 links: at 2,000 the carried field creeps after 810 steps and at
// 10,000 the first global LP alone takes minutes (docs/CARPENTER.md, Limits), so such a run
// would not end.
BENCHMARK(BM_Carpenter_StraightenLatticeWalkCarried)->Arg(100)->Arg(300)->Arg(1000)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_Carpenter_StraightenLatticeWalkPseudo)->Arg(100)->Arg(300)->Arg(1000)->Iterations(1)->Unit(benchmark::kSecond);
// 30 vertices convexify; 100 stops at the step limit after ~6 s (docs/CARPENTER.md, Limits), and
// 200 and 400 are not registered (200 stops with no step, 400 ran over 5 minutes).
BENCHMARK(BM_Carpenter_ConvexifyPseudo)->Arg(30)->Arg(100)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_Carpenter_Ours)->Arg(50)->Arg(100)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Carpenter_AllStruts)->Arg(50)->Arg(100)->Iterations(1)->Unit(benchmark::kMillisecond);

// A frame and the one after it: a lattice walk scaled by 1 + 1e-6 about its first vertex, so every
// pair grows (then every pair needs its square roots: the worst case); with `shrink`, vertex 0
// also moves 1e-3 of the way to vertex 2, so some of its pairs shrink, as rounding makes a few
// pairs shrink between the planner's frames (then only those need square roots).
std::pair<Frame2, Frame2> frame_pair(int links, bool shrink) {
  const Frame2 p = foldkit::microbench::random_lattice_walk(links, 1);
  Frame2 q = p;
  for (auto& x : q) x = p[0] + (1.0 + 1e-6) * (x - p[0]);
  if (shrink) q[0] += 1e-3 * (p[2] - p[0]);
  return {p, q};
}

void BM_RecordFrame_CheckMotion(benchmark::State& state) {
  const auto [p, q] = frame_pair(static_cast<int>(state.range(0)), state.range(1) != 0);
  for (auto _ : state) {
    const MotionCheck step = check_motion({p, q}, false), lengths = check_motion({p, q}, false);
    benchmark::DoNotOptimize(step.min_distance_growth + lengths.max_length_error);
  }
}

void BM_RecordFrame_Ours(benchmark::State& state) {
  const auto [p, q] = frame_pair(static_cast<int>(state.range(0)), state.range(1) != 0);
  for (auto _ : state)
    benchmark::DoNotOptimize(planar_detail::min_distance_growth(p, q) + planar_detail::bar_length_error(p, q, false));
}
// Wall time: ours runs half its pairs on a second thread, which the main thread's CPU time misses.
BENCHMARK(BM_RecordFrame_CheckMotion)->ArgsProduct({{1000, 3000, 10000}, {0, 1}})->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RecordFrame_Ours)->ArgsProduct({{1000, 3000, 10000}, {0, 1}})->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
