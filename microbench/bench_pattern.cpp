// Loading a crease pattern: what `foldkit info` does, and the overlap check inside it side by
// side with the all-pairs check a plain implementation would run; and reading the PMML text:
//   BM_ParsePmml_Ours     — io::parse_pmml: foldkit's own shape read without an XML parser;
//   BM_ParsePmml_Baseline — io::detail::parse_pmml_xml: tinyxml2 and XmlInput's checks, as every
//                           PMML was read before (and any text out of that shape still is);
//   BM_Overlap_Ours     — geometry::overlapping_pairs (Boost.Geometry R-tree, then exact tests);
//   BM_Overlap_Baseline — the exact test on every pair of triangles.
#include <benchmark/benchmark.h>

#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/triangle_overlap.hpp"
#include "foldkit/io/pmml.hpp"

namespace {

using namespace foldkit;

geometry::PatternSpec miura(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  return geometry::generators::miura(n, n);
}

std::vector<geometry::Tri2> triangles_of(const geometry::PatternSpec& spec) {
  std::vector<geometry::Tri2> tris;
  for (const auto& a : spec.actors)
    for (const auto& t : a.triangles) tris.push_back(t.corners);
  return tris;
}

void BM_ParseAndBuildPmml(benchmark::State& state) {
  const std::string text = io::write_pmml(miura(state));
  for (auto _ : state) {
    auto built = geometry::build_pattern(io::parse_pmml(text, "miura.pmml"));
    benchmark::DoNotOptimize(built.pattern);
  }
  state.counters["actors"] = static_cast<double>(state.range(0) * state.range(0));
}
BENCHMARK(BM_ParseAndBuildPmml)->Arg(10)->Arg(20)->Arg(40)->Arg(100)->Unit(benchmark::kMillisecond);

void BM_ParsePmml_Ours(benchmark::State& state) {
  const std::string text = io::write_pmml(miura(state));
  for (auto _ : state) benchmark::DoNotOptimize(io::parse_pmml(text, "miura.pmml"));
  state.counters["MB"] = static_cast<double>(text.size()) / 1e6;
}
BENCHMARK(BM_ParsePmml_Ours)->Arg(40)->Arg(100)->Unit(benchmark::kMillisecond);

void BM_ParsePmml_Baseline(benchmark::State& state) {
  const std::string text = io::write_pmml(miura(state));
  for (auto _ : state) benchmark::DoNotOptimize(io::detail::parse_pmml_xml(text, "miura.pmml"));
  state.counters["MB"] = static_cast<double>(text.size()) / 1e6;
}
BENCHMARK(BM_ParsePmml_Baseline)->Arg(40)->Arg(100)->Unit(benchmark::kMillisecond);

void BM_Overlap_Ours(benchmark::State& state) {
  const auto tris = triangles_of(miura(state));
  for (auto _ : state) benchmark::DoNotOptimize(geometry::overlapping_pairs(tris, 1e-9));
  state.counters["facets"] = static_cast<double>(state.range(0) * state.range(0));
}
BENCHMARK(BM_Overlap_Ours)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMillisecond);

// The generic way: test every pair of triangles.
void BM_Overlap_Baseline(benchmark::State& state) {
  const auto tris = triangles_of(miura(state));
  for (auto _ : state) {
    std::size_t found = 0;
    for (std::size_t i = 0; i < tris.size(); ++i)
      for (std::size_t j = i + 1; j < tris.size(); ++j) found += geometry::triangles_overlap(tris[i], tris[j], 1e-9);
    benchmark::DoNotOptimize(found);
  }
  state.counters["facets"] = static_cast<double>(state.range(0) * state.range(0));
}
BENCHMARK(BM_Overlap_Baseline)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
