#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace foldkit::io {

// Shortest decimal text that reads back to exactly `value`.
std::string format_number(double value);

// Degrees for a value kept in radians: the shortest decimal d with d·π/180 == radians when
// there is one (always for angles read from a file, so they are written back unchanged), else
// the nearest degrees; the reading is then within one unit in the last place.
std::string format_degrees(double radians);
double degrees_to_radians(double degrees);

// Whitespace-separated finite numbers; an error text when a token is not one (NaN, inf,
// out of range like 1e999, or garbage). A token may start with one '+' followed by a digit or
// '.' ("+1.5", "+.5"; not "+-5", "++5").
struct NumberList {
  std::vector<double> values;
  std::string error;  // empty on success
};
NumberList parse_numbers(std::string_view text);

// A whole integer within int range, surrounding whitespace allowed: an optional '-' or one '+'
// then digits ("+5" yes; "+-5", "++5", "+", fractions and exponents no).
std::optional<int> parse_int(std::string_view text);

}  // namespace foldkit::io
