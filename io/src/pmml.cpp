#include "foldkit/io/pmml.hpp"

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

using geometry::Assignment;
using detail::has_name;
using tinyxml2::XMLElement;

Assignment assignment(const detail::XmlInput& in, const XMLElement& e) {
  const std::string t = in.leaf_text(e);
  if (t == "M") return Assignment::Mountain;
  if (t == "V") return Assignment::Valley;
  if (t == "F") return Assignment::Flat;
  if (t == "U") return Assignment::Unassigned;
  in.fail(e, "<Assignment> must be M, V, F or U, found '" + t.substr(0, 40) + "'");
}

geometry::ActorSpec read_actor(const detail::XmlInput& in, const XMLElement& e) {
  geometry::ActorSpec actor;
  actor.line = e.GetLineNum();
  actor.id = in.integer(in.only_child(e, "ID"), "an integer");
  for (const XMLElement* c : in.children(e)) {
    if (has_name(c, "ID")) continue;
    if (!has_name(c, "Triangle")) in.fail(*c, std::string("unknown element <") + c->Name() + "> in <Actor>");
    const auto v = in.numbers(*c, 6);
    actor.triangles.push_back({{geometry::Vec2(v[0], v[1]), geometry::Vec2(v[2], v[3]), geometry::Vec2(v[4], v[5])}, c->GetLineNum()});
  }
  if (actor.triangles.empty()) in.fail(e, "<Actor> " + std::to_string(actor.id) + " has no <Triangle>");
  return actor;
}

geometry::JointSpec read_joint(const detail::XmlInput& in, const XMLElement& e) {
  static const char* const known[] = {"ID", "Coords", "ActorIDs", "SpringConst", "DampConst", "Assignment", "MaxTorque"};
  for (const XMLElement* c : in.children(e)) {
    bool ok = false;
    for (const char* k : known) ok = ok || has_name(c, k);
    if (!ok) in.fail(*c, std::string("unknown element <") + c->Name() + "> in <Joint>");
  }
  geometry::JointSpec joint;
  joint.line = e.GetLineNum();
  joint.id = in.integer(in.only_child(e, "ID"), "an integer");
  const auto c = in.numbers(in.only_child(e, "Coords"), 4);
  joint.coords = {geometry::Vec2(c[0], c[1]), geometry::Vec2(c[2], c[3])};
  const XMLElement& ids = in.only_child(e, "ActorIDs");
  std::istringstream tokens(in.leaf_text(ids));
  std::string token;
  std::vector<int> actor_ids;
  while (tokens >> token) {
    auto v = parse_int(token);
    if (!v) in.fail(ids, "<ActorIDs> must hold two integer actor IDs, found '" + token.substr(0, 40) + "'");
    actor_ids.push_back(*v);
  }
  if (actor_ids.size() != 2)
    in.fail(ids, "<ActorIDs> must hold two actor IDs, found " + std::to_string(actor_ids.size()));
  joint.actor_ids = {actor_ids[0], actor_ids[1]};
  joint.spring = in.number(in.only_child(e, "SpringConst"));
  joint.damping = in.number(in.only_child(e, "DampConst"));
  if (e.FirstChildElement("Assignment")) joint.assignment = assignment(in, in.only_child(e, "Assignment"));
  // foldkit's extension: the joint's motor torque limit in the dynamic model, N·m (checked when built).
  if (e.FirstChildElement("MaxTorque")) joint.max_torque = in.number(in.only_child(e, "MaxTorque"));
  return joint;
}

// foldkit's extensions for the dynamic model, children of <PMML> (docs/FORMATS.md); false for
// any other element. Their values are checked when the pattern is built, each at its line.
bool read_physics(const detail::XmlInput& in, const XMLElement& e, geometry::PhysicsSpec& physics) {
  const auto once = [&](bool set) {
    if (set) in.fail(e, std::string("<PMML> has more than one <") + e.Name() + ">");
  };
  if (has_name(&e, "Density")) {
    once(physics.density.has_value());
    physics.density = in.number(e);
    physics.density_line = in.line(e);
  } else if (has_name(&e, "Gravity")) {
    once(physics.gravity.has_value());
    const auto g = in.numbers(e, 3);
    physics.gravity = geometry::Vec3(g[0], g[1], g[2]);
    physics.gravity_line = in.line(e);
  } else if (has_name(&e, "FixedActor")) {
    once(physics.fixed_actor.has_value());
    physics.fixed_actor = in.integer(e, "an actor ID");
    physics.fixed_actor_line = in.line(e);
  } else {
    return false;
  }
  return true;
}

}  // namespace

geometry::PatternSpec parse_pmml(const std::string& text, const std::string& name) {
  // foldkit's own files skip the XML document (pmml_plain.cpp: a third of `dof` at 100×100).
  if (std::optional<geometry::PatternSpec> plain = detail::read_plain_pmml(text)) return std::move(*plain);
  return detail::parse_pmml_xml(text, name);
}

geometry::PatternSpec detail::parse_pmml_xml(const std::string& text, const std::string& name) {
  detail::XmlInput in(text, name);
  const XMLElement& root = in.root("PMML");
  geometry::PatternSpec spec;
  bool titled = false;
  for (const XMLElement* c : in.children(root)) {
    if (has_name(c, "Title")) {
      if (titled) in.fail(*c, "<PMML> has more than one <Title>");
      titled = true;
      spec.title = in.leaf_text(*c);
    } else if (has_name(c, "Actor")) {
      spec.actors.push_back(read_actor(in, *c));
    } else if (has_name(c, "Joint")) {
      spec.joints.push_back(read_joint(in, *c));
    } else if (!read_physics(in, *c, spec.physics)) {
      in.fail(*c, std::string("unknown element <") + c->Name() + "> in <PMML>");
    }
  }
  if (spec.actors.empty()) in.fail(root, "<PMML> has no <Actor>");
  return spec;
}

geometry::PatternSpec read_pmml_spec(const std::string& path) { return parse_pmml(read_file(path), path); }

geometry::CreasePattern read_pmml(const std::string& path, const geometry::BuildOptions& options) {
  const geometry::PatternSpec spec = read_pmml_spec(path);
  geometry::BuildResult built = geometry::build_pattern(spec, options);
  if (built.pattern) return std::move(*built.pattern);
  std::size_t errors = 0;
  const geometry::Diagnostic* first = nullptr;
  for (const auto& d : built.diagnostics)
    if (d.severity == geometry::Severity::Error && ++errors == 1) first = &d;
  std::string message = first->message;
  if (errors > 1) message += " (and " + std::to_string(errors - 1) + " more errors: run 'foldkit validate' to list them)";
  throw ParseError(path, first->line, message);
}

namespace {

// A finite number as text; `what` names it in the std::invalid_argument otherwise.
std::string finite(double value, const std::string& what) {
  if (!std::isfinite(value)) throw std::invalid_argument("write_pmml: " + what + ": not a finite number");
  return format_number(value);
}

}  // namespace

std::string write_pmml(const geometry::PatternSpec& spec) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<PMML>\n";
  out << "  <Title>" << detail::escape_xml(spec.title) << "</Title>\n";
  // foldkit's extensions, only when set: a plain PMML writes back as the paper's Table 1.
  const geometry::PhysicsSpec& physics = spec.physics;
  if (physics.density) out << "  <Density>" << finite(*physics.density, "density") << "</Density>\n";
  if (physics.gravity) {
    const std::string what = "gravity";
    out << "  <Gravity>" << finite(physics.gravity->x(), what) << ' ' << finite(physics.gravity->y(), what) << ' '
        << finite(physics.gravity->z(), what) << "</Gravity>\n";
  }
  if (physics.fixed_actor) out << "  <FixedActor>" << *physics.fixed_actor << "</FixedActor>\n";
  for (const auto& a : spec.actors) {
    out << "  <Actor>\n    <ID>" << a.id << "</ID>\n";
    for (const auto& t : a.triangles) {
      out << "    <Triangle>";
      const std::string what = "actor " + std::to_string(a.id) + " triangle coordinate";
      for (int k = 0; k < 3; ++k)
        out << (k ? " " : "") << finite(t.corners[k].x(), what) << ' ' << finite(t.corners[k].y(), what);
      out << "</Triangle>\n";
    }
    out << "  </Actor>\n";
  }
  for (const auto& j : spec.joints) {
    const std::string joint = "joint " + std::to_string(j.id);
    const std::string coords = joint + " coordinate";
    out << "  <Joint>\n    <ID>" << j.id << "</ID>\n    <Coords>" << finite(j.coords[0].x(), coords) << ' '
        << finite(j.coords[0].y(), coords) << ' ' << finite(j.coords[1].x(), coords) << ' ' << finite(j.coords[1].y(), coords)
        << "</Coords>\n    <ActorIDs>" << j.actor_ids[0] << ' ' << j.actor_ids[1] << "</ActorIDs>\n    <SpringConst>"
        << finite(j.spring, joint + " spring constant") << "</SpringConst>\n    <DampConst>"
        << finite(j.damping, joint + " damping constant") << "</DampConst>\n";
    if (j.assignment != Assignment::Unassigned) out << "    <Assignment>" << geometry::to_string(j.assignment) << "</Assignment>\n";
    if (j.max_torque) out << "    <MaxTorque>" << finite(*j.max_torque, joint + " maximum torque") << "</MaxTorque>\n";
    out << "  </Joint>\n";
  }
  out << "</PMML>\n";
  return out.str();
}

std::string write_pmml(const geometry::CreasePattern& pattern) { return write_pmml(pattern.to_spec()); }

}  // namespace foldkit::io
