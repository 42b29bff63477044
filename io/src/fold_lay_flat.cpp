// FOLD import: the faces oriented consistently, a folded form laid flat (planar coordinates, or
// the faces unfolded across their shared sides), and the assignment's letters checked against
// the folded form (fold_importer.hpp).
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include <boost/pending/disjoint_sets.hpp>

#include "fold_importer.hpp"

namespace foldkit::io::fold_detail {

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

}  // namespace foldkit::io::fold_detail
