#pragma once
#include <string>
#include <vector>

namespace foldkit::geometry {

enum class Severity { Warning, Error };

// One finding about an input, located by the source line of the element it concerns
// (0 when the element did not come from a file).
struct Diagnostic {
  Severity severity = Severity::Error;
  int line = 0;
  std::string message;
};

using Diagnostics = std::vector<Diagnostic>;

bool has_errors(const Diagnostics& diagnostics);

// "FILE:LINE: message" (or "FILE: message" without a line), warnings prefixed by "warning: ".
std::string format(const Diagnostic& d, const std::string& file);

}  // namespace foldkit::geometry
