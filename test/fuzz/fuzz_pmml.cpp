// Any bytes: parse_pmml either throws ParseError or gives a spec; a spec either builds or not;
// a built pattern writes a PMML that reads back to the same text; and whatever the plain reading
// (no XML parser) reads, the XML reading reads alike: the same text written back, the same lines.
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "foldkit/io/parse_error.hpp"
#include "foldkit/io/pmml.hpp"

namespace {

std::vector<int> lines(const foldkit::geometry::PatternSpec& s) {
  std::vector<int> out = {s.physics.density_line, s.physics.gravity_line, s.physics.fixed_actor_line};
  for (const auto& a : s.actors) {
    out.push_back(a.line);
    for (const auto& t : a.triangles) out.push_back(t.line);
  }
  for (const auto& j : s.joints) out.push_back(j.line);
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace foldkit;
  const std::string text(reinterpret_cast<const char*>(data), size);
  if (const auto plain = io::detail::read_plain_pmml(text)) {
    geometry::PatternSpec xml;
    try {
      xml = io::detail::parse_pmml_xml(text, "fuzz.pmml");
    } catch (const io::ParseError&) {
      std::abort();  // read without XML what the XML reading refuses
    }
    if (io::write_pmml(*plain) != io::write_pmml(xml) || lines(*plain) != lines(xml)) std::abort();
  }
  geometry::PatternSpec spec;
  try {
    spec = io::parse_pmml(text, "fuzz.pmml");
  } catch (const io::ParseError&) {
    return 0;
  }
  geometry::BuildResult built = geometry::build_pattern(spec);
  if (!built.pattern) return 0;
  const std::string once = io::write_pmml(*built.pattern);
  const geometry::BuildResult again = geometry::build_pattern(io::parse_pmml(once, "again.pmml"));
  if (!again.pattern || io::write_pmml(*again.pattern) != once) std::abort();
  return 0;
}
