#include "foldkit/io/cmml.hpp"

#include <cstring>
#include <sstream>

#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/number_format.hpp"
#include "foldkit/io/parse_error.hpp"
#include "xml_reader.hpp"

namespace foldkit::io {
namespace {

using tinyxml2::XMLElement;

bool is(const XMLElement* e, const char* tag) { return std::strcmp(e->Name(), tag) == 0; }

double number(const detail::XmlInput& in, const XMLElement& e) {
  NumberList list = parse_numbers(in.leaf_text(e));
  if (!list.error.empty()) in.fail(e, std::string("<") + e.Name() + ">: " + list.error);
  if (list.values.size() != 1) in.fail(e, std::string("<") + e.Name() + "> must hold one number");
  return list.values[0];
}

std::pair<int, geometry::FoldCommand> read_fold(const detail::XmlInput& in, const XMLElement& e) {
  for (const XMLElement* c : in.children(e))
    if (!is(c, "EventNumber") && !is(c, "ID") && !is(c, "FoldAngle") && !is(c, "Velocity"))
      in.fail(*c, std::string("unknown element <") + c->Name() + "> in <Fold>");
  geometry::FoldCommand fold;
  fold.line = e.GetLineNum();

  const XMLElement& ev = in.only_child(e, "EventNumber");
  const std::string ev_text = in.leaf_text(ev);
  auto event = parse_int(ev_text);
  if (!event || *event < 0)
    in.fail(ev, "<EventNumber> must be a non-negative integer, found '" + ev_text.substr(0, 40) + "'");

  const XMLElement& id = in.only_child(e, "ID");
  const std::string id_text = in.leaf_text(id);
  auto joint = parse_int(id_text);
  if (!joint) in.fail(id, "<ID> must be an integer joint ID, found '" + id_text.substr(0, 40) + "'");
  fold.joint_id = *joint;

  const XMLElement& angle = in.only_child(e, "FoldAngle");
  const double degrees = number(in, angle);
  if (degrees < -180.0 || degrees > 180.0)
    in.fail(angle, "<FoldAngle> " + format_number(degrees) + " is outside [-180, 180] degrees");
  fold.angle = degrees_to_radians(degrees);

  const XMLElement& vel = in.only_child(e, "Velocity");
  const double speed = number(in, vel);
  if (!(speed > 0.0)) in.fail(vel, "<Velocity> must be positive (degrees per second), found " + format_number(speed));
  fold.velocity = degrees_to_radians(speed);
  return {*event, fold};
}

}  // namespace

geometry::FoldSequence parse_cmml(const std::string& text, const std::string& name) {
  detail::XmlInput in(text, name);
  const XMLElement& root = in.root("CMML");
  std::string title;
  bool titled = false;
  std::vector<std::pair<int, geometry::FoldCommand>> folds;
  for (const XMLElement* c : in.children(root)) {
    if (is(c, "Title")) {
      if (titled) in.fail(*c, "<CMML> has more than one <Title>");
      titled = true;
      title = in.leaf_text(*c);
    } else if (is(c, "Fold")) {
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
          << "</ID>\n    <FoldAngle>" << format_degrees(f.angle) << "</FoldAngle>\n    <Velocity>"
          << format_degrees(f.velocity) << "</Velocity>\n  </Fold>\n";
  out << "</CMML>\n";
  return out.str();
}

}  // namespace foldkit::io
