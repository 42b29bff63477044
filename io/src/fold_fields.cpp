// FOLD's keys, read and type-checked frame by frame; frame_inherit.
#include "fold_fields.hpp"

#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>

#include "foldkit/io/number_format.hpp"
#include "foldkit/io/parse_error.hpp"

namespace foldkit::io::detail {

using geometry::Diagnostic;
using geometry::Severity;
using geometry::Vec3;

std::string indexed(const std::string& name, std::size_t i) { return name + "[" + std::to_string(i) + "]"; }

std::string describe(const json& v) {
  switch (v.type()) {
    case json::value_t::null: return "null";
    case json::value_t::boolean: return v.get<bool>() ? "true" : "false";
    case json::value_t::string: {
      const auto& s = v.get_ref<const std::string&>();
      return "a string (\"" + printable(s.substr(0, 20)) + (s.size() > 20 ? "…" : "") + "\")";
    }
    case json::value_t::array: return "an array";
    case json::value_t::object: return "an object";
    default: return "a number";
  }
}

void Reader::fail(const Loc& at, const std::string& what, const std::string& message) const {
  throw ParseError(name_, at.line, what.empty() ? message : what + ": " + message);
}

void Reader::warn(const Loc& at, const std::string& what, const std::string& message) {
  warnings_.push_back(Diagnostic{Severity::Warning, at.line, what.empty() ? message : what + ": " + message});
}

double Reader::number(const json& v, const Loc& at, const std::string& what) const {
  if (!v.is_number()) fail(at, what, "expected a number, found " + describe(v));
  const double d = v.get<double>();
  if (!std::isfinite(d)) fail(at, what, "not a finite number");
  return d;
}

RawIndex Reader::index(const json& v, const Loc& at, const std::string& what) const {
  constexpr auto kMax = static_cast<double>(std::numeric_limits<int>::max());
  if (v.is_number_unsigned()) {
    const auto u = v.get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) fail(at, what, "index too large");
    return static_cast<RawIndex>(u);
  }
  if (v.is_number_integer()) {
    const auto s = v.get<std::int64_t>();
    if (s > std::numeric_limits<int>::max() || s < std::numeric_limits<int>::min()) fail(at, what, "index too large");
    return s;
  }
  if (v.is_number_float()) {
    const double d = v.get<double>();
    if (std::isfinite(d) && d == std::floor(d) && std::abs(d) <= kMax) return static_cast<RawIndex>(d);
    fail(at, what, "expected a whole number as index, found " + format_number(d));
  }
  fail(at, what, "expected an index, found " + describe(v));
}

template <class T>
const json* Reader::array_field(const json& obj, const Loc& at, const std::string& prefix, const char* key,
                                Field<T>& field, const char* expected) const {
  const auto it = obj.find(key);
  if (it == obj.end()) return nullptr;
  field.present = true;
  field.loc = lines_.member(at, key);
  field.name = prefix + key;
  if (!it->is_array()) fail(field.loc, field.name, std::string("expected ") + expected + ", found " + describe(*it));
  return &*it;
}

void Reader::read_coords(const json& obj, const Loc& at, const std::string& prefix, const char* key, Field<Coords>& f) {
  const json* arr = array_field(obj, at, prefix, key, f, "an array of [x, y] or [x, y, z]");
  if (!arr) return;
  for (std::size_t i = 0; i < arr->size(); ++i) {
    const json& p = (*arr)[i];
    const Loc pl = lines_.item(f.loc, i);
    const std::string what = indexed(f.name, i);
    if (!p.is_array()) fail(pl, what, "expected [x, y] or [x, y, z], found " + describe(p));
    if (p.size() != 2 && p.size() != 3)
      fail(pl, what, "expected 2 or 3 coordinates, found " + std::to_string(p.size()));
    Vec3 q = Vec3::Zero();
    for (std::size_t j = 0; j < p.size(); ++j)
      q[static_cast<Eigen::Index>(j)] = number(p[j], lines_.item(pl, j), indexed(what, j));
    f.value.three_d = f.value.three_d || p.size() == 3;
    f.value.points.push_back(q);
  }
}

void Reader::read_edges(const json& obj, const Loc& at, const std::string& prefix, RawFrame& frame) {
  auto& f = frame.edges;
  const json* arr = array_field(obj, at, prefix, "edges_vertices", f, "an array of [vertex, vertex]");
  if (!arr) return;
  for (std::size_t i = 0; i < arr->size(); ++i) {
    const json& e = (*arr)[i];
    const Loc el = lines_.item(f.loc, i);
    const std::string what = indexed(f.name, i);
    if (!e.is_array() || e.size() != 2)
      fail(el, what, "expected [vertex, vertex], found " +
                         (e.is_array() ? "an array of " + std::to_string(e.size()) : describe(e)));
    f.value.push_back({index(e[0], el, what), index(e[1], el, what)});
  }
}

void Reader::read_assignment(const json& obj, const Loc& at, const std::string& prefix, RawFrame& frame) {
  auto& f = frame.assignment;
  const json* arr = array_field(obj, at, prefix, "edges_assignment", f, "an array of letters");
  if (!arr) return;
  for (std::size_t i = 0; i < arr->size(); ++i) {
    const json& a = (*arr)[i];
    const Loc al = lines_.item(f.loc, i);
    const std::string text = a.is_string() ? a.get<std::string>() : std::string();
    const char letter = text.size() == 1 ? static_cast<char>(std::toupper(static_cast<unsigned char>(text[0]))) : '?';
    if (std::string_view("BMVFUCJ").find(letter) == std::string_view::npos)
      fail(al, indexed(f.name, i), "expected one of B, M, V, F, U, C, J, found " + describe(a));
    f.value.push_back(letter);
  }
}

void Reader::read_fold_angle(const json& obj, const Loc& at, const std::string& prefix, RawFrame& frame) {
  auto& f = frame.fold_angle;
  const json* arr = array_field(obj, at, prefix, "edges_foldAngle", f, "an array of degrees");
  if (!arr) return;
  for (std::size_t i = 0; i < arr->size(); ++i) {
    const json& a = (*arr)[i];
    if (a.is_null()) {
      f.value.emplace_back();
      continue;
    }
    const Loc al = lines_.item(f.loc, i);
    const double d = number(a, al, indexed(f.name, i));
    if (std::abs(d) > 180.0) fail(al, indexed(f.name, i), format_number(d) + "° is outside [-180, 180]");
    f.value.emplace_back(d);
  }
}

void Reader::read_faces(const json& obj, const Loc& at, const std::string& prefix, RawFrame& frame) {
  auto& f = frame.faces;
  const json* arr = array_field(obj, at, prefix, "faces_vertices", f, "an array of vertex lists");
  if (!arr) return;
  for (std::size_t i = 0; i < arr->size(); ++i) {
    const json& face = (*arr)[i];
    const Loc fl = lines_.item(f.loc, i);
    const std::string what = indexed(f.name, i);
    if (!face.is_array()) fail(fl, what, "expected a list of vertices, found " + describe(face));
    if (face.size() < 3) fail(fl, what, "a face needs at least 3 vertices, found " + std::to_string(face.size()));
    std::vector<RawIndex> vs;
    for (std::size_t j = 0; j < face.size(); ++j) vs.push_back(index(face[j], lines_.item(fl, j), what));
    f.value.push_back(std::move(vs));
  }
}

void Reader::read_metadata(const json& obj, const Loc& at, const std::string& prefix, RawFrame& frame) {
  if (const auto it = obj.find("frame_title"); it != obj.end()) {
    if (it->is_string()) {
      frame.title.present = true;
      frame.title.value = it->get<std::string>();
    } else {
      warn(lines_.member(at, "frame_title"), prefix + "frame_title", "not a string; ignored");
    }
  }
  if (const auto it = obj.find("frame_classes"); it != obj.end()) {
    if (!it->is_array()) {
      warn(lines_.member(at, "frame_classes"), prefix + "frame_classes", "not an array; ignored");
    } else {
      frame.classes.present = true;
      for (const json& c : *it)
        if (c.is_string()) frame.classes.value.push_back(c.get<std::string>());
    }
  }
}

RawFrame Reader::read_frame(const json& obj, const Loc& at, const std::string& prefix, bool key_frame) {
  RawFrame frame;
  frame.loc = at;
  frame.prefix = prefix;
  read_metadata(obj, at, prefix, frame);
  read_coords(obj, at, prefix, "vertices_coords", frame.coords);
  if (key_frame) read_coords(obj, at, prefix, "vertices_flatUnfoldCoords", frame.flat_unfold);
  read_edges(obj, at, prefix, frame);
  read_assignment(obj, at, prefix, frame);
  read_fold_angle(obj, at, prefix, frame);
  read_faces(obj, at, prefix, frame);
  frame.own_coords = frame.coords.present;
  frame.own_fold_angle = frame.fold_angle.present;
  return frame;
}

RawFrame inherit(RawFrame child, const RawFrame& parent) {
  if (!child.inherit) return child;
  auto take = [](auto& mine, const auto& theirs) {
    if (!mine.present) mine = theirs;
  };
  take(child.coords, parent.coords);
  take(child.edges, parent.edges);
  take(child.assignment, parent.assignment);
  take(child.fold_angle, parent.fold_angle);
  take(child.faces, parent.faces);
  take(child.title, parent.title);
  take(child.classes, parent.classes);
  return child;
}

}  // namespace foldkit::io::detail
