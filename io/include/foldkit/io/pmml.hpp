#pragma once
#include <string>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/pattern_spec.hpp"

namespace foldkit::io {

// PMML (paper Table 1). `name` is used in error messages. Throws ParseError for anything that
// is not PMML: unknown elements, missing or repeated fields, non-integer IDs, non-finite numbers,
// text that is not UTF-8. The title keeps its inner whitespace; leading and trailing whitespace
// is trimmed.
geometry::PatternSpec parse_pmml(const std::string& text, const std::string& name);
geometry::PatternSpec read_pmml_spec(const std::string& path);

// Reads and builds; geometric errors (build_pattern diagnostics) are thrown as one ParseError
// carrying the first error, after every diagnostic is formatted into its message.
geometry::CreasePattern read_pmml(const std::string& path, const geometry::BuildOptions& options = {});

// Throws std::invalid_argument ("…: not a finite number") for a non-finite coordinate, spring
// or damping constant: a written file never holds NaN or inf. The title is written so that the
// file stays valid XML (characters XML forbids become U+FFFD).
std::string write_pmml(const geometry::PatternSpec& spec);
std::string write_pmml(const geometry::CreasePattern& pattern);

}  // namespace foldkit::io
