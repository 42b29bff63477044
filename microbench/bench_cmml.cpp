// Reading a large CMML, as `foldkit simulate` reads the output of `foldkit fold` on a big sheet
// (projected folding writes every crease at every step: a Miura-ori 40 × 40 folded to 0.9 is 99
// events × 3,120 creases, 49 MB), side by side:
//   BM_ReadCmml_Ours     — io::parse_cmml: a slice of about 1 MB of <Fold> elements at a time;
//   BM_ReadCmml_Baseline — the whole file as one XML document, as every CMML was read before.
// Peak memory is the difference that matters (docs/FORMATS.md: 471 MB → 116 MB for `foldkit
// validate` of that file); the counters give the text's size.
// Writing it, side by side:
//   BM_WriteCmml_Ours     — io::write_cmml: each fold appended to one buffer, its degrees
//                           formatted into a stack buffer;
//   BM_WriteCmml_Baseline — the same text built as write_cmml built it until 2026-11-27: strings
//                           concatenated per fold, each number a std::string, read back by
//                           parse_numbers.
#include <cmath>
#include <string>

#include <benchmark/benchmark.h>

#include "foldkit/io/cmml.hpp"
#include "foldkit/io/number_format.hpp"

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

geometry::FoldSequence sequence(int events, int creases) { return io::parse_cmml(sequence_text(events, creases), "fold.cmml"); }

void BM_WriteCmml_Ours(benchmark::State& state) {
  const geometry::FoldSequence s = sequence(99, static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(io::write_cmml(s));
}
BENCHMARK(BM_WriteCmml_Ours)->Arg(760)->Arg(3120)->Unit(benchmark::kMillisecond);

std::string baseline_write(const geometry::FoldSequence& sequence) {
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<CMML>\n  <Title>" + sequence.title + "</Title>\n";
  for (const auto& event : sequence.events) {
    const std::string number = std::to_string(event.number);
    for (const auto& f : event.folds) {
      std::string angle = io::format_degrees(f.angle);
      if (io::parse_numbers(angle).values.at(0) > 180.0) angle = "180";
      const std::string speed = io::format_degrees(f.speed);
      if (!(io::degrees_to_radians(io::parse_numbers(speed).values.at(0)) > 0.0)) return {};
      out += "  <Fold>\n    <EventNumber>" + number + "</EventNumber>\n    <ID>" + std::to_string(f.joint_id) +
             "</ID>\n    <FoldAngle>" + angle + "</FoldAngle>\n    <Velocity>" + speed + "</Velocity>\n  </Fold>\n";
    }
  }
  return out + "</CMML>\n";
}

void BM_WriteCmml_Baseline(benchmark::State& state) {
  const geometry::FoldSequence s = sequence(99, static_cast<int>(state.range(0)));
  if (baseline_write(s) != io::write_cmml(s)) state.SkipWithError("the baseline writes another text");
  for (auto _ : state) benchmark::DoNotOptimize(baseline_write(s));
}
BENCHMARK(BM_WriteCmml_Baseline)->Arg(760)->Arg(3120)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
