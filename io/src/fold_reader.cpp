// FOLD import: JSON text → checked FOLD frames → faces laid flat → actors and joints →
// build_pattern(). The first two steps live in fold_json.cpp and fold_fields.cpp; this file reads
// the frames and the topology, fold_lay_flat.cpp and fold_actors.cpp hold the rest
// (fold_importer.hpp). See docs/FOLD.md for the mapping and what is rejected.
#include <algorithm>

#include "fold_importer.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/parse_error.hpp"

namespace foldkit::io {
namespace fold_detail {

std::uint64_t side_key(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b));
  const auto hi = static_cast<std::uint32_t>(std::max(a, b));
  return (std::uint64_t{lo} << 32U) | hi;
}

Sides collect_sides(const std::vector<Face>& faces, const std::unordered_map<std::uint64_t, int>& edge_by_key) {
  Sides s;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Face& face = faces[f];
    for (std::size_t i = 0; i < face.size(); ++i) {
      const int a = face[i];
      const int b = face[(i + 1) % face.size()];
      const auto key = side_key(a, b);
      auto [it, added] = s.by_key.emplace(key, static_cast<int>(s.list.size()));
      if (added) {
        const auto e = edge_by_key.find(key);
        s.list.push_back(Side{a, b, e == edge_by_key.end() ? -1 : e->second, {}});
      }
      s.list[static_cast<std::size_t>(it->second)].faces.push_back(static_cast<int>(f));
    }
  }
  return s;
}

// Does `face` run from a to b (rather than b to a)?
bool runs_forward(const Face& face, int a, int b) {
  const auto k = face.size();
  for (std::size_t i = 0; i < k; ++i)
    if (face[i] == a) return face[(i + 1) % k] == b;
  return false;
}

geometry::Assignment to_assignment(char letter) {
  switch (letter) {
    case 'M': return geometry::Assignment::Mountain;
    case 'V': return geometry::Assignment::Valley;
    case 'F': return geometry::Assignment::Flat;
    default: return geometry::Assignment::Unassigned;
  }
}

std::string list_some(const std::vector<int>& items) {
  std::string s;
  for (std::size_t i = 0; i < items.size() && i < 5; ++i) s += (i ? ", " : "") + std::to_string(items[i]);
  if (items.size() > 5) s += ", … (" + std::to_string(items.size()) + " in all)";
  return s;
}

// ───────────────────────────── the import ─────────────────────────────

FoldImport Importer::run() {
  const json& doc = doc_;
  if (!doc.is_object()) reader_.fail(lines_.root(), "", "expected a FOLD object {…} at the top level, found " + describe(doc));
  if (const auto it = doc.find("file_spec"); it != doc.end()) {
    if (it->is_number() && it->get<double>() > 1.2 + 1e-9)
      reader_.warn(lines_.member(lines_.root(), "file_spec"), "file_spec",
                   "version " + it->dump() + " is newer than 1.2; read as 1.2");
  }
  read_frames(doc);
  title_ = key().title.present ? key().title.value : "";
  if (title_.empty()) {
    if (const auto it = doc.find("file_title"); it != doc.end() && it->is_string()) title_ = it->get<std::string>();
  }

  prepare_topology();
  orient_faces();
  lay_flat();
  form_actors_and_joints();

  geometry::BuildResult built = geometry::build_pattern(make_spec(), options_);
  std::vector<const Diagnostic*> errors;
  for (const Diagnostic& d : built.diagnostics)
    if (d.severity == Severity::Error) errors.push_back(&d);
  if (!built.pattern || !errors.empty()) {
    if (errors.empty()) throw ParseError(name_, 0, "crease pattern rejected");
    std::string message = "crease pattern rejected: " + errors[0]->message;
    for (std::size_t i = 1; i < errors.size(); ++i) message += "\n" + geometry::format(*errors[i], name_);
    throw ParseError(name_, errors[0]->line, message);
  }

  std::optional<geometry::FoldState> state = key_state(*built.pattern);
  std::vector<geometry::FoldState> frames = frame_states(*built.pattern);
  FoldImport result{std::move(*built.pattern), std::move(state), std::move(frames), std::move(reader_.warnings())};
  for (Diagnostic& d : built.diagnostics) result.warnings.push_back(std::move(d));
  return result;
}

void Importer::read_frames(const json& doc) {
  frames_.push_back(reader_.read_frame(doc, lines_.root(), "", true));
  const auto it = doc.find("file_frames");
  if (it == doc.end()) return;
  const Loc at = lines_.member(lines_.root(), "file_frames");
  if (!it->is_array()) reader_.fail(at, "file_frames", "expected an array of frames, found " + describe(*it));
  for (std::size_t i = 0; i < it->size(); ++i) {
    const json& obj = (*it)[i];
    const Loc fl = lines_.item(at, i);
    const std::string prefix = indexed("file_frames", i) + ".";
    if (!obj.is_object()) reader_.fail(fl, indexed("file_frames", i), "expected an object, found " + describe(obj));
    RawFrame frame = reader_.read_frame(obj, fl, prefix, false);
    if (const auto inh = obj.find("frame_inherit"); inh != obj.end()) {
      if (!inh->is_boolean())
        reader_.fail(lines_.member(fl, "frame_inherit"), prefix + "frame_inherit",
                     "expected true or false, found " + describe(*inh));
      frame.inherit = inh->get<bool>();
    }
    if (const auto par = obj.find("frame_parent"); par != obj.end()) {
      const Loc pl = lines_.member(fl, "frame_parent");
      const RawIndex p = reader_.index(*par, pl, prefix + "frame_parent");
      // Parents must come first: no cycles, and one pass resolves all inheritance.
      if (p < 0 || static_cast<std::size_t>(p) > i)
        reader_.fail(pl, prefix + "frame_parent",
                     "frame " + std::to_string(p) + " is not an earlier frame (this is frame " +
                         std::to_string(i + 1) + "; frame 0 is the file itself)");
      frame.parent = static_cast<int>(p);
    }
    const auto parent = static_cast<std::size_t>(frame.parent);
    RawFrame resolved = inherit(std::move(frame), frames_[parent]);
    frames_.push_back(std::move(resolved));
  }
}

void Importer::check_frame(const RawFrame& fr, std::size_t vertex_count) const {
  const auto n = static_cast<RawIndex>(vertex_count);
  auto check_vertex = [&](RawIndex v, const Loc& at, const std::string& what) {
    if (v < 0 || v >= n)
      reader_.fail(at, what,
                   "vertex index " + std::to_string(v) + " out of range (" + std::to_string(n) + " vertices)");
  };
  for (std::size_t i = 0; i < fr.edges.value.size(); ++i) {
    const auto& e = fr.edges.value[i];
    const Loc at = lines_.item(fr.edges.loc, i);
    const std::string what = indexed(fr.edges.name, i);
    check_vertex(e[0], at, what);
    check_vertex(e[1], at, what);
    if (e[0] == e[1]) reader_.fail(at, what, "both ends are vertex " + std::to_string(e[0]));
  }
  auto check_length = [&](const auto& field) {
    if (!field.present) return;
    if (!fr.edges.present) reader_.fail(field.loc, field.name, "given without edges_vertices");
    if (field.value.size() != fr.edges.value.size())
      reader_.fail(field.loc, field.name,
                   "has " + std::to_string(field.value.size()) + " entries but " + fr.edges.name + " has " +
                       std::to_string(fr.edges.value.size()));
  };
  check_length(fr.assignment);
  check_length(fr.fold_angle);
  for (std::size_t i = 0; i < fr.faces.value.size(); ++i) {
    const auto& face = fr.faces.value[i];
    const Loc at = lines_.item(fr.faces.loc, i);
    const std::string what = indexed(fr.faces.name, i);
    for (std::size_t j = 0; j < face.size(); ++j) {
      check_vertex(face[j], at, what);
      for (std::size_t k = 0; k < j; ++k)
        if (face[k] == face[j])
          reader_.fail(at, what, "vertex " + std::to_string(face[j]) + " appears twice (degenerate face)");
    }
  }
}

void Importer::prepare_topology() {
  const RawFrame& k = key();
  if (!k.coords.present) reader_.fail(lines_.root(), "", "no vertices_coords: nothing to import");
  if (k.coords.value.points.empty()) reader_.fail(k.coords.loc, k.coords.name, "no vertices");
  points_ = k.coords.value.points;
  check_frame(k, points_.size());

  Eigen::AlignedBox3d box;
  for (const Vec3& p : points_) box.extend(p);
  diagonal_ = box.diagonal().norm();
  if (!(diagonal_ > 0.0)) reader_.fail(k.coords.loc, k.coords.name, "all vertices coincide");

  for (std::size_t i = 0; i < k.edges.value.size(); ++i) {
    const std::array<int, 2> e{static_cast<int>(k.edges.value[i][0]), static_cast<int>(k.edges.value[i][1])};
    const auto [it, added] = edge_by_key_.emplace(side_key(e[0], e[1]), static_cast<int>(i));
    if (!added)
      reader_.fail(edge_loc(static_cast<int>(i)), indexed(k.edges.name, i),
                   "joins the same vertices as " + indexed(k.edges.name, static_cast<std::size_t>(it->second)));
    edges_.push_back(e);
  }

  if (k.faces.present) {
    if (k.faces.value.empty()) reader_.fail(k.faces.loc, k.faces.name, "no faces");
    for (const auto& raw : k.faces.value) {
      Face face;
      for (RawIndex v : raw) face.push_back(static_cast<int>(v));
      faces_.push_back(std::move(face));
    }
  } else {
    derive_faces();
  }
}

void Importer::derive_faces() {
  const RawFrame& k = key();
  if (edges_.empty())
    reader_.fail(k.edges.present ? k.edges.loc : lines_.root(), k.edges.present ? k.edges.name : "",
                 "neither faces_vertices nor edges_vertices: there are no faces to import");
  fold_detail::Plane plane;
  if (k.coords.value.three_d) {
    std::vector<Vec3> used;
    for (const auto& e : edges_) {
      used.push_back(points_[static_cast<std::size_t>(e[0])]);
      used.push_back(points_[static_cast<std::size_t>(e[1])]);
    }
    plane = fold_detail::fit_plane(used);
    if (plane.max_distance > kPlanarTolerance * diagonal_)
      reader_.fail(lines_.root(), "",
                   "no faces_vertices, and the vertices do not lie in one plane: a folded form needs faces_vertices");
  }
  std::vector<Vec2> flat;
  for (const Vec3& p : points_) flat.push_back(fold_detail::project(plane, p));
  fold_detail::TracedFaces traced = fold_detail::trace_faces(flat, edges_);
  if (traced.error) {
    const int e = std::max(traced.error->edge, 0);
    reader_.fail(edge_loc(e), indexed(k.edges.name, static_cast<std::size_t>(e)), traced.error->message);
  }
  if (traced.faces.empty()) reader_.fail(k.edges.loc, k.edges.name, "the edges enclose no faces");
  faces_ = std::move(traced.faces);
  faces_derived_ = true;
}

void Importer::reverse_faces(const std::vector<int>& which) {
  for (int f : which) std::reverse(faces_[static_cast<std::size_t>(f)].begin(), faces_[static_cast<std::size_t>(f)].end());
  sides_ = collect_sides(faces_, edge_by_key_);
}

Loc Importer::face_loc(int f) const {
  if (faces_derived_) return key().edges.loc;
  return lines_.item(key().faces.loc, static_cast<std::size_t>(f));
}

std::string Importer::face_name(int f) const {
  if (faces_derived_) return "derived face " + std::to_string(f);
  return indexed(key().faces.name, static_cast<std::size_t>(f));
}

Loc Importer::edge_loc(int e) const { return lines_.item(key().edges.loc, static_cast<std::size_t>(e)); }

Loc Importer::assignment_loc(int e) const {
  if (e < 0) return lines_.root();
  if (key().assignment.present) return lines_.item(key().assignment.loc, static_cast<std::size_t>(e));
  return edge_loc(e);
}

char Importer::letter(int edge) const {
  if (edge < 0 || !key().assignment.present) return 'U';
  return key().assignment.value[static_cast<std::size_t>(edge)];
}

}  // namespace fold_detail

FoldImport parse_fold(const std::string& text, const std::string& name, const geometry::BuildOptions& options) {
  detail::check_text(text, name);
  return fold_detail::Importer(text, name, options, detail::parse_json(text, name)).run();
}

FoldImport read_fold(const std::string& path, const geometry::BuildOptions& options) {
  return parse_fold(read_file(path), path, options);
}

}  // namespace foldkit::io
