#pragma once
/// @file
/// Number text of foldkit's file formats: shortest round-trip decimals, degrees of angles kept
/// in radians, and strict number parsing.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace foldkit::io {

/// Shortest decimal text that reads back to exactly `value`; −0 is written as "0" (files never
/// carry a signed zero).
std::string format_number(double value);

/// Degrees for a value kept in radians: the shortest decimal d with d·π/180 == radians when
/// there is one (always for angles read from a file, so they are written back unchanged), else
/// the nearest degrees; the reading is then within one unit in the last place.
std::string format_degrees(double radians);
/// The most characters format_degrees writes.
inline constexpr std::size_t kDegreesChars = 32;
/// format_degrees(radians) into `out` (room for kDegreesChars), without allocating: for writers
/// of hundreds of thousands of angles. @return the text's length
std::size_t format_degrees(double radians, char* out);
/// degrees · π/180, the conversion every reader uses.
double degrees_to_radians(double degrees);

/// Whitespace-separated finite numbers; an error text when a token is not one (NaN, inf,
/// out of range like 1e999, or garbage). A token may start with one '+' followed by a digit or
/// '.' ("+1.5", "+.5"; not "+-5", "++5").
struct NumberList {
  std::vector<double> values;  ///< the numbers read, up to the first bad token
  std::string error;           ///< empty on success
};
/// Reads every whitespace-separated number of `text` (see NumberList); stops at the first token
/// that is not a finite number, with the error set.
NumberList parse_numbers(std::string_view text);

/// A whole integer within int range, surrounding whitespace allowed: an optional '-' or one '+'
/// then digits ("+5" yes; "+-5", "++5", "+", fractions and exponents no).
/// @return the integer, or nothing when `text` is not one
std::optional<int> parse_int(std::string_view text);

}  // namespace foldkit::io
