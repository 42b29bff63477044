#pragma once
#include <string>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/pattern_spec.hpp"

namespace foldkit::io {

// PMML (paper Table 1). `name` is used in error messages. Throws ParseError for anything that
// is not PMML: unknown elements, missing or repeated fields, non-integer IDs, non-finite numbers.
geometry::PatternSpec parse_pmml(const std::string& text, const std::string& name);
geometry::PatternSpec read_pmml_spec(const std::string& path);

// Reads and builds; geometric errors (build_pattern diagnostics) are thrown as one ParseError
// carrying the first error, after every diagnostic is formatted into its message.
geometry::CreasePattern read_pmml(const std::string& path, const geometry::BuildOptions& options = {});

std::string write_pmml(const geometry::PatternSpec& spec);
std::string write_pmml(const geometry::CreasePattern& pattern);

}  // namespace foldkit::io
