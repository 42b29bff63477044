// Planar Carpenter's rule: straighten seeded random 100–1,000-link chains (constraint generation:
// the LP starts with near pairs and takes violated struts as they show, warm-started; the closed-
// form end takes over once the chain is monotone; docs/CARPENTER.md has the figures), and, side by
// side on smaller chains, the same planner with all O(n²) struts in every LP
// (BM_Carpenter_Ours vs BM_Carpenter_AllStruts on identical chains). The 1,000-link case used to
// look like a planner that never finished: it was the chain generator, which restarted from
// scratch at every dead end (see random_chain).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "carpenter_inputs.hpp"
#include "foldkit/folding/carpenter.hpp"

namespace {

using namespace foldkit::folding;
using Vec = Eigen::Vector2d;

double segment_gap(const Vec& a, const Vec& b, const Vec& c, const Vec& d) {
  auto point = [](const Vec& p, const Vec& s, const Vec& e) {
    const Vec r = e - s;
    const double t = std::clamp((p - s).dot(r) / r.squaredNorm(), 0.0, 1.0);
    return (s + t * r - p).norm();
  };
  auto side = [](const Vec& s, const Vec& e, const Vec& p) {
    const Vec r = e - s, q = p - s;
    return r.x() * q.y() - r.y() * q.x();
  };
  if (side(a, b, c) * side(a, b, d) < 0 && side(c, d, a) * side(c, d, b) < 0) return 0.0;
  return std::min({point(a, c, d), point(b, c, d), point(c, a, b), point(d, a, b)});
}

// Seeded self-avoiding chain: bars 0.5–1.5, turns up to ±2.6 rad, bars kept 0.05 apart. A walk
// whose tip is walled in (200 failed tries) backs up 2, 4, 8, … bars until it grows past the dead
// end: restarting from scratch instead, as this generator once did, took 30,000 restarts (14 s)
// for 400 links and never reached 1,000.
Frame2 random_chain(int links, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> length(0.5, 1.5), turn(-2.6, 2.6);
  Frame2 p = {Vec(0, 0)};
  std::vector<double> heading = {0.0};
  int failures = 0;
  std::size_t retreat = 1, dead_end = 0;
  while (static_cast<int>(p.size()) <= links) {
    const double h = heading.back() + turn(rng);
    const Vec q = p.back() + length(rng) * Vec(std::cos(h), std::sin(h));
    bool ok = true;
    for (std::size_t b = 0; b + 2 < p.size() && ok; ++b) ok = segment_gap(p[b], p[b + 1], p.back(), q) > 0.05;
    if (ok) {
      p.push_back(q);
      heading.push_back(h);
      failures = 0;
      if (p.size() > dead_end) retreat = 1;
    } else if (++failures == 200) {
      failures = 0;
      if (retreat == 1) dead_end = p.size();
      retreat *= 2;
      if (retreat >= p.size()) {  // walled in from the start: begin again
        retreat = p.size() - 1;
        dead_end = 0;
      }
      p.resize(p.size() - retreat);
      heading.resize(p.size());
    }
  }
  return p;
}

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
  run(state, {random_chain(static_cast<int>(state.range(0)), 1), false}, all_struts);
}

void BM_Carpenter_Straighten(benchmark::State& state) { run(state, false); }

void BM_Carpenter_Convexify(benchmark::State& state) {
  run(state, {foldkit::benchmarks::random_star(static_cast<int>(state.range(0)), 1), true}, false);
}
// Issue 20's polygon to convexify, 100–1,000 vertices (carpenter_inputs.hpp).
BENCHMARK(BM_Carpenter_Convexify)->Arg(100)->Arg(200)->Arg(400)->Arg(1000)->Iterations(1)->Unit(benchmark::kSecond);
void BM_Carpenter_Ours(benchmark::State& state) { run(state, false); }
void BM_Carpenter_AllStruts(benchmark::State& state) { run(state, true); }

BENCHMARK(BM_Carpenter_Straighten)->Arg(100)->Arg(200)->Arg(400)->Arg(1000)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_Carpenter_Ours)->Arg(50)->Arg(100)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Carpenter_AllStruts)->Arg(50)->Arg(100)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
