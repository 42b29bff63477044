#pragma once
#include <string>

#include "foldkit/geometry/fold_sequence.hpp"

namespace foldkit::io {

// CMML (paper Table 2): FoldAngle in degrees within [−180, 180], Velocity in degrees per
// second, positive (also once converted to radians: 5e-324 is rejected as too small);
// EventNumber a non-negative integer. The text must be UTF-8. Throws ParseError.
geometry::FoldSequence parse_cmml(const std::string& text, const std::string& name);
geometry::FoldSequence read_cmml(const std::string& path);

// Angles are clamped to [−π, π] and written in degrees; angles within rounding of ±180° are
// written as ±180, so every written angle reads back. Throws std::invalid_argument for a
// non-finite angle or velocity, a velocity ≤ 0, or one whose degrees overflow or are too small
// to read back as positive. The title is written with escape rules that keep the file valid
// XML (see detail::escape_xml: forbidden characters become U+FFFD).
std::string write_cmml(const geometry::FoldSequence& sequence);

}  // namespace foldkit::io
