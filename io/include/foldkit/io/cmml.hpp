#pragma once
#include <string>

#include "foldkit/geometry/fold_sequence.hpp"

namespace foldkit::io {

// CMML (paper Table 2): FoldAngle in degrees within [−180, 180], Velocity in degrees per
// second, positive; EventNumber a non-negative integer. Throws ParseError.
geometry::FoldSequence parse_cmml(const std::string& text, const std::string& name);
geometry::FoldSequence read_cmml(const std::string& path);

std::string write_cmml(const geometry::FoldSequence& sequence);

}  // namespace foldkit::io
