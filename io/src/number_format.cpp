#include "foldkit/io/number_format.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <system_error>

namespace foldkit::io {

std::string format_number(double value) {
  if (value == 0.0) return "0";  // also turns -0 into 0: files never carry a signed zero
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
  return ec == std::errc() ? std::string(buf, end) : std::string("nan");
}

// Inline here: the exported function is not inlined into exact_degrees' nine calls per angle
// (it could be interposed), and the call was a tenth of writing a CMML.
static inline double to_radians(double degrees) { return degrees * (M_PI / 180.0); }
double degrees_to_radians(double degrees) { return to_radians(degrees); }

namespace {

// Significant digits of the shortest decimal that reads back as `value`. (Counted on the
// scientific form: the fixed form of a large integer spells out all its digits, not the shortest.)
int shortest_digits(double value) {
  char buf[kDegreesChars];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::scientific);
  int digits = 0;
  for (const char* c = buf; c != end && *c != 'e'; ++c) digits += *c >= '0' && *c <= '9';
  return ec == std::errc() ? digits : 17;
}

// Fewest significant digits whose reading maps back to exactly `radians`, if any does, written
// to `out` (its length; 0 for none). The preimage need not be the rounded product
// radians·180/π itself, so its neighbours are tried. A decimal reads as one double; so the
// fewest digits that map back are the shortest round-trip form (to_chars without precision) of
// the neighbour that maps back with the fewest. Trying every precision 1…17 on every neighbour
// gave the same answer at ~150 conversions per angle, which made writing a large fold's CMML
// slower than folding it (NumberFormat.DegreesMatchEveryPrecisionSearch keeps that search as the
// oracle). `radians` is not 0, so no candidate that maps back is ±0.
std::size_t exact_degrees(double radians, char* out) {
  const double degrees = radians * (180.0 / M_PI);
  std::optional<double> best;
  int best_digits = 0;
  auto consider = [&](double d) {
    if (to_radians(d) != radians) return;
    const int digits = shortest_digits(d);
    if (!best || digits < best_digits) best = d, best_digits = digits;  // ties keep the earlier, nearer one
  };
  consider(degrees);
  double up = degrees, down = degrees;
  for (int i = 0; i < 4; ++i) {
    consider(up = std::nextafter(up, HUGE_VAL));
    consider(down = std::nextafter(down, -HUGE_VAL));
  }
  if (!best) return 0;
  const auto [end, ec] = std::to_chars(out, out + kDegreesChars, *best);
  return ec == std::errc() ? static_cast<std::size_t>(end - out) : 0;
}

}  // namespace

std::size_t format_degrees(double radians, char* out) {
  if (radians == 0.0) {
    out[0] = '0';
    return 1;
  }
  // "30" read from a file is written as "30" again. Not every double in radians is d·π/180 for
  // a decimal d: those are written as the degrees of the nearest value that is, which then
  // reads back to itself, so a written file is stable under read and write.
  if (const std::size_t size = exact_degrees(radians, out)) return size;
  if (const std::size_t size = exact_degrees(degrees_to_radians(radians * (180.0 / M_PI)), out)) return size;
  const auto [end, ec] = std::to_chars(out, out + kDegreesChars, radians * (180.0 / M_PI));
  if (ec == std::errc()) return static_cast<std::size_t>(end - out);
  std::memcpy(out, "nan", 3);
  return 3;
}

std::string format_degrees(double radians) {
  char text[kDegreesChars];
  return std::string(text, format_degrees(radians, text));
}

NumberList parse_numbers(std::string_view text) {
  NumberList out;
  std::size_t i = 0;
  auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  while (i < text.size()) {
    while (i < text.size() && is_space(text[i])) ++i;
    if (i == text.size()) break;
    std::size_t j = i;
    while (j < text.size() && !is_space(text[j])) ++j;
    const std::string_view token = text.substr(i, j - i);
    double value = 0.0;
    // from_chars accepts "nan"/"inf" and a leading '+' is not accepted: allow one '+' explicitly,
    // followed by a digit or '.' (so not "+-5", "++5" or "+inf").
    const std::string_view digits = token.size() > 1 && token[0] == '+' ? token.substr(1) : token;
    if (digits.size() != token.size() && !(std::isdigit(static_cast<unsigned char>(digits[0])) || digits[0] == '.')) {
      out.error = "'" + std::string(token.substr(0, 40)) + "' is not a number";
      return out;
    }
    auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec == std::errc::result_out_of_range) {
      out.error = "number '" + std::string(token) + "' is out of range";
      return out;
    }
    if (ec != std::errc() || end != digits.data() + digits.size()) {
      out.error = "'" + std::string(token.substr(0, 40)) + "' is not a number";
      return out;
    }
    if (!std::isfinite(value)) {
      out.error = "'" + std::string(token) + "' is not a finite number";
      return out;
    }
    out.values.push_back(value);
    i = j;
  }
  return out;
}

std::optional<int> parse_int(std::string_view text) {
  while (!text.empty() && (text.front() == ' ' || text.front() == '\t' || text.front() == '\n' || text.front() == '\r'))
    text.remove_prefix(1);
  while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\n' || text.back() == '\r'))
    text.remove_suffix(1);
  if (text.empty()) return std::nullopt;
  // One leading '+' is accepted, as parse_numbers does; the rest must then start with a digit.
  if (text.front() == '+') {
    text.remove_prefix(1);
    if (text.empty() || !std::isdigit(static_cast<unsigned char>(text.front()))) return std::nullopt;
  }
  int value = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

}  // namespace foldkit::io
