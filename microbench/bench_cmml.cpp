// Reading a large CMML, as `foldkit simulate` reads the output of `foldkit fold` on a big sheet
// (projected folding writes every crease at every step: a Miura-ori 40 × 40 folded to 0.9 is 99
// events × 3,120 creases, 49 MB), side by side:
//   BM_ReadCmml_Ours     — io::parse_cmml: a slice of about 1 MB of <Fold> elements at a time;
//   BM_ReadCmml_Baseline — the whole file as one XML document, as every CMML was read before.
// Peak memory is the difference that matters (docs/FORMATS.md: 471 MB → 116 MB for `foldkit
// validate` of that file); the counters give the text's size.
#include <benchmark/benchmark.h>

#include "foldkit/io/cmml.hpp"

namespace {

using namespace foldkit;

// `events` events, each moving `creases` creases, written by foldkit.
std::string sequence_text(int events, int creases) {
  geometry::FoldSequence s;
  s.title = "benchmark";
  for (int e = 0; e < events; ++e) {
    geometry::FoldEvent event{e + 1, {}};
    for (int j = 1; j <= creases; ++j) event.folds.push_back({j, 0.001 * (e + 1) * (j % 2 ? 1 : -1) + 1e-7 * j, 0.3 + 1e-6 * j});
    s.events.push_back(std::move(event));
  }
  return io::write_cmml(s);
}

void BM_ReadCmml_Ours(benchmark::State& state) {
  const std::string text = sequence_text(99, static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(io::parse_cmml(text, "fold.cmml"));
  state.counters["MB"] = static_cast<double>(text.size()) / 1e6;
}
BENCHMARK(BM_ReadCmml_Ours)->Arg(180)->Arg(760)->Arg(3120)->Unit(benchmark::kMillisecond);

void BM_ReadCmml_Baseline(benchmark::State& state) {
  const std::string text = sequence_text(99, static_cast<int>(state.range(0)));
  // One slice holding the whole body is one XML document of the whole file.
  for (auto _ : state) benchmark::DoNotOptimize(io::detail::parse_cmml_sliced(text, "fold.cmml", text.size()));
  state.counters["MB"] = static_cast<double>(text.size()) / 1e6;
}
BENCHMARK(BM_ReadCmml_Baseline)->Arg(180)->Arg(760)->Arg(3120)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
