#pragma once
// The FOLD importer, private to foldkit::io: its state and its steps, in three files by what they
// do. fold_reader.cpp reads the frames and the topology (sides, faces); fold_lay_flat.cpp orients
// the faces and lays a folded form flat; fold_actors.cpp forms actors and joints, the pattern
// spec and the fold states. See docs/FOLD.md for the mapping and what is rejected.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "fold_fields.hpp"
#include "fold_json.hpp"
#include "fold_unfold.hpp"
#include "foldkit/io/fold_format.hpp"

namespace foldkit::io::fold_detail {

using detail::describe;
using detail::indexed;
using detail::inherit;
using detail::json;
using detail::LineMap;
using detail::Loc;
using detail::RawFrame;
using detail::RawIndex;
using detail::Reader;
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

// A key of the unordered pair {a, b} of vertex indices.
std::uint64_t side_key(int a, int b);

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

// Every side of every face, with the faces that have it and the FOLD edge that records it.
Sides collect_sides(const std::vector<Face>& faces, const std::unordered_map<std::uint64_t, int>& edge_by_key);
// Does `face` run from a to b (rather than b to a)?
bool runs_forward(const Face& face, int a, int b);
// A FOLD assignment letter as foldkit's assignment (B, C, J, U: unassigned).
geometry::Assignment to_assignment(char letter);
// The first five items, and how many in all: for messages.
std::string list_some(const std::vector<int>& items);

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

}  // namespace foldkit::io::fold_detail
