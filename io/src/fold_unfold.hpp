#pragma once
// Geometry behind the FOLD importer: planes, isometric unfolding, dihedral angles, faces of a
// plane graph and polygon triangulation. Internal to foldkit_io.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "foldkit/geometry/types.hpp"

namespace foldkit::io::fold_detail {

using geometry::Vec2;
using geometry::Vec3;
using Face = std::vector<int>;  // vertex indices, in order around the face

// What went wrong in a geometric step, and the face or FOLD edge it concerns (-1: none).
struct GeometryError {
  std::string message;
  int face = -1;
  int edge = -1;
};

// Newell's method: the normal of a polygon, with length twice its area. Well defined for
// non-convex and slightly non-planar polygons, where a cross product of two sides is not.
Vec3 newell_normal(const std::vector<Vec3>& points, const Face& face);
double signed_area(const std::vector<Vec2>& points, const Face& face);

// An orthonormal in-plane basis (u, v) with u × v = normal, u as close to +x as the plane
// allows, so that a plane parallel to z = 0 with normal +z keeps x and y unchanged.
std::array<Vec3, 2> in_plane_basis(const Vec3& unit_normal);

struct Plane {
  Vec3 normal = Vec3::UnitZ();  // unit
  Vec3 u = Vec3::UnitX();
  Vec3 v = Vec3::UnitY();
  double max_distance = 0.0;  // of the fitted points from the plane
};
// Least-squares plane through the points (smallest principal axis of their covariance).
Plane fit_plane(const std::vector<Vec3>& points);
Plane flipped(const Plane& plane);
inline Vec2 project(const Plane& plane, const Vec3& p) { return {p.dot(plane.u), p.dot(plane.v)}; }

// Lays the faces (consistently oriented, connected through shared sides) flat: breadth-first from
// face 0, each face in its own frame (keeping its orientation) and aligned on the side it shares
// with an already placed face. A vertex that would land in two places farther apart than
// `tolerance` means the surface is not developable.
struct Unfolding {
  std::vector<Vec2> coords;  // per input point; unused points stay at the origin
  std::optional<GeometryError> error;
};
Unfolding unfold(const std::vector<Vec3>& points, const std::vector<Face>& faces, double tolerance);

// Signed dihedral angle between two faces, foldkit's sign (positive = mountain): n1, n2 are the
// unit normals of the faces and e the unit direction of their shared side as face 1 traverses it.
double dihedral(const Vec3& n1, const Vec3& n2, const Vec3& e);

// Bounded faces of a plane straight-line graph, counter-clockwise, found by walking each
// half-edge to the next one clockwise around its head; the unbounded face of each component is
// dropped. Fails on dangling edges, bridges and overlapping edges.
struct TracedFaces {
  std::vector<Face> faces;
  std::optional<GeometryError> error;
};
TracedFaces trace_faces(const std::vector<Vec2>& points, const std::vector<std::array<int, 2>>& edges);

// Ear clipping of a simple counter-clockwise polygon (convex or not); indices are into
// `points`. Triangles whose height over their longest side is at most `min_height` (length units
// of `points`; pass the pattern builder's merge tolerance) are avoided where the polygon allows.
// Empty when the polygon is not simple or has no area.
std::vector<std::array<int, 3>> triangulate(const std::vector<Vec2>& points, const Face& face, double min_height = 0.0);

}  // namespace foldkit::io::fold_detail
