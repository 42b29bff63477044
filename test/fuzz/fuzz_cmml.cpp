// Any bytes: parse_cmml either throws ParseError or gives a sequence whose CMML reads back to
// the same text.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "foldkit/io/cmml.hpp"
#include "foldkit/io/parse_error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace foldkit;
  geometry::FoldSequence seq;
  try {
    seq = io::parse_cmml(std::string(reinterpret_cast<const char*>(data), size), "fuzz.cmml");
  } catch (const io::ParseError&) {
    return 0;
  }
  const std::string once = io::write_cmml(seq);
  if (io::write_cmml(io::parse_cmml(once, "again.cmml")) != once) std::abort();
  return 0;
}
