#pragma once
// FOLD's keys, frame by frame: read from the parsed JSON and type-checked, with the line of
// every value for messages; frame_inherit resolved. Internal to foldkit_io.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "fold_json.hpp"
#include "foldkit/geometry/diagnostics.hpp"
#include "foldkit/geometry/types.hpp"

namespace foldkit::io::detail {

template <class T>
struct Field {
  bool present = false;
  T value{};
  Loc loc;
  std::string name;  // as in messages: "edges_vertices" or "file_frames[2].edges_vertices"
};

struct Coords {
  std::vector<geometry::Vec3> points;
  bool three_d = false;
};
using RawIndex = long long;  // range-checked once the vertex count is known

// One frame's own keys (frame 0 is the file itself, file_frames[i] is frame i + 1).
struct RawFrame {
  Loc loc;
  std::string prefix;
  Field<Coords> coords;
  Field<Coords> flat_unfold;
  Field<std::vector<std::array<RawIndex, 2>>> edges;
  Field<std::vector<char>> assignment;
  Field<std::vector<std::optional<double>>> fold_angle;
  Field<std::vector<std::vector<RawIndex>>> faces;
  Field<std::string> title;
  Field<std::vector<std::string>> classes;
  bool inherit = false;
  int parent = 0;
  bool own_coords = false;  // before inheritance: does this frame carry its own?
  bool own_fold_angle = false;
};

// "name[i]", for messages.
std::string indexed(const std::string& name, std::size_t i);
// A JSON value's kind for messages ("an array", "a string (\"…\")").
std::string describe(const json& v);

// Reads frames, failing with a ParseError at the offending value and collecting warnings.
class Reader {
 public:
  Reader(const std::string& name, const LineMap& lines) : name_(name), lines_(lines) {}

  [[noreturn]] void fail(const Loc& at, const std::string& what, const std::string& message) const;
  void warn(const Loc& at, const std::string& what, const std::string& message);
  geometry::Diagnostics& warnings() { return warnings_; }

  RawIndex index(const json& v, const Loc& at, const std::string& what) const;
  RawFrame read_frame(const json& obj, const Loc& at, const std::string& prefix, bool key_frame);

 private:
  double number(const json& v, const Loc& at, const std::string& what) const;
  // The array under `key`, or nullptr when the key is absent.
  template <class T>
  const json* array_field(const json& obj, const Loc& at, const std::string& prefix, const char* key,
                          Field<T>& field, const char* expected) const;
  void read_coords(const json& obj, const Loc& at, const std::string& prefix, const char* key, Field<Coords>& f);
  void read_edges(const json& obj, const Loc& at, const std::string& prefix, RawFrame& frame);
  void read_assignment(const json& obj, const Loc& at, const std::string& prefix, RawFrame& frame);
  void read_fold_angle(const json& obj, const Loc& at, const std::string& prefix, RawFrame& frame);
  void read_faces(const json& obj, const Loc& at, const std::string& prefix, RawFrame& frame);
  void read_metadata(const json& obj, const Loc& at, const std::string& prefix, RawFrame& frame);

  const std::string& name_;
  const LineMap& lines_;
  geometry::Diagnostics warnings_;
};

// A frame with what it inherits filled in (FOLD frame_inherit).
RawFrame inherit(RawFrame child, const RawFrame& parent);

}  // namespace foldkit::io::detail
