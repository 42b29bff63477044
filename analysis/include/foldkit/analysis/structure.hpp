#pragma once
/// @file
/// The lumped stiffness model of a folded sheet: rigid modules joined by 6-DOF springs.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"

/// Stiffness analysis of folded structures: the lumped model of the paper's Sec. 5, rigid
/// modules (the actors, in a folded state) joined by generalized 6-DOF springs, and its static
/// equilibrium under dead loads (docs/STIFFNESS.md). Lengths are in the pattern's units, forces
/// in N.
namespace foldkit::analysis {

/// A 6×6 stiffness matrix acting on [Δp; θ] (translation, then rotation vector) in a
/// connection's axes.
using Matrix6 = Eigen::Matrix<double, 6, 6>;

/// The kinds of connection of Fig. 9.
enum class ConnectionKind {
  Hinged = 0,  ///< a crease
  Face = 1,    ///< two faces that touch
  Edge = 2     ///< two boundary edges that meet
};
/// The kind's name: "hinged", "face" or "edge".
const char* to_string(ConnectionKind kind);
/// The kind named `name` ("hinged", "face" or "edge"), or nothing.
std::optional<ConnectionKind> connection_kind(std::string_view name);

/// Eq. 6: diagonal, 1e6 translational (N per length unit), 1e1 rotational (N·length per
/// radian); the hinge is weak about its line, K66 = 1.
Matrix6 default_stiffness(ConnectionKind kind);

/// A rigid module: one actor in the folded state.
struct Module {
  int id = 0;                 ///< actor ID
  Eigen::Vector3d centroid;   ///< area centroid in the folded state, pattern units
  Eigen::Vector3d normal;     ///< unit normal of the facet's plane, folded
  double area = 0.0;          ///< area, squared pattern units
};

/// A spring between modules a and b (indices into Structure::modules). Its axes are fixed to
/// both in the folded state: origin at the midpoint of the shared edge or the centre of the shared
/// face; columns e1, e2, e3. Edge and hinge: e3 along the edge, e1 in a's plane perpendicular to
/// e3 pointing into a. Face: e3 along a's normal, e1 along a's first outline edge.
struct Connection {
  ConnectionKind kind = ConnectionKind::Hinged;  ///< what joins the two modules
  int a = 0,  ///< the first module (index); the axes are set from it
      b = 0;  ///< the second module (index)
  Eigen::Vector3d origin;  ///< the axes' origin in the folded state, pattern units
  Eigen::Matrix3d axes;    ///< the connection's axes e1, e2, e3 as columns (orthonormal)
  int joint = -1;       ///< the crease (joint index) of a hinged connection; −1 otherwise
  double extent = 0.0;  ///< length of the shared edge, or area of the shared face
};

/// The modules and springs of a folded sheet.
struct Structure {
  std::vector<Module> modules;  ///< one per actor, in the pattern's order
  std::vector<Connection> connections;  ///< sorted by kind, then modules, then joint
  double tile = 1.0;  ///< length scale: √(mean module area), pattern units
};

/// Tolerances of build_structure().
struct DetectOptions {
  /// Coincidence tolerance for planes, lines and overlaps, relative to the tile size.
  double tolerance = 1e-6;
};

/// Modules from the actors posed by `state` (tree rooted at actor 0); hinges from the joints;
/// faces and edges that touch after folding, detected from the geometry. A pair joined by a
/// crease or touching face to face gets no edge connection.
/// @param pattern  the pattern
/// @param state    one angle per joint, radians
/// @param options  detection tolerance
Structure build_structure(const geometry::CreasePattern& pattern, const geometry::FoldState& state,
                          const DetectOptions& options = {});

/// The same from explicit rigid motions of the actors (one per actor, from the flat sheet): a
/// folded state moved or turned as a whole, or pieces assembled by hand; each joint's two actors
/// must stay together.
/// @throws std::invalid_argument when `poses` does not hold one pose per actor
Structure build_structure(const geometry::CreasePattern& pattern, const std::vector<Eigen::Isometry3d>& poses,
                          const DetectOptions& options = {});

}  // namespace foldkit::analysis
