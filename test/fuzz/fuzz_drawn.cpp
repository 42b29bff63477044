// Any bytes as a crease pattern drawn as lines (issue 34), built once per reader with
// FOLDKIT_FUZZ_PARSER set to parse_svg_lines, parse_cp_lines or parse_opx_lines
// (test/fuzz/CMakeLists.txt): the reader and pattern_from_lines either throw ParseError or give a
// pattern that foldkit's SVG writer draws and the SVG reader reads again with the same counts of
// actors and joints — unless the pattern has slivers (an edge shorter than 1e-4 of its diagonal,
// a few merge tolerances), which a second import may merge (docs/FORMATS.md).
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>

#include "foldkit/io/drawn_lines.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/io/svg.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace foldkit;
  std::optional<io::PatternFile> in;
  try {
    in.emplace(io::pattern_from_lines(io::FOLDKIT_FUZZ_PARSER(std::string(reinterpret_cast<const char*>(data), size), "fuzz"), "fuzz"));
  } catch (const io::ParseError&) {
    return 0;
  }
  Eigen::AlignedBox2d box;
  for (const auto& v : in->pattern.vertices()) box.extend(v);
  const double sliver = 1e-4 * box.diagonal().norm();
  const auto& V = in->pattern.vertices();
  for (const auto& [a, b] : in->pattern.boundary_edges())
    if ((V[a] - V[b]).norm() < sliver) return 0;
  for (const auto& j : in->pattern.joints())
    if ((V[j.v[0]] - V[j.v[1]]).norm() < sliver) return 0;
  const io::PatternFile again = io::pattern_from_lines(io::parse_svg_lines(io::write_svg(in->pattern), "again.svg"), "again.svg");
  if (again.pattern.actors().size() != in->pattern.actors().size() ||
      again.pattern.joints().size() != in->pattern.joints().size())
    std::abort();
  return 0;
}
