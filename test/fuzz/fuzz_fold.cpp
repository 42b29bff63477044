// Any bytes: parse_fold either throws ParseError or imports a pattern that exports to a FOLD
// file which imports again with the same counts.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "foldkit/io/fold_format.hpp"
#include "foldkit/io/parse_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace foldkit;
  std::optional<io::FoldImport> in;
  try {
    in.emplace(io::parse_fold(std::string(reinterpret_cast<const char*>(data), size), "fuzz.fold"));
  } catch (const io::ParseError&) {
    return 0;
  }
  const io::FoldImport again = io::parse_fold(io::write_fold(in->pattern, {in->state, {}}), "again.fold");
  if (again.pattern.actors().size() != in->pattern.actors().size() ||
      again.pattern.joints().size() != in->pattern.joints().size())
    std::abort();
  return 0;
}
