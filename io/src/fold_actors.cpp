// FOLD import: faces joined across J edges into actors, the joints between actors, the pattern
// spec (faces cut into triangles) and the fold states of the key frame and the other frames
// (fold_importer.hpp).
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <boost/pending/disjoint_sets.hpp>

#include "fold_importer.hpp"
#include "foldkit/io/number_format.hpp"

namespace foldkit::io::fold_detail {

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

}  // namespace foldkit::io::fold_detail
