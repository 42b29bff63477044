#include "foldkit/io/cmml.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string_view>

#include <tinyxml2.h>

#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/number_format.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/io/xml_reader.hpp"
#include "text_lines.hpp"

namespace foldkit::io {
namespace {

using detail::has_name;
using tinyxml2::XMLElement;

std::pair<int, geometry::FoldCommand> read_fold(const detail::XmlInput& in, const XMLElement& e) {
  for (const XMLElement* c : in.children(e))
    if (!has_name(c, "EventNumber") && !has_name(c, "ID") && !has_name(c, "FoldAngle") && !has_name(c, "Velocity"))
      in.fail(*c, std::string("unknown element <") + c->Name() + "> in <Fold>");
  geometry::FoldCommand fold;
  fold.line = in.line(e);

  const XMLElement& ev = in.only_child(e, "EventNumber");
  const int event = in.integer(ev, "a non-negative integer");
  if (event < 0) in.fail(ev, "<EventNumber> must be a non-negative integer, found '" + in.leaf_text(ev) + "'");
  fold.joint_id = in.integer(in.only_child(e, "ID"), "an integer joint ID");

  const XMLElement& angle = in.only_child(e, "FoldAngle");
  const double degrees = in.number(angle);
  if (degrees < -180.0 || degrees > 180.0)
    in.fail(angle, "<FoldAngle> " + format_number(degrees) + " is outside [-180, 180] degrees");
  fold.angle = degrees_to_radians(degrees);

  const XMLElement& vel = in.only_child(e, "Velocity");
  const double speed = in.number(vel);
  if (!(speed > 0.0)) in.fail(vel, "<Velocity> must be positive (degrees per second), found " + format_number(speed));
  fold.speed = degrees_to_radians(speed);
  // A subnormal speed such as 5e-324 degrees/s is 0 rad/s once converted.
  if (!(fold.speed > 0.0))
    in.fail(vel, "<Velocity> must be positive (degrees per second), found " + format_number(speed) + " (too small)");
  return {event, fold};
}

[[noreturn]] void invalid(const geometry::FoldCommand& f, const std::string& what) {
  throw std::invalid_argument("write_cmml: joint " + std::to_string(f.joint_id) + " " + what);
}

// Degrees within [-180, 180], as read_cmml requires: angles within rounding of ±180° (and any
// beyond, which no sequence read from a file has) are written as ±180.
std::string angle_text(const geometry::FoldCommand& f) {
  if (!std::isfinite(f.angle)) invalid(f, "fold angle: not a finite number");
  const std::string text = format_degrees(std::clamp(f.angle, -M_PI, M_PI));
  const double degrees = parse_numbers(text).values.at(0);
  if (degrees > 180.0) return "180";
  if (degrees < -180.0) return "-180";
  return text;
}

// The <Velocity> text: positive degrees per second that read back to a positive, finite speed.
std::string speed_text(const geometry::FoldCommand& f) {
  if (!std::isfinite(f.speed)) invalid(f, "speed: not a finite number");
  if (!(f.speed > 0.0)) invalid(f, "speed must be positive, found " + format_number(f.speed));
  if (!std::isfinite(f.speed * (180.0 / M_PI)))
    invalid(f, "speed " + format_number(f.speed) + " rad/s in degrees: not a finite number");
  const std::string text = format_degrees(f.speed);
  const NumberList back = parse_numbers(text);
  if (!back.error.empty() || !(degrees_to_radians(back.values.at(0)) > 0.0))
    invalid(f, "speed " + format_number(f.speed) + " rad/s cannot be written: " + (back.error.empty() ? "too small" : back.error));
  return text;
}

// What the children of one <CMML> element add to a sequence being read.
struct CmmlReading {
  std::string title;
  bool titled = false;
  std::vector<std::pair<int, geometry::FoldCommand>> folds;

  void read(const detail::XmlInput& in, const XMLElement& root) {
    for (const XMLElement* c : in.children(root)) {
      if (has_name(c, "Title")) {
        if (titled) in.fail(*c, "<CMML> has more than one <Title>");
        titled = true;
        title = in.leaf_text(*c);
      } else if (has_name(c, "Fold")) {
        folds.push_back(read_fold(in, *c));
      } else {
        in.fail(*c, std::string("unknown element <") + c->Name() + "> in <CMML>");
      }
    }
  }
};

// Files from this size on are read a slice at a time (parse_cmml_sliced).
constexpr std::size_t kSlicedFrom = std::size_t(4) << 20;
constexpr std::size_t kSliceBytes = std::size_t(1) << 20;

}  // namespace

namespace detail {

std::optional<geometry::FoldSequence> parse_cmml_sliced(const std::string& text, const std::string& name, std::size_t slice_bytes) {
  // Only the plain shape foldkit writes: an optional declaration, <CMML>, then elements and text
  // with no comment, CDATA section, processing instruction or DOCTYPE (whose text could hold
  // "</Fold>"), and nothing after </CMML>. Anything else is read whole.
  const std::size_t open = text.find("<CMML>");
  const std::size_t close = text.rfind("</CMML>");
  if (open == std::string::npos || close == std::string::npos || close < open) return std::nullopt;
  std::string_view prefix(text.data(), open);
  if (prefix.substr(0, 3) == "\xEF\xBB\xBF") prefix.remove_prefix(3);
  if (prefix.substr(0, 5) == "<?xml") {
    const std::size_t end = prefix.find("?>");
    if (end == std::string_view::npos) return std::nullopt;
    prefix.remove_prefix(end + 2);
  }
  const std::string_view body(text.data() + open + 6, close - open - 6);
  if (!detail::blank(prefix) || !detail::blank(std::string_view(text).substr(close + 7)) || body.find("<!") != std::string_view::npos ||
      body.find("<?") != std::string_view::npos || body.find("<CMML") != std::string_view::npos || body.find("</CMML") != std::string_view::npos)
    return std::nullopt;
  CmmlReading reading;
  int line = line_at(text, open);
  try {
    for (std::size_t at = 0; at < body.size();) {
      std::size_t end = std::min(body.size(), at + std::max<std::size_t>(slice_bytes, 1));
      if (end < body.size()) {
        const std::size_t fold_end = body.find("</Fold>", end);
        end = fold_end == std::string_view::npos ? body.size() : fold_end + 7;
      }
      // The slice keeps its lines: it starts on the line <CMML> or the last slice ended on.
      const std::string piece = (at == 0 ? text.substr(0, open) : std::string()) + "<CMML>" + std::string(body.substr(at, end - at)) + "</CMML>";
      const detail::XmlInput in(piece, name, at == 0 ? 1 : line);
      reading.read(in, in.root("CMML"));
      line += static_cast<int>(std::count(body.begin() + at, body.begin() + end, '\n'));
      at = end;
    }
  } catch (const ParseError&) {
    return std::nullopt;  // the whole file's reading says what is wrong, and where
  }
  return geometry::make_sequence(std::move(reading.title), std::move(reading.folds));
}

}  // namespace detail

namespace {

geometry::FoldSequence parse_cmml_whole(const std::string& text, const std::string& name) {
  detail::XmlInput in(text, name);
  CmmlReading reading;
  reading.read(in, in.root("CMML"));
  return geometry::make_sequence(std::move(reading.title), std::move(reading.folds));
}

}  // namespace

// A CMML of thousands of folds (projected folding writes every crease at every step: 308,000
// <Fold> elements, 49 MB, for a Miura-ori 40 × 40) is read a slice of elements at a time, so that
// only one slice's document is in memory; the result is that of reading it whole, and a file the
// slices cannot read is read whole for its error.
geometry::FoldSequence parse_cmml(const std::string& text, const std::string& name) {
  if (text.size() >= kSlicedFrom)
    if (auto sequence = detail::parse_cmml_sliced(text, name, kSliceBytes)) return std::move(*sequence);
  return parse_cmml_whole(text, name);
}

geometry::FoldSequence read_cmml(const std::string& path) { return parse_cmml(read_file(path), path); }

std::string write_cmml(const geometry::FoldSequence& sequence) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<CMML>\n";
  out << "  <Title>" << detail::escape_xml(sequence.title) << "</Title>\n";
  for (const auto& event : sequence.events)
    for (const auto& f : event.folds)
      out << "  <Fold>\n    <EventNumber>" << event.number << "</EventNumber>\n    <ID>" << f.joint_id
          << "</ID>\n    <FoldAngle>" << angle_text(f) << "</FoldAngle>\n    <Velocity>" << speed_text(f)
          << "</Velocity>\n  </Fold>\n";
  out << "</CMML>\n";
  return out.str();
}

}  // namespace foldkit::io
