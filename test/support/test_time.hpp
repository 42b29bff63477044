#pragma once
// Time limits of tests that plan, scaled for slow builds. The search keeps to its limit (issue 32),
// so a limit chosen for the Release build runs out under the sanitizers' tenfold slowdown:
// FOLDKIT_TEST_TIME_SCALE (scripts/test-sanitizers.sh and test-tsan.sh set 10) multiplies every
// limit passed through here; unset, it is 1.
#include <cstdlib>
#include <string>

namespace foldkit::test {

inline double time_scale() {
  const char* text = std::getenv("FOLDKIT_TEST_TIME_SCALE");
  const double scale = text ? std::atof(text) : 1.0;
  return scale >= 1.0 ? scale : 1.0;
}

// `seconds` × time_scale().
inline double scaled_seconds(double seconds) { return seconds * time_scale(); }

// The same, as a command-line argument.
inline std::string scaled_arg(double seconds) { return std::to_string(scaled_seconds(seconds)); }

}  // namespace foldkit::test
