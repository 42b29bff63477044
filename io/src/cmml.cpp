#include "foldkit/io/cmml.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include <tinyxml2.h>

#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/number_format.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/io/xml_reader.hpp"

namespace foldkit::io {
namespace {

using detail::has_name;
using tinyxml2::XMLElement;

std::pair<int, geometry::FoldCommand> read_fold(const detail::XmlInput& in, const XMLElement& e) {
  for (const XMLElement* c : in.children(e))
    if (!has_name(c, "EventNumber") && !has_name(c, "ID") && !has_name(c, "FoldAngle") && !has_name(c, "Velocity"))
      in.fail(*c, std::string("unknown element <") + c->Name() + "> in <Fold>");
  geometry::FoldCommand fold;
  fold.line = e.GetLineNum();

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
  fold.velocity = degrees_to_radians(speed);
  // A subnormal speed such as 5e-324 degrees/s is 0 rad/s once converted.
  if (!(fold.velocity > 0.0))
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

// Positive degrees per second that read back to a positive, finite velocity.
std::string velocity_text(const geometry::FoldCommand& f) {
  if (!std::isfinite(f.velocity)) invalid(f, "velocity: not a finite number");
  if (!(f.velocity > 0.0)) invalid(f, "velocity must be positive, found " + format_number(f.velocity));
  if (!std::isfinite(f.velocity * (180.0 / M_PI)))
    invalid(f, "velocity " + format_number(f.velocity) + " rad/s in degrees: not a finite number");
  const std::string text = format_degrees(f.velocity);
  const NumberList back = parse_numbers(text);
  if (!back.error.empty() || !(degrees_to_radians(back.values.at(0)) > 0.0))
    invalid(f, "velocity " + format_number(f.velocity) + " rad/s cannot be written: " + (back.error.empty() ? "too small" : back.error));
  return text;
}

}  // namespace

geometry::FoldSequence parse_cmml(const std::string& text, const std::string& name) {
  detail::XmlInput in(text, name);
  const XMLElement& root = in.root("CMML");
  std::string title;
  bool titled = false;
  std::vector<std::pair<int, geometry::FoldCommand>> folds;
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
  return geometry::make_sequence(std::move(title), std::move(folds));
}

geometry::FoldSequence read_cmml(const std::string& path) { return parse_cmml(read_file(path), path); }

std::string write_cmml(const geometry::FoldSequence& sequence) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<CMML>\n";
  out << "  <Title>" << detail::escape_xml(sequence.title) << "</Title>\n";
  for (const auto& event : sequence.events)
    for (const auto& f : event.folds)
      out << "  <Fold>\n    <EventNumber>" << event.number << "</EventNumber>\n    <ID>" << f.joint_id
          << "</ID>\n    <FoldAngle>" << angle_text(f) << "</FoldAngle>\n    <Velocity>" << velocity_text(f)
          << "</Velocity>\n  </Fold>\n";
  out << "</CMML>\n";
  return out.str();
}

}  // namespace foldkit::io
