// A PMML read without an XML parser when it is in the plain shape foldkit writes (write_pmml).
// A Miura 100×100 is 30,000 actors and 20,000 joints (6 MB): tinyxml2's document, its checks and
// XmlInput's strings took 0.13–0.17 s, a third of `foldkit dof` on it. Anything out of that shape
// declines, and the file is read by XML as before: errors are reported as they were, at their
// lines. What is accepted is read exactly as parse_pmml's XML reading reads it (the same number
// parsers; test/io/pmml_plain_test.cpp compares the two).
#include <array>
#include <optional>
#include <string_view>

#include "foldkit/io/number_format.hpp"
#include "foldkit/io/pmml.hpp"
#include "plain_cursor.hpp"

namespace foldkit::io::detail {
namespace {

// Exactly `count` finite numbers, as XmlInput::numbers(e, count) reads them.
template <std::size_t N>
bool numbers(PlainCursor& in, std::string_view open, std::string_view close, std::array<double, N>& out) {
  bool found = false;
  const std::string_view text = in.leaf(open, close, number_list_char, found);
  if (!found) return false;
  const NumberList list = parse_numbers(text);
  if (!list.error.empty() || list.values.size() != N) return false;
  for (std::size_t k = 0; k < N; ++k) out[k] = list.values[k];
  return true;
}

bool number(PlainCursor& in, std::string_view open, std::string_view close, double& out) {
  std::array<double, 1> v{};
  if (!numbers(in, open, close, v)) return false;
  out = v[0];
  return true;
}

bool integer(PlainCursor& in, std::string_view open, std::string_view close, int& out) {
  const std::optional<int> v = parse_int(in.leaf(open, close));
  if (v) out = *v;
  return v.has_value();
}

// Title text: printable ASCII that needs no entity, on one line (XmlInput::leaf_text, trimmed).
bool title_char(char c) { return c == '\t' || (c >= 0x20 && c <= 0x7E && c != '<' && c != '>' && c != '&'); }

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// <Actor> at the cursor: <ID>, then one or more <Triangle>.
bool actor(PlainCursor& in, geometry::ActorSpec& a) {
  a.line = in.line();
  if (!in.take("<Actor>") || !integer(in, "<ID>", "</ID>", a.id)) return false;
  for (in.skip_space(); in.at("<Triangle>"); in.skip_space()) {
    geometry::TriangleSpec t;
    t.line = in.line();
    std::array<double, 6> v{};
    if (!numbers(in, "<Triangle>", "</Triangle>", v)) return false;
    t.corners = {geometry::Vec2(v[0], v[1]), geometry::Vec2(v[2], v[3]), geometry::Vec2(v[4], v[5])};
    a.triangles.push_back(t);
  }
  return !a.triangles.empty() && in.take("</Actor>");
}

bool assignment(PlainCursor& in, geometry::Assignment& out) {
  const auto letter = [](char c) { return c == 'M' || c == 'V' || c == 'F' || c == 'U'; };
  bool found = false;
  const std::string_view t = in.leaf("<Assignment>", "</Assignment>", letter, found);
  if (!found || t.size() != 1) return false;
  out = t[0] == 'M' ? geometry::Assignment::Mountain
        : t[0] == 'V' ? geometry::Assignment::Valley
        : t[0] == 'F' ? geometry::Assignment::Flat
                      : geometry::Assignment::Unassigned;
  return true;
}

// <Joint> at the cursor, its children in write_pmml's order.
bool joint(PlainCursor& in, geometry::JointSpec& j) {
  j.line = in.line();
  std::array<double, 4> c{};
  bool found = false;
  if (!in.take("<Joint>") || !integer(in, "<ID>", "</ID>", j.id) || !numbers(in, "<Coords>", "</Coords>", c)) return false;
  j.coords = {geometry::Vec2(c[0], c[1]), geometry::Vec2(c[2], c[3])};
  // Two integer tokens, as read_joint() splits them.
  const std::string_view ids = in.leaf("<ActorIDs>", "</ActorIDs>", number_list_char, found);
  if (!found) return false;
  int count = 0;
  for (std::size_t at = 0; at < ids.size();) {
    while (at < ids.size() && (ids[at] == ' ' || ids[at] == '\t')) ++at;
    std::size_t end = at;
    while (end < ids.size() && ids[end] != ' ' && ids[end] != '\t') ++end;
    if (end == at) break;
    const std::optional<int> v = parse_int(ids.substr(at, end - at));
    if (!v || count == 2) return false;
    j.actor_ids[count++] = *v;
    at = end;
  }
  if (count != 2 || !number(in, "<SpringConst>", "</SpringConst>", j.spring) ||
      !number(in, "<DampConst>", "</DampConst>", j.damping))
    return false;
  in.skip_space();
  if (in.at("<Assignment>") && !assignment(in, j.assignment)) return false;
  in.skip_space();
  if (in.at("<MaxTorque>") && !number(in, "<MaxTorque>", "</MaxTorque>", j.max_torque.emplace())) return false;
  in.skip_space();
  return in.take("</Joint>");
}

// One child of <PMML> at the cursor (after its white space); false for anything else, or a
// second <Title> or physics element (which XML reading refuses).
bool child(PlainCursor& in, geometry::PatternSpec& spec, bool& titled) {
  geometry::PhysicsSpec& physics = spec.physics;
  const int line = in.line();
  if (in.at("<Actor>")) return actor(in, spec.actors.emplace_back());
  if (in.at("<Joint>")) return joint(in, spec.joints.emplace_back());
  if (in.at("<Title>")) {
    bool found = false;
    const std::string_view text = in.leaf("<Title>", "</Title>", title_char, found);
    if (!found || titled) return false;
    titled = true;
    spec.title = std::string(trimmed(text));
    return true;
  }
  if (in.at("<Density>")) {
    physics.density_line = line;
    return !physics.density && number(in, "<Density>", "</Density>", physics.density.emplace());
  }
  if (in.at("<Gravity>")) {
    std::array<double, 3> g{};
    if (physics.gravity || !numbers(in, "<Gravity>", "</Gravity>", g)) return false;
    physics.gravity = geometry::Vec3(g[0], g[1], g[2]);
    physics.gravity_line = line;
    return true;
  }
  if (in.at("<FixedActor>")) {
    physics.fixed_actor_line = line;
    return !physics.fixed_actor && integer(in, "<FixedActor>", "</FixedActor>", physics.fixed_actor.emplace());
  }
  return false;
}

}  // namespace

std::optional<geometry::PatternSpec> read_plain_pmml(std::string_view text) {
  PlainCursor in(text, 1);
  in.take("<?xml version=\"1.0\" encoding=\"UTF-8\"?>");
  in.skip_space();
  if (!in.take("<PMML>")) return std::nullopt;
  geometry::PatternSpec spec;
  bool titled = false;
  for (in.skip_space(); !in.take("</PMML>"); in.skip_space())
    if (!child(in, spec, titled)) return std::nullopt;
  in.skip_space();
  if (!in.done() || spec.actors.empty()) return std::nullopt;
  return spec;
}

}  // namespace foldkit::io::detail
