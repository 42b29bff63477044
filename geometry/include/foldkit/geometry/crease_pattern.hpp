#pragma once
/// @file
/// The crease-pattern model: vertices, rigid facets (actors), revolute creases (joints), and the
/// topology derived from them; built and checked by build_pattern().
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

/// One triangle of an actor, by vertex index.
struct Triangle {
  std::array<int, 3> v{};  ///< vertex indices, counter-clockwise
  int line = 0;            ///< source line; 0 when not read from a file
};

/// A rigid facet: one or more triangles that move as one body.
struct Actor {
  int id = 0;                       ///< the actor's ID, as in the file
  std::vector<Triangle> triangles;  ///< connected through shared edges
  int line = 0;                     ///< source line; 0 when not read from a file
};

/// A revolute crease between two actors. Its axis runs from vertex v[0] to v[1]; the order
/// (like the order of the actors) carries no sign: positive fold angle = mountain always.
struct Joint {
  int id = 0;                   ///< the joint's ID, as in the file (or assigned by BuildOptions::auto_joints)
  std::array<int, 2> v{};       ///< vertex indices of the segment ends (the segment may span several mesh edges)
  std::array<int, 2> actors{};  ///< actor indices (not IDs)
  double spring = 0.0;          ///< PMML SpringConst (≥ 0)
  double damping = 0.0;         ///< PMML DampConst (≥ 0)
  Assignment assignment = Assignment::Unassigned;  ///< mountain/valley intent, if any
  int line = 0;                 ///< source line; 0 when not read from a file
  /// foldkit's PMML extension `<MaxTorque>`: the torque limit of this joint's motor in the dynamic
  /// model, N·m (positive, finite); empty: the run's default (dynamics::DynamicOptions::max_torque).
  std::optional<double> max_torque;
};

/// The creases around one interior vertex, sorted counter-clockwise by direction, and the
/// sector angle between each crease and the next (sectors[i] lies between creases i and i+1,
/// the last one wrapping round to crease 0). A crease that passes straight through the vertex
/// appears twice, once per direction.
struct VertexStar {
  int vertex = 0;                  ///< vertex index
  std::vector<int> joints;         ///< joint indices, counter-clockwise
  std::vector<double> directions;  ///< polar angle of each crease leaving the vertex, radians
  std::vector<double> sectors;     ///< sector angles, radians, summing to 2π (one entry per crease)
};

/// Facet adjacency: one graph vertex per actor, one edge per joint (edge_index = joint index).
using FacetGraph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                         boost::property<boost::edge_index_t, int>>;

/// Tolerances and repairs of build_pattern().
struct BuildOptions {
  /// Vertices closer than merge_tolerance × (bounding-box diagonal) are one vertex; the same
  /// length is the tolerance of the degeneracy, overlap and T-junction checks.
  double merge_tolerance = 1e-9;
  /// Largest difference (absolute, radians) between 2π and the sum of the facet angles round an
  /// interior vertex: beyond it the vertex has a gap or an overlap, an error.
  double angle_tolerance = 1e-7;
  /// An edge shared by two actors without a joint is an error, or a new joint (and a warning)
  /// when this is set.
  bool auto_joints = false;
  double auto_spring = 1.0;   ///< SpringConst of joints added by auto_joints
  double auto_damping = 0.1;  ///< DampConst of joints added by auto_joints
};

struct BuildResult;
namespace detail {
class PatternBuilder;
}

/// Merges vertices, checks every rule of docs/FORMATS.md and derives the topology. Problems
/// in the spec are reported as diagnostics, each at its source line, never thrown; one run
/// lists every problem it can find.
/// @return the pattern when no diagnostic is an error, and every diagnostic (warnings included)
BuildResult build_pattern(const PatternSpec& spec, const BuildOptions& options = {});

/// The immutable model. Built only through build_pattern(), so every instance is valid.
/// Vertices, actors and joints are referred to by index (their position in these vectors);
/// IDs are the file's names for actors and joints.
class CreasePattern {
 public:
  /// The pattern's title (free text).
  const std::string& title() const { return title_; }
  /// The merged vertices of the flat sheet, pattern units.
  const std::vector<Vec2>& vertices() const { return vertices_; }
  /// The actors (rigid facets), in file order.
  const std::vector<Actor>& actors() const { return actors_; }
  /// The joints (creases): those of the file in file order, then any added by
  /// BuildOptions::auto_joints. A FoldState holds one angle per entry.
  const std::vector<Joint>& joints() const { return joints_; }
  /// Sheet boundary: mesh edges used by one triangle only, as vertex pairs.
  const std::vector<std::array<int, 2>>& boundary_edges() const { return boundary_edges_; }
  /// Whether vertex index `v` (which must be in range) lies on the sheet's boundary.
  bool is_boundary_vertex(int v) const { return on_boundary_[v]; }
  /// Number of vertices on the boundary.
  std::size_t boundary_vertex_count() const;
  /// Length of the diagonal of the flat sheet's bounding box: the scale relative tolerances use.
  double diagonal() const;
  /// Every vertex off the boundary, with its creases in cyclic order (none for a vertex inside
  /// one actor).
  const std::vector<VertexStar>& interior_vertices() const { return stars_; }
  /// The facet adjacency graph.
  const FacetGraph& facet_graph() const { return graph_; }
  /// What the file says about the sheet's physics for the dynamic model (foldkit's PMML
  /// extensions `<Density>`, `<Gravity>`, `<FixedActor>`; all empty when it says nothing).
  const PhysicsSpec& physics() const { return physics_; }

  /// The index of the actor with ID `id`, or nothing.
  std::optional<int> actor_index(int id) const;
  /// The index of the joint with ID `id`, or nothing.
  std::optional<int> joint_index(int id) const;

  /// The spec this pattern writes back (vertex coordinates after merging).
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
  PhysicsSpec physics_;
  std::unordered_map<int, int> actor_by_id_;
  std::unordered_map<int, int> joint_by_id_;
};

/// What build_pattern() made of a spec.
struct BuildResult {
  std::optional<CreasePattern> pattern;  ///< empty when any diagnostic is an error
  Diagnostics diagnostics;               ///< every finding, warnings included, in the order found
};

/// build_pattern() for callers that want an exception (used with generators, whose output must
/// always be valid).
/// @throws std::invalid_argument listing every error, each formatted by format() with the
///         spec's title (or "pattern") as the file name
CreasePattern build_or_throw(const PatternSpec& spec, const BuildOptions& options = {});

}  // namespace foldkit::geometry
