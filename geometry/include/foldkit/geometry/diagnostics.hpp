#pragma once
/// @file
/// Findings about an input (a pattern, a fold sequence), each located by a source line.
#include <string>
#include <vector>

namespace foldkit::geometry {

/// How bad a Diagnostic is.
enum class Severity {
  Warning,  ///< the input is accepted (for instance a joint added by BuildOptions::auto_joints)
  Error     ///< the input is rejected
};

/// One finding about an input, located by the source line of the element it concerns.
struct Diagnostic {
  Severity severity = Severity::Error;  ///< warning or error
  int line = 0;                         ///< source line; 0 when the element did not come from a file
  std::string message;                  ///< what is wrong, in words
};

/// The findings of one check, in the order they were made.
using Diagnostics = std::vector<Diagnostic>;

/// True when any of `diagnostics` is an error.
bool has_errors(const Diagnostics& diagnostics);

/// "FILE:LINE: message" (or "FILE: message" without a line), warnings prefixed by "warning: ".
/// @param d     the finding
/// @param file  the name written in front (a path, or any label)
std::string format(const Diagnostic& d, const std::string& file);

}  // namespace foldkit::geometry
