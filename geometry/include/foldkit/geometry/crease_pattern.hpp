#pragma once
#include <array>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <boost/graph/adjacency_list.hpp>

#include "foldkit/geometry/diagnostics.hpp"
#include "foldkit/geometry/pattern_spec.hpp"
#include "foldkit/geometry/types.hpp"

namespace foldkit::geometry {

struct Triangle {
  std::array<int, 3> v{};  // vertex indices, counter-clockwise
  int line = 0;
};

// A rigid facet: one or more triangles that move as one body.
struct Actor {
  int id = 0;
  std::vector<Triangle> triangles;
  int line = 0;
};

// A revolute crease between two actors. Its axis runs from vertex v[0] to v[1]; the order
// (like the order of the actors) carries no sign: positive fold angle = mountain always.
struct Joint {
  int id = 0;
  std::array<int, 2> v{};       // vertex indices of the segment ends
  std::array<int, 2> actors{};  // actor indices (not IDs)
  double spring = 0.0;
  double damping = 0.0;
  Assignment assignment = Assignment::Unassigned;
  int line = 0;
};

// The creases around one interior vertex, sorted counter-clockwise by direction, and the
// sector angle between each crease and the next (sectors[i] lies between creases i and i+1).
struct VertexStar {
  int vertex = 0;
  std::vector<int> joints;  // joint indices
  std::vector<double> directions;  // polar angle of each crease leaving the vertex, radians
  std::vector<double> sectors;
};

// Facet adjacency: one graph vertex per actor, one edge per joint (edge_index = joint index).
using FacetGraph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                         boost::property<boost::edge_index_t, int>>;

struct BuildOptions {
  // Vertices closer than merge_tolerance × (bounding-box diagonal) are one vertex.
  double merge_tolerance = 1e-9;
  // Tolerance for sector sums and overlaps, relative like merge_tolerance (angles: absolute radians).
  double angle_tolerance = 1e-7;
  // An edge shared by two actors without a joint is an error, or a new joint when this is set.
  bool auto_joints = false;
  double auto_spring = 1.0;
  double auto_damping = 0.1;
};

struct BuildResult;
namespace detail {
class PatternBuilder;
}

// Merges vertices, checks every rule of docs/FORMATS.md and derives the topology.
BuildResult build_pattern(const PatternSpec& spec, const BuildOptions& options = {});

// The immutable model. Built only through build_pattern(), so every instance is valid.
class CreasePattern {
 public:
  const std::string& title() const { return title_; }
  const std::vector<Vec2>& vertices() const { return vertices_; }
  const std::vector<Actor>& actors() const { return actors_; }
  const std::vector<Joint>& joints() const { return joints_; }
  // Sheet boundary: mesh edges used by one triangle only, as vertex pairs.
  const std::vector<std::array<int, 2>>& boundary_edges() const { return boundary_edges_; }
  bool is_boundary_vertex(int v) const { return on_boundary_[v]; }
  std::size_t boundary_vertex_count() const;
  // Length of the diagonal of the flat sheet's bounding box: the scale relative tolerances use.
  double diagonal() const;
  // Every vertex off the boundary, with its creases in cyclic order.
  const std::vector<VertexStar>& interior_vertices() const { return stars_; }
  const FacetGraph& facet_graph() const { return graph_; }

  std::optional<int> actor_index(int id) const;
  std::optional<int> joint_index(int id) const;

  // The spec this pattern writes back (vertex coordinates after merging).
  PatternSpec to_spec() const;

 private:
  friend class detail::PatternBuilder;
  CreasePattern() = default;

  std::string title_;
  std::vector<Vec2> vertices_;
  std::vector<Actor> actors_;
  std::vector<Joint> joints_;
  std::vector<std::array<int, 2>> boundary_edges_;
  std::vector<bool> on_boundary_;
  std::vector<VertexStar> stars_;
  FacetGraph graph_;
  std::unordered_map<int, int> actor_by_id_;
  std::unordered_map<int, int> joint_by_id_;
};

struct BuildResult {
  std::optional<CreasePattern> pattern;  // empty when any diagnostic is an error
  Diagnostics diagnostics;
};

// build_pattern() for callers that want an exception: throws std::invalid_argument listing
// every error (used by generators, whose output must always be valid).
CreasePattern build_or_throw(const PatternSpec& spec, const BuildOptions& options = {});

}  // namespace foldkit::geometry
