#pragma once
// Random corruptions of a text, for the tests of the readers that skip the XML parser on
// foldkit's own files (cmml_plain_test.cpp, pmml_plain_test.cpp): each trial erases 1–4 bytes or
// inserts one of `inserts` at a random place, one to three times.
#include <cstddef>
#include <random>
#include <string>
#include <vector>

namespace foldkit::test {

/// One corrupted copy of `base` drawn from `rng`.
inline std::string corrupted(const std::string& base, const std::vector<std::string>& inserts, std::mt19937& rng) {
  std::string t = base;
  const int edits = 1 + static_cast<int>(rng() % 3);
  for (int k = 0; k < edits; ++k) {
    const std::size_t at = rng() % t.size();
    if (rng() % 3 == 0) t.erase(at, 1 + rng() % 4);
    else t.insert(at, inserts[rng() % inserts.size()]);
  }
  return t;
}

}  // namespace foldkit::test
