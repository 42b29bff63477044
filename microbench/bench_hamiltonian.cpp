// Hamiltonian paths: the linear-time 2× refinement (per-cell time should stay flat from 10² to
// 10⁵ coarse cells) beside the exponential exact search on small shapes; BM_Hamiltonian_Ours and
// BM_Hamiltonian_Baseline are the pair on identical cells.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <set>
#include <tuple>

#include "foldkit/folding/hamiltonian.hpp"

namespace {

using namespace foldkit::folding;
using foldkit::geometry::StatusCode;

// A roughly square blob of n cells grown at random (seeded), so the spanning tree branches.
PixelShape blob(std::size_t n) {
  const int side = 2 * static_cast<int>(std::sqrt(static_cast<double>(n))) + 4;
  PixelShape s{side, side, std::vector<std::uint8_t>(static_cast<std::size_t>(side) * static_cast<std::size_t>(side), 0)};
  std::mt19937 rng(1);
  std::vector<std::pair<int, int>> list = {{side / 2, side / 2}};
  s.cells[static_cast<std::size_t>(side / 2 * side + side / 2)] = 1;
  static const int kSteps[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  while (list.size() < n) {
    const auto [x, y] = list[rng() % list.size()];
    const auto& d = kSteps[rng() % 4];
    const int nx = x + d[0], ny = y + d[1];
    if (nx < 0 || ny < 0 || nx >= side || ny >= side) continue;
    auto& c = s.cells[static_cast<std::size_t>(ny * side + nx)];
    if (c == 0) {
      c = 1;
      list.emplace_back(nx, ny);
    }
  }
  return s;
}

VoxelShape cube(int side) {
  return {side, side, side, std::vector<std::uint8_t>(static_cast<std::size_t>(side * side * side), 1)};
}

void BM_Refine2D(benchmark::State& state) {
  const PixelShape s = blob(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(refined_hamiltonian_cycle(s).path.data());
  state.counters["time_per_cell"] =
      benchmark::Counter(static_cast<double>(state.range(0)) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Refine2D)->Arg(100)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMicrosecond);

void BM_Refine3D(benchmark::State& state) {
  const VoxelShape s = cube(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(refined_hamiltonian_cycle(s).path.data());
  const double cells = static_cast<double>(state.range(0) * state.range(0) * state.range(0));
  state.counters["time_per_cell"] = benchmark::Counter(cells * static_cast<double>(state.iterations()),
                                                       benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Refine3D)->Arg(5)->Arg(10)->Arg(22)->Arg(46)->Unit(benchmark::kMicrosecond);

void BM_ExactRectangle(benchmark::State& state) {
  const int side = static_cast<int>(state.range(0));
  const PixelShape s{side, side, std::vector<std::uint8_t>(static_cast<std::size_t>(side * side), 1)};
  ExactOptions o;
  o.node_budget = 10'000'000;
  for (auto _ : state) benchmark::DoNotOptimize(exact_hamiltonian(s, o).nodes);
}
BENCHMARK(BM_ExactRectangle)->Arg(4)->Arg(8)->Arg(16)->Arg(30)->Unit(benchmark::kMicrosecond);

// Side by side on the same cells: a Hamiltonian cycle through the 2× refinement of a random blob
// of n coarse cells, built by the refinement (ours) or found by the exact search (the generic
// way: depth-first search with pruning; found = -1 when its node budget runs out first, so the
// ratio is then a lower bound).
void BM_Hamiltonian_Ours(benchmark::State& state) {
  const PixelShape s = blob(static_cast<std::size_t>(state.range(0)));
  HamiltonianResult r;
  for (auto _ : state) {
    r = refined_hamiltonian_cycle(s);
    benchmark::DoNotOptimize(r.path.data());
  }
  state.counters["cells"] = static_cast<double>(r.path.size());
  state.counters["found"] = r.status.code == StatusCode::Success ? 1 : 0;
}
BENCHMARK(BM_Hamiltonian_Ours)->Arg(5)->Arg(10)->Arg(20)->Arg(40)->Arg(80)->Unit(benchmark::kMicrosecond);

void BM_Hamiltonian_Baseline(benchmark::State& state) {
  const PixelShape s = refine(blob(static_cast<std::size_t>(state.range(0))));
  ExactOptions o;
  o.cycle = true;
  o.node_budget = 1'000'000;
  HamiltonianResult r;
  for (auto _ : state) r = exact_hamiltonian(s, o);
  state.counters["cells"] = static_cast<double>(s.count());
  state.counters["nodes"] = static_cast<double>(r.nodes);
  state.counters["found"] = r.status.code == StatusCode::Success ? 1 : r.status.code == StatusCode::NoSolution ? 0 : -1;
}
BENCHMARK(BM_Hamiltonian_Baseline)->Arg(5)->Arg(10)->Arg(20)->Arg(40)->Arg(80)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
