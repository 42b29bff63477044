// Importing crease patterns drawn as lines (issue 34: a 10,000-line tessellation in ≤ 1 s), side
// by side with the generic way, the same pattern read as FOLD (edges already split and merged):
//   BM_ImportSvg_Ours    — io::parse_svg_lines + io::pattern_from_lines (CGAL arrangement, FOLD importer);
//   BM_ImportFold_Generic — io::parse_fold of the same pattern;
//   BM_ImportFixture     — each of Origami Simulator's files in ../shared/fixtures/svg (when there).
// The ratio of the first two is what the arrangement costs; counters give the lines.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "foldkit/geometry/generators.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/drawn_lines.hpp"
#include "foldkit/io/fold_format.hpp"
#include "foldkit/io/svg.hpp"

namespace {

using namespace foldkit;

geometry::CreasePattern miura(int n) { return geometry::build_or_throw(geometry::generators::miura(n, n)); }

void BM_ImportSvg_Ours(benchmark::State& state) {
  const std::string text = io::write_svg(miura(static_cast<int>(state.range(0))));
  std::size_t lines = 0;
  for (auto _ : state) {
    const auto drawn = io::parse_svg_lines(text, "miura.svg");
    lines = drawn.size();
    benchmark::DoNotOptimize(io::pattern_from_lines(drawn, "miura.svg"));
  }
  state.counters["lines"] = static_cast<double>(lines);
}
BENCHMARK(BM_ImportSvg_Ours)->Arg(10)->Arg(35)->Arg(71)->Unit(benchmark::kMillisecond);

void BM_ImportFold_Generic(benchmark::State& state) {
  const std::string text = io::write_fold(miura(static_cast<int>(state.range(0))));
  for (auto _ : state) benchmark::DoNotOptimize(io::parse_fold(text, "miura.fold"));
}
BENCHMARK(BM_ImportFold_Generic)->Arg(10)->Arg(35)->Arg(71)->Unit(benchmark::kMillisecond);

const char* kFixtures[] = {"birdBase", "brochurefold", "huffmanWaterbomb", "miura-ori", "reschTriTessellation", "simpleVertex",
                           "singlesquaretwist", "squareBase", "traditionalCrane", "waterbomb", "waterbombBase"};

void BM_ImportFixture(benchmark::State& state) {
  const std::string name = kFixtures[state.range(0)];
  const std::string path = std::string(FOLDKIT_SHARED_FIXTURES) + "/svg/OrigamiSimulator__" + name + ".svg";
  if (!std::filesystem::exists(path)) {
    state.SkipWithError(("no " + path).c_str());
    return;
  }
  state.SetLabel(name);
  const std::string text = io::read_file(path);
  for (auto _ : state) benchmark::DoNotOptimize(io::pattern_from_lines(io::parse_svg_lines(text, path), path));
  state.counters["lines"] = static_cast<double>(io::parse_svg_lines(text, path).size());
}
BENCHMARK(BM_ImportFixture)->DenseRange(0, 10)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
