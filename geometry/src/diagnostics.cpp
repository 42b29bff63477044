#include "foldkit/geometry/diagnostics.hpp"

#include <algorithm>

namespace foldkit::geometry {

bool has_errors(const Diagnostics& diagnostics) {
  return std::any_of(diagnostics.begin(), diagnostics.end(),
                     [](const Diagnostic& d) { return d.severity == Severity::Error; });
}

std::string format(const Diagnostic& d, const std::string& file) {
  std::string out = file;
  if (d.line > 0) out += ":" + std::to_string(d.line);
  out += ": ";
  if (d.severity == Severity::Warning) out += "warning: ";
  out += d.message;
  return out;
}

}  // namespace foldkit::geometry
