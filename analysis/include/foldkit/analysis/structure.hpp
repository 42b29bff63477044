#pragma once
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"

// The lumped model of the paper's Sec. 5: rigid modules (the actors, in a folded state) joined
// by generalized 6-DOF springs (see docs/STIFFNESS.md).
namespace foldkit::analysis {

using Matrix6 = Eigen::Matrix<double, 6, 6>;

// Fig. 9: a crease (hinged), two faces that touch (face), two boundary edges that meet (edge).
enum class ConnectionKind { Hinged = 0, Face = 1, Edge = 2 };
const char* to_string(ConnectionKind kind);
std::optional<ConnectionKind> connection_kind(std::string_view name);

// Eq. 6: 1e6 translational, 1e1 rotational; the hinge is weak about its line, K66 = 1.
Matrix6 default_stiffness(ConnectionKind kind);

struct Module {
  int id = 0;                 // actor ID
  Eigen::Vector3d centroid;   // in the folded state
  Eigen::Vector3d normal;     // of the facet's plane, folded
  double area = 0.0;
};

// A spring between modules a and b (indices into Structure::modules). Its frame is fixed to
// both in the folded state: origin at the midpoint of the shared edge or the centre of the shared
// face; columns e1, e2, e3. Edge and hinge: e3 along the edge, e1 in a's plane perpendicular to
// e3 pointing into a. Face: e3 along a's normal towards b, e1 along a's first outline edge.
struct Connection {
  ConnectionKind kind = ConnectionKind::Hinged;
  int a = 0, b = 0;
  Eigen::Vector3d origin;
  Eigen::Matrix3d frame;
  int joint = -1;       // the crease (joint index) of a hinged connection
  double extent = 0.0;  // length of the shared edge, or area of the shared face
};

struct Structure {
  std::vector<Module> modules;  // one per actor, in the pattern's order
  std::vector<Connection> connections;
  double tile = 1.0;  // length scale: √(mean module area)
};

struct DetectOptions {
  // Coincidence tolerance for planes, lines and overlaps, relative to the tile size.
  double tolerance = 1e-6;
};

// Modules from the actors posed by `state` (tree rooted at actor 0); hinges from the joints;
// faces and edges that touch after folding, detected from the geometry. A pair joined by a
// crease or touching face to face gets no edge connection.
Structure build_structure(const geometry::CreasePattern& pattern, const geometry::FoldState& state,
                          const DetectOptions& options = {});

// The same from explicit rigid motions of the actors (one per actor, from the flat sheet): a
// folded state moved or turned as a whole, or pieces assembled by hand; each joint's two actors
// must stay together.
Structure build_structure(const geometry::CreasePattern& pattern, const std::vector<Eigen::Isometry3d>& poses,
                          const DetectOptions& options = {});

}  // namespace foldkit::analysis
