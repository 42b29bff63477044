// Any bytes: parse_pmml either throws ParseError or gives a spec; a spec either builds or not;
// a built pattern writes a PMML that reads back to the same text.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "foldkit/io/parse_error.hpp"
#include "foldkit/io/pmml.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace foldkit;
  geometry::PatternSpec spec;
  try {
    spec = io::parse_pmml(std::string(reinterpret_cast<const char*>(data), size), "fuzz.pmml");
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
