// FOLD export: the triangle mesh as faces, every mesh edge as an edge record. See docs/FOLD.md.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "foldkit/io/fold_format.hpp"
#include "foldkit/io/number_format.hpp"

namespace foldkit::io {
namespace {

using geometry::Assignment;
using geometry::CreasePattern;
using geometry::FoldState;
using geometry::Vec2;

std::string quoted(const std::string& s) {
  // Titles come from other formats and may hold invalid UTF-8; replace rather than throw.
  return nlohmann::json(s).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

// A triangle side and the actors (indices) of the triangles that have it.
struct MeshEdge {
  std::array<int, 2> v{};
  std::vector<int> actors;
};

std::vector<MeshEdge> mesh_edges(const CreasePattern& pattern) {
  std::vector<MeshEdge> edges;
  std::unordered_map<std::uint64_t, std::size_t> index;
  const auto& actors = pattern.actors();
  for (std::size_t a = 0; a < actors.size(); ++a) {
    for (const auto& t : actors[a].triangles) {
      for (std::size_t c = 0; c < 3; ++c) {
        const int u = t.v[c];
        const int w = t.v[(c + 1) % 3];
        const auto key = (std::uint64_t{static_cast<std::uint32_t>(std::min(u, w))} << 32U) |
                         static_cast<std::uint32_t>(std::max(u, w));
        const auto [it, added] = index.emplace(key, edges.size());
        if (added) edges.push_back(MeshEdge{{u, w}, {}});
        edges[it->second].actors.push_back(static_cast<int>(a));
      }
    }
  }
  return edges;
}

bool on_segment(const Vec2& q, const Vec2& p0, const Vec2& p1) {
  const Vec2 d = p1 - p0;
  const double length2 = d.squaredNorm();
  if (length2 <= 0.0) return false;
  const double t = (q - p0).dot(d) / length2;
  const double tolerance = 1e-9;
  return t >= -tolerance && t <= 1.0 + tolerance && (q - (p0 + t * d)).norm() <= tolerance * std::sqrt(length2);
}

// The joint a mesh edge between two actors belongs to: the joint of that pair of actors whose
// segment contains the edge (a joint may span several mesh edges). -1 if none does.
int joint_of(const CreasePattern& pattern, const MeshEdge& edge) {
  const auto& joints = pattern.joints();
  const auto& vs = pattern.vertices();
  const int a = edge.actors[0];
  const int b = edge.actors[1];
  int fallback = -1;
  for (std::size_t j = 0; j < joints.size(); ++j) {
    const auto& joint = joints[j];
    const bool pair = (joint.actors[0] == a && joint.actors[1] == b) || (joint.actors[0] == b && joint.actors[1] == a);
    if (!pair) continue;
    const Vec2& p0 = vs[static_cast<std::size_t>(joint.v[0])];
    const Vec2& p1 = vs[static_cast<std::size_t>(joint.v[1])];
    if (on_segment(vs[static_cast<std::size_t>(edge.v[0])], p0, p1) &&
        on_segment(vs[static_cast<std::size_t>(edge.v[1])], p0, p1))
      return static_cast<int>(j);
    if (fallback < 0) fallback = static_cast<int>(j);
  }
  return fallback;
}

const char* letter(Assignment a) {
  switch (a) {
    case Assignment::Mountain: return "M";
    case Assignment::Valley: return "V";
    case Assignment::Flat: return "F";
    default: return "U";
  }
}

// A joint's letter under a state: the sign of its angle (positive is mountain in foldkit), and at
// an angle of 0, which has no sign (the flat first frame of a sequence), its own assignment.
const char* letter_for_angle(double angle, Assignment own) {
  if (angle > 0.0) return "M";
  if (angle < 0.0) return "V";
  return letter(own);
}

// FOLD degrees, valley positive; chosen so that reading them back gives `angle` bit for bit.
std::string fold_degrees(double angle) { return angle == 0.0 ? "0" : format_degrees(-angle); }

void check_size(const FoldState& state, const CreasePattern& pattern, const char* what) {
  if (static_cast<std::size_t>(state.angles.size()) != pattern.joints().size())
    throw std::invalid_argument(std::string("write_fold: ") + what + " has " + std::to_string(state.angles.size()) +
                                " angles but the pattern has " + std::to_string(pattern.joints().size()) + " joints");
}

// Scalar lists wrapped to readable lines; lists of lists one inner list per line.
class ListWriter {
 public:
  ListWriter(std::string& out, std::string indent) : out_(out), indent_(std::move(indent)) {}
  void scalars(const std::vector<std::string>& items) {
    out_ += "[";
    std::size_t column = 0;
    for (std::size_t i = 0; i < items.size(); ++i) {
      if (column == 0 || column + items[i].size() > 90) {
        out_ += (i ? ",\n" : "\n") + indent_ + "  ";
        column = 0;
      } else {
        out_ += ", ";
      }
      out_ += items[i];
      column += items[i].size() + 2;
    }
    out_ += items.empty() ? "]" : "\n" + indent_ + "]";
  }
  void rows(const std::vector<std::string>& rows) {
    out_ += "[";
    for (std::size_t i = 0; i < rows.size(); ++i) out_ += (i ? ",\n" : "\n") + indent_ + "  " + rows[i];
    out_ += rows.empty() ? "]" : "\n" + indent_ + "]";
  }

 private:
  std::string& out_;
  std::string indent_;
};

std::string row(std::initializer_list<std::string> items) {
  std::string s = "[";
  for (const std::string& item : items) s += (s.size() > 1 ? ", " : "") + item;
  return s + "]";
}

}  // namespace

std::string write_fold(const CreasePattern& pattern, const FoldExport& extra) {
  if (extra.state) check_size(*extra.state, pattern, "the state");
  for (const FoldState& frame : extra.frames) check_size(frame, pattern, "a frame");
  if (!extra.frame_times.empty() && extra.frame_times.size() != extra.frames.size())
    throw std::invalid_argument("write_fold: " + std::to_string(extra.frame_times.size()) + " frame times for " +
                                std::to_string(extra.frames.size()) + " frames");
  for (double t : extra.frame_times)
    if (!std::isfinite(t)) throw std::invalid_argument("write_fold: a frame time is not a finite number");

  const std::vector<MeshEdge> edges = mesh_edges(pattern);
  std::vector<int> joint(edges.size(), -1);  // joint index per mesh edge, -1: boundary or inside an actor
  for (std::size_t e = 0; e < edges.size(); ++e)
    if (edges[e].actors.size() == 2 && edges[e].actors[0] != edges[e].actors[1]) joint[e] = joint_of(pattern, edges[e]);

  auto joint_letter = [&](std::size_t e) {
    const Assignment own = pattern.joints()[static_cast<std::size_t>(joint[e])].assignment;
    return extra.state ? letter_for_angle(extra.state->angles[joint[e]], own) : letter(own);
  };
  std::vector<std::string> assignment;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (edges[e].actors.size() == 1) assignment.emplace_back("\"B\"");
    else if (joint[e] < 0) assignment.emplace_back(edges[e].actors[0] == edges[e].actors[1] ? "\"J\"" : "\"U\"");
    else assignment.push_back(std::string("\"") + joint_letter(e) + "\"");
  }
  auto fold_angles = [&](const FoldState& state) {
    std::vector<std::string> angles;
    for (std::size_t e = 0; e < edges.size(); ++e)
      angles.push_back(joint[e] < 0 ? "0" : fold_degrees(state.angles[joint[e]]));
    return angles;
  };

  std::string out = "{\n";
  out += "  \"file_spec\": 1.2,\n";
  out += "  \"file_creator\": \"foldkit\",\n";
  out += "  \"file_classes\": [\"singleModel\"],\n";
  out += "  \"frame_title\": " + quoted(pattern.title()) + ",\n";
  out += "  \"frame_classes\": [\"creasePattern\"],\n";
  ListWriter list(out, "  ");

  std::vector<std::string> rows;
  for (const Vec2& p : pattern.vertices()) rows.push_back(row({format_number(p.x()), format_number(p.y())}));
  out += "  \"vertices_coords\": ";
  list.rows(rows);

  rows.clear();
  for (const auto& actor : pattern.actors())
    for (const auto& t : actor.triangles)
      rows.push_back(row({std::to_string(t.v[0]), std::to_string(t.v[1]), std::to_string(t.v[2])}));
  out += ",\n  \"faces_vertices\": ";
  list.rows(rows);

  rows.clear();
  for (const MeshEdge& e : edges) rows.push_back(row({std::to_string(e.v[0]), std::to_string(e.v[1])}));
  out += ",\n  \"edges_vertices\": ";
  list.rows(rows);

  out += ",\n  \"edges_assignment\": ";
  list.scalars(assignment);

  if (extra.state) {
    out += ",\n  \"edges_foldAngle\": ";
    list.scalars(fold_angles(*extra.state));
  }
  if (!extra.frames.empty()) {
    out += ",\n  \"file_frames\": [";
    ListWriter inner(out, "      ");
    for (std::size_t i = 0; i < extra.frames.size(); ++i) {
      out += (i ? ",\n" : "\n");
      out += "    {\n      \"frame_inherit\": true,\n      \"frame_parent\": 0,\n      \"edges_foldAngle\": ";
      inner.scalars(fold_angles(extra.frames[i]));
      if (!extra.frame_times.empty()) out += ",\n      \"foldkit:time\": " + format_number(extra.frame_times[i]);
      out += "\n    }";
    }
    out += "\n  ]";
  }
  out += "\n}\n";
  return out;
}

}  // namespace foldkit::io
