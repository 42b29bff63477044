// FOLD import: JSON text → checked FOLD frames → faces laid flat → actors and joints →
// build_pattern(). The first two steps live in fold_json.cpp and fold_fields.cpp; this file
// holds the topology and the import. See docs/FOLD.md for the mapping and what is rejected.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <string_view>
#include <unordered_map>

#include <boost/pending/disjoint_sets.hpp>

#include "fold_fields.hpp"
#include "fold_json.hpp"
#include "fold_unfold.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/fold_format.hpp"
#include "foldkit/io/number_format.hpp"
#include "foldkit/io/parse_error.hpp"

namespace foldkit::io {
namespace {

using detail::describe;
using detail::indexed;
using detail::inherit;
using detail::json;
using detail::LineMap;
using detail::Loc;
using detail::RawFrame;
using detail::RawIndex;
using detail::Reader;
using fold_detail::Face;
using geometry::Diagnostic;
using geometry::Severity;
using geometry::Vec2;
using geometry::Vec3;

constexpr double kPi = 3.14159265358979323846;
// Relative to the bounding-box diagonal. Planarity allows for float32 exports (Origami
// Simulator); development allows for coordinates rounded to six digits (Mathematica).
constexpr double kPlanarTolerance = 1e-6;
constexpr double kDevelopTolerance = 1e-4;
// A dihedral this close to ±180° is a flat fold whose sign the geometry cannot tell.
constexpr double kFlatFoldBand = 1e-5;
// A J edge bent further than this (radians) means its "rigid" actor is not flat.
constexpr double kJoinBendLimit = 1e-3;

// ───────────────────────────── topology ─────────────────────────────

std::uint64_t side_key(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b));
  const auto hi = static_cast<std::uint32_t>(std::max(a, b));
  return (std::uint64_t{lo} << 32U) | hi;
}

// A segment between two face corners, with the faces that have it as a side.
struct Side {
  int a = 0, b = 0;  // as the first face traverses it
  int edge = -1;     // FOLD edge index, -1 when edges_vertices has no record of it
  std::vector<int> faces;
};

struct Sides {
  std::vector<Side> list;
  std::unordered_map<std::uint64_t, int> by_key;
};

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

// A joint as the FOLD data sees it: which record, which faces, which way face f runs along it.
struct JointSource {
  int id = 0;
  int edge = -1;
  int f = 0, g = 0;
  int a = 0, b = 0;  // face f runs from a to b
};

class Importer {
 public:
  // `doc` is `text` parsed: the line map relies on the text being valid JSON.
  Importer(const std::string& text, const std::string& name, const geometry::BuildOptions& options, json doc)
      : name_(name), options_(options), doc_(std::move(doc)), lines_(text), reader_(name, lines_) {}

  FoldImport run();

 private:
  void read_frames(const json& doc);
  void check_frame(const RawFrame& frame, std::size_t vertex_count) const;
  void prepare_topology();
  void derive_faces();
  void orient_faces();
  void lay_flat();
  bool lay_flat_planar(const std::vector<Vec2>& coords);
  void unfold();
  void agree_with_assignments();
  void form_actors_and_joints();
  geometry::PatternSpec make_spec() const;
  std::optional<geometry::FoldState> key_state(const geometry::CreasePattern& pattern);
  std::vector<geometry::FoldState> frame_states(const geometry::CreasePattern& pattern);
  geometry::FoldState state_for(const geometry::CreasePattern& pattern,
                                const std::vector<std::optional<double>>* fold_angle,
                                const std::vector<Vec3>* folded);
  double angle_of(const JointSource& j, const std::vector<std::optional<double>>* fold_angle,
                  const std::vector<Vec3>* folded);
  double side_dihedral(const std::vector<Vec3>& points, int f, int g, int a, int b) const;
  void reverse_faces(const std::vector<int>& which);
  Loc face_loc(int f) const;
  std::string face_name(int f) const;
  Loc edge_loc(int e) const;
  Loc assignment_loc(int e) const;
  char letter(int edge) const;

  const std::string& name_;
  const geometry::BuildOptions& options_;
  const json doc_;
  LineMap lines_;
  Reader reader_;

  std::vector<RawFrame> frames_;  // effective (inheritance resolved); [0] is the key frame
  RawFrame& key() { return frames_[0]; }
  const RawFrame& key() const { return frames_[0]; }

  std::string title_;
  std::vector<Vec3> points_;
  std::vector<std::array<int, 2>> edges_;
  std::unordered_map<std::uint64_t, int> edge_by_key_;
  std::vector<Face> faces_;
  bool faces_derived_ = false;
  Sides sides_;
  double diagonal_ = 0.0;
  bool folded_ = false;  // the coordinates are a folded form: dihedrals give the state
  std::vector<Vec2> flat_;
  std::vector<int> actor_of_face_;
  std::vector<int> first_face_of_actor_;
  std::vector<JointSource> joints_;
  std::unordered_map<int, const JointSource*> joint_by_id_;
};

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

// Neighbouring faces must run along their shared side in opposite directions (FOLD lists all
// faces counter-clockwise); repair files that list some faces the other way round.
void Importer::orient_faces() {
  sides_ = collect_sides(faces_, edge_by_key_);
  for (const Side& s : sides_.list) {
    if (s.faces.size() > 2)
      reader_.fail(face_loc(s.faces[2]), face_name(s.faces[2]),
                   "its side " + std::to_string(s.a) + "–" + std::to_string(s.b) +
                       " is shared by more than two faces (the surface is not a manifold)");
    if (s.faces.size() == 2 && s.faces[0] == s.faces[1])
      reader_.fail(face_loc(s.faces[0]), face_name(s.faces[0]),
                   "runs along its side " + std::to_string(s.a) + "–" + std::to_string(s.b) + " twice");
  }
  const std::size_t count = faces_.size();
  std::vector<int> flip(count, -1);
  std::vector<int> to_reverse;
  for (std::size_t start = 0; start < count; ++start) {
    if (flip[start] >= 0) continue;
    std::vector<int> component{static_cast<int>(start)};
    flip[start] = 0;
    for (std::size_t next = 0; next < component.size(); ++next) {
      const int f = component[next];
      const Face& face = faces_[static_cast<std::size_t>(f)];
      for (std::size_t i = 0; i < face.size(); ++i) {
        const int a = face[i];
        const int b = face[(i + 1) % face.size()];
        const bool f_forward = (flip[static_cast<std::size_t>(f)] == 0);  // f runs a→b after flipping
        for (int g : sides_.list[static_cast<std::size_t>(sides_.by_key.at(side_key(a, b)))].faces) {
          if (g == f) continue;
          const int wanted = runs_forward(faces_[static_cast<std::size_t>(g)], a, b) == f_forward ? 1 : 0;
          int& have = flip[static_cast<std::size_t>(g)];
          if (have < 0) {
            have = wanted;
            component.push_back(g);
          } else if (have != wanted) {
            reader_.fail(face_loc(g), face_name(g),
                         "the faces cannot be oriented consistently (the surface is not orientable)");
          }
        }
      }
    }
    // Keep the orientation most faces of this piece already have.
    std::size_t flipped = 0;
    for (int f : component) flipped += static_cast<std::size_t>(flip[static_cast<std::size_t>(f)]);
    const int reverse_when = 2 * flipped > component.size() ? 0 : 1;
    for (int f : component)
      if (flip[static_cast<std::size_t>(f)] == reverse_when) to_reverse.push_back(f);
  }
  if (!to_reverse.empty()) {
    std::sort(to_reverse.begin(), to_reverse.end());
    reader_.warn(face_loc(to_reverse[0]), faces_derived_ ? "derived faces" : key().faces.name,
                 "faces " + list_some(to_reverse) +
                     " run the other way round from their neighbours; reversed for a consistent orientation");
    reverse_faces(to_reverse);
  }
}

// Decides what the coordinates are: a crease pattern (in some plane), a flat-folded form, or
// a 3D folded form; the last two are unfolded.
void Importer::lay_flat() {
  const RawFrame& k = key();
  if (k.flat_unfold.present) {
    const auto& f = k.flat_unfold;
    if (f.value.points.size() != points_.size())
      reader_.fail(f.loc, f.name,
                   "has " + std::to_string(f.value.points.size()) + " entries but vertices_coords has " +
                       std::to_string(points_.size()));
    std::vector<Vec2> coords;
    for (const Vec3& p : f.value.points) {
      if (p.z() != 0.0) reader_.fail(f.loc, f.name, "must be 2D (a crease pattern)");
      coords.emplace_back(p.x(), p.y());
    }
    if (!lay_flat_planar(coords))
      reader_.fail(f.loc, f.name, "its faces overlap or are mirrored: not a crease pattern");
    folded_ = true;
    return;
  }
  std::vector<Vec3> used;
  for (const Face& face : faces_)
    for (int v : face) used.push_back(points_[static_cast<std::size_t>(v)]);
  fold_detail::Plane plane;
  if (k.coords.value.three_d) plane = fold_detail::fit_plane(used);
  if (plane.max_distance > kPlanarTolerance * diagonal_) {
    unfold();
    return;
  }
  std::vector<Vec2> coords;
  for (const Vec3& p : points_) coords.push_back(fold_detail::project(plane, p));
  // Seen from the other side of its plane, a 3D sheet whose faces all run clockwise is a
  // proper crease pattern: flip the plane rather than the faces.
  bool all_clockwise = true;
  for (const Face& face : faces_) all_clockwise = all_clockwise && fold_detail::signed_area(coords, face) < 0.0;
  if (all_clockwise && k.coords.value.three_d) {
    plane = fold_detail::flipped(plane);
    coords.clear();
    for (const Vec3& p : points_) coords.push_back(fold_detail::project(plane, p));
  }
  if (lay_flat_planar(coords)) return;
  // Mixed orientations: folded flat, unless the file says it is a crease pattern.
  const auto& classes = k.classes.value;
  if (std::find(classes.begin(), classes.end(), "creasePattern") != classes.end())
    reader_.fail(k.faces.present ? k.faces.loc : k.edges.loc, faces_derived_ ? k.edges.name : k.faces.name,
                 "some faces lie on each other mirrored (the sheet is folded flat), but frame_classes says creasePattern");
  unfold();
}

// Accepts planar coordinates when every connected piece is uniformly oriented (reversing a
// piece whose faces all run clockwise); false when some piece mixes orientations.
bool Importer::lay_flat_planar(const std::vector<Vec2>& coords) {
  const double tiny = 1e-12 * diagonal_ * diagonal_;
  std::vector<double> area(faces_.size());
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    area[f] = fold_detail::signed_area(coords, faces_[f]);
    if (std::abs(area[f]) <= tiny) reader_.fail(face_loc(static_cast<int>(f)), face_name(static_cast<int>(f)), "degenerate face: no area");
  }
  // Connected pieces through shared sides.
  std::vector<int> piece_rank(faces_.size()), piece_parent(faces_.size());
  boost::disjoint_sets<int*, int*> pieces(piece_rank.data(), piece_parent.data());
  for (std::size_t f = 0; f < faces_.size(); ++f) pieces.make_set(static_cast<int>(f));
  for (const Side& s : sides_.list)
    if (s.faces.size() == 2) pieces.union_set(s.faces[0], s.faces[1]);
  std::map<int, std::pair<int, int>> signs;  // piece → (counter-clockwise, clockwise) faces
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    auto& [ccw, cw] = signs[pieces.find_set(static_cast<int>(f))];
    (area[f] > 0.0 ? ccw : cw) += 1;
  }
  std::vector<int> to_reverse;
  for (const auto& [piece, count] : signs) {
    if (count.first > 0 && count.second > 0) return false;
    if (count.second > 0) {
      for (std::size_t f = 0; f < faces_.size(); ++f)
        if (pieces.find_set(static_cast<int>(f)) == piece) to_reverse.push_back(static_cast<int>(f));
    }
  }
  if (!to_reverse.empty()) {
    std::sort(to_reverse.begin(), to_reverse.end());
    reader_.warn(face_loc(to_reverse[0]), faces_derived_ ? "derived faces" : key().faces.name,
                 "faces " + list_some(to_reverse) + " run clockwise (FOLD wants counter-clockwise); reversed");
    reverse_faces(to_reverse);
  }
  flat_ = coords;
  return true;
}

void Importer::unfold() {
  folded_ = true;
  const double tiny = 1e-12 * diagonal_ * diagonal_;
  for (std::size_t f = 0; f < faces_.size(); ++f)
    if (fold_detail::newell_normal(points_, faces_[f]).norm() <= tiny)
      reader_.fail(face_loc(static_cast<int>(f)), face_name(static_cast<int>(f)), "degenerate face: no area");
  agree_with_assignments();
  const fold_detail::Unfolding u = fold_detail::unfold(points_, faces_, kDevelopTolerance * diagonal_);
  if (u.error) {
    const int f = std::max(u.error->face, 0);
    reader_.fail(face_loc(f), face_name(f), "cannot unfold the folded form: " + u.error->message);
  }
  flat_ = u.coords;
  for (std::size_t f = 0; f < faces_.size(); ++f)
    if (fold_detail::signed_area(flat_, faces_[f]) <= tiny)
      reader_.fail(face_loc(static_cast<int>(f)), face_name(static_cast<int>(f)),
                   "cannot unfold the folded form: the face ends up mirrored or without area");
}

double Importer::side_dihedral(const std::vector<Vec3>& points, int f, int g, int a, int b) const {
  const Vec3 n1 = fold_detail::newell_normal(points, faces_[static_cast<std::size_t>(f)]).normalized();
  const Vec3 n2 = fold_detail::newell_normal(points, faces_[static_cast<std::size_t>(g)]).normalized();
  if (!runs_forward(faces_[static_cast<std::size_t>(f)], a, b)) std::swap(a, b);
  const Vec3 e = (points[static_cast<std::size_t>(b)] - points[static_cast<std::size_t>(a)]).normalized();
  return fold_detail::dihedral(n1, n2, e);
}

// M/V are relative to the side the faces run counter-clockwise on. When most creases of a
// 3D folded form bend the wrong way for their letters, the faces were listed from the back.
void Importer::agree_with_assignments() {
  int agree = 0;
  int disagree = 0;
  for (const Side& s : sides_.list) {
    const char l = letter(s.edge);
    if (s.faces.size() != 2 || (l != 'M' && l != 'V')) continue;
    const double theta = side_dihedral(points_, s.faces[0], s.faces[1], s.a, s.b);
    if (std::abs(theta) < kJoinBendLimit || kPi - std::abs(theta) < kFlatFoldBand) continue;
    ((theta > 0.0) == (l == 'M') ? agree : disagree) += 1;
  }
  if (disagree <= agree) return;
  std::vector<int> all(faces_.size());
  std::iota(all.begin(), all.end(), 0);
  reader_.warn(face_loc(0), faces_derived_ ? "derived faces" : key().faces.name,
               std::to_string(disagree) + " of " + std::to_string(agree + disagree) +
                   " creases bend against their M/V assignment: faces listed from the back; all reversed");
  reverse_faces(all);
}

void Importer::form_actors_and_joints() {
  const std::size_t count = faces_.size();
  std::vector<int> joined_rank(count), joined_parent(count);
  boost::disjoint_sets<int*, int*> joined(joined_rank.data(), joined_parent.data());
  for (std::size_t f = 0; f < count; ++f) joined.make_set(static_cast<int>(f));
  for (const Side& s : sides_.list) {
    if (s.faces.size() != 2) continue;
    const char l = letter(s.edge);
    const std::string faces_text = "faces " + std::to_string(s.faces[0]) + " and " + std::to_string(s.faces[1]);
    const std::string what = key().assignment.present ? indexed(key().assignment.name, static_cast<std::size_t>(s.edge)) : "";
    if (l == 'B') reader_.fail(assignment_loc(s.edge), what, "boundary edge (B) shared by " + faces_text);
    if (l == 'C')
      reader_.fail(assignment_loc(s.edge), what,
                   "cut edge (C) shared by " + faces_text + "; give each side of a cut its own vertices");
    if (l == 'J') joined.union_set(s.faces[0], s.faces[1]);
  }
  actor_of_face_.assign(count, -1);
  std::unordered_map<int, int> actor_of_root;
  for (std::size_t f = 0; f < count; ++f) {
    const auto [it, added] = actor_of_root.emplace(joined.find_set(static_cast<int>(f)), static_cast<int>(first_face_of_actor_.size()));
    if (added) first_face_of_actor_.push_back(static_cast<int>(f));
    actor_of_face_[f] = it->second;
  }

  std::vector<int> marked_boundary, unrecorded, inside, bent_joins;
  std::vector<char> used(edges_.size(), 0);
  int next_id = static_cast<int>(edges_.size()) + 1;
  for (const Side& s : sides_.list) {
    if (s.edge >= 0) used[static_cast<std::size_t>(s.edge)] = 1;
    const char l = letter(s.edge);
    if (s.faces.size() == 1) {
      if (s.edge >= 0 && std::string_view("MVFJ").find(l) != std::string_view::npos) marked_boundary.push_back(s.edge);
      continue;
    }
    const int f = s.faces[0];
    const int g = s.faces[1];
    if (actor_of_face_[static_cast<std::size_t>(f)] == actor_of_face_[static_cast<std::size_t>(g)]) {
      if (l != 'J' && s.edge >= 0) inside.push_back(s.edge);
      if (l == 'J' && folded_ && std::abs(side_dihedral(points_, f, g, s.a, s.b)) > kJoinBendLimit)
        bent_joins.push_back(s.edge);
      continue;
    }
    if (s.edge < 0) unrecorded.push_back(f);
    JointSource j;
    j.id = s.edge >= 0 ? s.edge + 1 : next_id++;
    j.edge = s.edge;
    j.f = f;
    j.g = g;
    j.a = s.a;
    j.b = s.b;
    if (!runs_forward(faces_[static_cast<std::size_t>(f)], j.a, j.b)) std::swap(j.a, j.b);
    joints_.push_back(j);
  }
  std::sort(joints_.begin(), joints_.end(), [](const JointSource& x, const JointSource& y) { return x.id < y.id; });
  for (const JointSource& j : joints_) joint_by_id_[j.id] = &j;

  const std::string& edges_name = key().edges.name;
  if (!marked_boundary.empty())
    reader_.warn(edge_loc(marked_boundary[0]), edges_name,
                 "edges " + list_some(marked_boundary) + " are creases (M/V/F/J) with only one face; read as boundary");
  if (!inside.empty())
    reader_.warn(edge_loc(inside[0]), edges_name,
                 "edges " + list_some(inside) + " are creases inside one actor (its faces are joined by J edges elsewhere); ignored");
  if (!bent_joins.empty())
    reader_.warn(edge_loc(bent_joins[0]), edges_name,
                 "J edges " + list_some(bent_joins) + " are bent in the folded form, but their faces form one rigid actor");
  if (!unrecorded.empty() && key().edges.present)
    reader_.warn(face_loc(unrecorded[0]), faces_derived_ ? "derived faces" : key().faces.name,
                 std::to_string(unrecorded.size()) + " shared sides of faces " + list_some(unrecorded) +
                     " have no edges_vertices record; read as unassigned (U) creases");
  std::vector<int> unused;
  for (std::size_t e = 0; e < edges_.size(); ++e)
    if (!used[e]) unused.push_back(static_cast<int>(e));
  if (!unused.empty())
    reader_.warn(edge_loc(unused[0]), edges_name, "edges " + list_some(unused) + " are not a side of any face; ignored");
}

geometry::PatternSpec Importer::make_spec() const {
  geometry::PatternSpec spec;
  spec.title = title_;
  for (std::size_t a = 0; a < first_face_of_actor_.size(); ++a) {
    geometry::ActorSpec actor;
    actor.id = static_cast<int>(a) + 1;
    actor.line = face_loc(first_face_of_actor_[a]).line;
    spec.actors.push_back(actor);
  }
  // The builder calls a triangle degenerate when its height is within merge_tolerance x the
  // pattern's diagonal; welding may move each corner by that much again, hence twice.
  Eigen::AlignedBox2d box;
  for (const Face& face : faces_)
    for (int v : face) box.extend(flat_[static_cast<std::size_t>(v)]);
  const double min_height = 2.0 * options_.merge_tolerance * box.diagonal().stableNorm();
  for (std::size_t f = 0; f < faces_.size(); ++f) {
    const int fi = static_cast<int>(f);
    const auto triangles = fold_detail::triangulate(flat_, faces_[f], min_height);
    if (triangles.empty())
      reader_.fail(face_loc(fi), face_name(fi), "cannot be cut into triangles (the polygon crosses itself)");
    auto& actor = spec.actors[static_cast<std::size_t>(actor_of_face_[f])];
    for (const auto& t : triangles) {
      geometry::TriangleSpec tri;
      for (std::size_t c = 0; c < 3; ++c) tri.corners[c] = flat_[static_cast<std::size_t>(t[c])];
      tri.line = face_loc(fi).line;
      actor.triangles.push_back(tri);
    }
  }
  for (const JointSource& j : joints_) {
    geometry::JointSpec joint;
    joint.id = j.id;
    const std::array<int, 2> ends = j.edge >= 0 ? edges_[static_cast<std::size_t>(j.edge)] : std::array<int, 2>{j.a, j.b};
    joint.coords = {flat_[static_cast<std::size_t>(ends[0])], flat_[static_cast<std::size_t>(ends[1])]};
    joint.actor_ids = {actor_of_face_[static_cast<std::size_t>(j.f)] + 1, actor_of_face_[static_cast<std::size_t>(j.g)] + 1};
    joint.spring = options_.auto_spring;
    joint.damping = options_.auto_damping;
    joint.assignment = to_assignment(letter(j.edge));
    joint.line = j.edge >= 0 ? edge_loc(j.edge).line : face_loc(j.f).line;
    spec.joints.push_back(joint);
  }
  return spec;
}

double Importer::angle_of(const JointSource& j, const std::vector<std::optional<double>>* fold_angle,
                          const std::vector<Vec3>* folded) {
  if (fold_angle && j.edge >= 0) {
    if (const auto& degrees = (*fold_angle)[static_cast<std::size_t>(j.edge)])
      return 0.0 - degrees_to_radians(*degrees);  // not -x: FOLD's 0 must not become -0
  }
  if (!folded) return 0.0;
  const double theta = side_dihedral(*folded, j.f, j.g, j.a, j.b);
  if (kPi - std::abs(theta) >= kFlatFoldBand) return theta;
  // Folded flat: the two faces lie on each other and the geometry cannot tell which way.
  const char l = letter(j.edge);
  if (l == 'V') return -std::abs(theta);
  if (l != 'M')
    reader_.warn(j.edge >= 0 ? edge_loc(j.edge) : face_loc(j.f), j.edge >= 0 ? indexed(key().edges.name, static_cast<std::size_t>(j.edge)) : "",
                 "folded flat, and neither M nor V says which way; taken as mountain");
  return std::abs(theta);
}

geometry::FoldState Importer::state_for(const geometry::CreasePattern& pattern,
                                        const std::vector<std::optional<double>>* fold_angle,
                                        const std::vector<Vec3>* folded) {
  geometry::FoldState state = geometry::FoldState::flat(pattern);
  const auto& joints = pattern.joints();
  for (std::size_t i = 0; i < joints.size(); ++i) {
    const auto it = joint_by_id_.find(joints[i].id);
    if (it != joint_by_id_.end()) state.angles[static_cast<Eigen::Index>(i)] = angle_of(*it->second, fold_angle, folded);
  }
  return state;
}

std::optional<geometry::FoldState> Importer::key_state(const geometry::CreasePattern& pattern) {
  const RawFrame& k = key();
  bool any_angle = false;
  for (const auto& a : k.fold_angle.value) any_angle = any_angle || a.has_value();
  const auto& classes = k.classes.value;
  const bool folded_class = std::find(classes.begin(), classes.end(), "foldedForm") != classes.end();
  if (!any_angle && !folded_ && !folded_class && !k.coords.value.three_d) return std::nullopt;
  return state_for(pattern, k.fold_angle.present ? &k.fold_angle.value : nullptr, folded_ ? &points_ : nullptr);
}

std::vector<geometry::FoldState> Importer::frame_states(const geometry::CreasePattern& pattern) {
  std::vector<geometry::FoldState> states;
  for (std::size_t i = 1; i < frames_.size(); ++i) {
    const RawFrame& fr = frames_[i];
    if (!fr.own_coords && !fr.own_fold_angle) continue;
    const std::string what = indexed("file_frames", i - 1);
    if (fr.edges.value != key().edges.value || fr.faces.value != key().faces.value) {
      reader_.warn(fr.loc, what, "has edges or faces of its own, not the key frame's; skipped");
      continue;
    }
    check_frame(fr, points_.size());
    if (fr.own_coords && fr.coords.value.points.size() != points_.size())
      reader_.fail(fr.coords.loc, fr.coords.name,
                   "has " + std::to_string(fr.coords.value.points.size()) + " vertices but the key frame has " +
                       std::to_string(points_.size()));
    const std::vector<Vec3>* folded = fr.own_coords ? &fr.coords.value.points : (folded_ ? &points_ : nullptr);
    states.push_back(state_for(pattern, fr.fold_angle.present ? &fr.fold_angle.value : nullptr, folded));
  }
  return states;
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

}  // namespace

FoldImport parse_fold(const std::string& text, const std::string& name, const geometry::BuildOptions& options) {
  detail::check_text(text, name);
  return Importer(text, name, options, detail::parse_json(text, name)).run();
}

FoldImport read_fold(const std::string& path, const geometry::BuildOptions& options) {
  return parse_fold(read_file(path), path, options);
}

}  // namespace foldkit::io
