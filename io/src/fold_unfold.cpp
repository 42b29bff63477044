#include "fold_unfold.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <map>
#include <unordered_map>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

namespace foldkit::io::fold_detail {
namespace {

std::uint64_t side_key(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b));
  const auto hi = static_cast<std::uint32_t>(std::max(a, b));
  return (std::uint64_t{lo} << 32U) | hi;
}

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
double orient(const Vec2& a, const Vec2& b, const Vec2& c) { return cross2(b - a, c - a); }

// Rigid motion of the plane (no reflection: faces keep their orientation).
struct Motion {
  Eigen::Matrix2d rotation = Eigen::Matrix2d::Identity();
  Vec2 translation = Vec2::Zero();
  Vec2 operator()(const Vec2& p) const { return rotation * p + translation; }
};

// Carries segment (la, lb) onto (pa, pb); midpoints coincide so that a small length mismatch
// is split between both ends instead of piling up at one.
Motion align(const Vec2& la, const Vec2& lb, const Vec2& pa, const Vec2& pb) {
  const Vec2 dl = lb - la;
  const Vec2 dp = pb - pa;
  const double angle = std::atan2(dp.y(), dp.x()) - std::atan2(dl.y(), dl.x());
  Motion m;
  m.rotation = Eigen::Rotation2Dd(angle).toRotationMatrix();
  m.translation = 0.5 * (pa + pb) - m.rotation * (0.5 * (la + lb));
  return m;
}

std::string short_number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

}  // namespace

Vec3 newell_normal(const std::vector<Vec3>& points, const Face& face) {
  Vec3 n = Vec3::Zero();
  const std::size_t k = face.size();
  for (std::size_t i = 0; i < k; ++i) n += points[face[i]].cross(points[face[(i + 1) % k]]);
  return n;
}

double signed_area(const std::vector<Vec2>& points, const Face& face) {
  double twice = 0.0;
  const std::size_t k = face.size();
  for (std::size_t i = 0; i < k; ++i) twice += cross2(points[face[i]], points[face[(i + 1) % k]]);
  return 0.5 * twice;
}

std::array<Vec3, 2> in_plane_basis(const Vec3& unit_normal) {
  Vec3 u = Vec3::UnitX() - Vec3::UnitX().dot(unit_normal) * unit_normal;
  if (u.norm() < 1e-6) u = Vec3::UnitY() - Vec3::UnitY().dot(unit_normal) * unit_normal;
  u.normalize();
  return {u, unit_normal.cross(u)};
}

Plane fit_plane(const std::vector<Vec3>& points) {
  Plane plane;
  if (points.empty()) return plane;
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Vec3& p : points) covariance += (p - centroid) * (p - centroid).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  plane.normal = solver.eigenvectors().col(0).normalized();  // eigenvalues ascend
  const auto basis = in_plane_basis(plane.normal);
  plane.u = basis[0];
  plane.v = basis[1];
  for (const Vec3& p : points)
    plane.max_distance = std::max(plane.max_distance, std::abs((p - centroid).dot(plane.normal)));
  return plane;
}

Plane flipped(const Plane& plane) {
  Plane f = plane;
  f.normal = -plane.normal;
  const auto basis = in_plane_basis(f.normal);
  f.u = basis[0];
  f.v = basis[1];
  return f;
}

double dihedral(const Vec3& n1, const Vec3& n2, const Vec3& e) {
  return std::atan2(n1.cross(n2).dot(e), n1.dot(n2));
}

namespace {

// Breadth-first from face 0: each face reached across a side is laid flat in its own frame and
// moved onto that side where the faces before it put it.
class Unfolder {
 public:
  Unfolder(const std::vector<Vec3>& points, const std::vector<Face>& faces, double tolerance, Unfolding& out)
      : points_(points), faces_(faces), tolerance_(tolerance), out_(out), placed_vertex_(points.size(), 0),
        placed_face_(faces.size(), 0) {
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const Face& face = faces[f];
      for (std::size_t i = 0; i < face.size(); ++i)
        faces_by_side_[side_key(face[i], face[(i + 1) % face.size()])].push_back(static_cast<int>(f));
    }
  }

  // False when out.error was set.
  bool lay_flat() {
    if (!local_coords(0)) {
      out_.error = GeometryError{"face has no area", 0, -1};
      return false;
    }
    for (std::size_t i = 0; i < faces_[0].size(); ++i) {
      out_.coords[faces_[0][i]] = local_[i];
      placed_vertex_[faces_[0][i]] = 1;
    }
    placed_face_[0] = 1;
    std::deque<int> queue{0};
    while (!queue.empty()) {
      const int f = queue.front();
      queue.pop_front();
      const Face& face = faces_[f];
      for (std::size_t i = 0; i < face.size(); ++i) {
        const int a = face[i];
        const int b = face[(i + 1) % face.size()];
        for (int g : faces_by_side_[side_key(a, b)]) {
          if (placed_face_[g]) continue;
          if (!place(f, g, a, b)) return false;
          placed_face_[g] = 1;
          queue.push_back(g);
        }
      }
    }
    return true;
  }

  void check_connected() {
    for (std::size_t f = 0; f < faces_.size(); ++f) {
      if (!placed_face_[f]) {
        out_.error = GeometryError{"is not connected to face 0; a folded form must be one piece to unfold",
                                   static_cast<int>(f), -1};
        return;
      }
    }
  }

 private:
  // Coordinates of a face's corners in its own plane, orientation kept (u × v = its normal).
  bool local_coords(int f) {
    const Vec3 n = newell_normal(points_, faces_[f]);
    if (n.norm() <= 0.0) return false;
    const auto basis = in_plane_basis(n.normalized());
    local_.clear();
    for (int w : faces_[f]) local_.emplace_back(points_[w].dot(basis[0]), points_[w].dot(basis[1]));
    return true;
  }

  // Lays face g flat onto side (a, b) of the placed face f; false when out.error was set.
  bool place(int f, int g, int a, int b) {
    if (!local_coords(g)) {
      out_.error = GeometryError{"face has no area", g, -1};
      return false;
    }
    const Face& other = faces_[g];
    const auto at = [&](int vertex) {
      return local_[static_cast<std::size_t>(std::find(other.begin(), other.end(), vertex) - other.begin())];
    };
    const Vec2 la = at(a);
    const Vec2 lb = at(b);
    const Vec2& pa = out_.coords[a];
    const Vec2& pb = out_.coords[b];
    if (std::abs((lb - la).norm() - (pb - pa).norm()) > tolerance_) {
      out_.error = GeometryError{"not developable: the side between vertices " + std::to_string(a) + " and " +
                                     std::to_string(b) + " has different lengths in faces " + std::to_string(f) + " and " +
                                     std::to_string(g),
                                 g, -1};
      return false;
    }
    const Motion motion = align(la, lb, pa, pb);
    for (std::size_t k = 0; k < other.size(); ++k) {
      const int w = other[k];
      const Vec2 q = motion(local_[k]);
      if (!placed_vertex_[w]) {
        out_.coords[w] = q;
        placed_vertex_[w] = 1;
      } else if ((q - out_.coords[w]).norm() > tolerance_) {
        out_.error = GeometryError{"not developable: laid flat, this face puts vertex " + std::to_string(w) + " " +
                                       short_number((q - out_.coords[w]).norm()) +
                                       " away from where the faces before it put it",
                                   g, -1};
        return false;
      }
    }
    return true;
  }

  const std::vector<Vec3>& points_;
  const std::vector<Face>& faces_;
  const double tolerance_;
  Unfolding& out_;
  std::unordered_map<std::uint64_t, std::vector<int>> faces_by_side_;
  std::vector<char> placed_vertex_;
  std::vector<char> placed_face_;
  std::vector<Vec2> local_;  // the corners of the face being placed, in its own plane
};

}  // namespace

Unfolding unfold(const std::vector<Vec3>& points, const std::vector<Face>& faces, double tolerance) {
  Unfolding out;
  out.coords.assign(points.size(), Vec2::Zero());
  if (faces.empty()) return out;
  Unfolder unfolder(points, faces, tolerance, out);
  if (unfolder.lay_flat()) unfolder.check_connected();
  return out;
}

TracedFaces trace_faces(const std::vector<Vec2>& points, const std::vector<std::array<int, 2>>& edges) {
  TracedFaces out;
  // Half-edge h runs along edge h/2, from edges[h/2][h%2] to the other end.
  const std::size_t half_count = 2 * edges.size();
  auto from = [&](std::size_t h) { return edges[h / 2][h % 2]; };
  auto to = [&](std::size_t h) { return edges[h / 2][1 - h % 2]; };

  std::vector<std::vector<std::pair<double, std::size_t>>> around(points.size());
  for (std::size_t h = 0; h < half_count; ++h) {
    const Vec2 d = points[to(h)] - points[from(h)];
    around[from(h)].emplace_back(std::atan2(d.y(), d.x()), h);
  }
  std::vector<std::size_t> slot(half_count, 0);
  for (std::size_t v = 0; v < around.size(); ++v) {
    auto& star = around[v];
    std::sort(star.begin(), star.end());
    if (star.size() == 1) {
      out.error = GeometryError{"dangling edge: its vertex " + std::to_string(v) +
                                    " has no other edge, so no faces can be derived",
                                -1, static_cast<int>(star[0].second / 2)};
      return out;
    }
    for (std::size_t i = 0; i < star.size(); ++i) {
      slot[star[i].second] = i;
      if (i > 0 && star[i].first - star[i - 1].first < 1e-12) {
        out.error = GeometryError{"overlaps edge " + std::to_string(star[i - 1].second / 2) + " at vertex " +
                                      std::to_string(v),
                                  -1, static_cast<int>(star[i].second / 2)};
        return out;
      }
    }
  }
  // The face left of h continues along the edge next clockwise from h's twin around h's head.
  auto next = [&](std::size_t h) {
    const auto& star = around[to(h)];
    const std::size_t twin = h ^ 1U;
    return star[(slot[twin] + star.size() - 1) % star.size()].second;
  };

  constexpr std::size_t kUnseen = static_cast<std::size_t>(-1);
  std::vector<std::size_t> cycle_of(half_count, kUnseen);
  for (std::size_t start = 0, cycle = 0; start < half_count; ++start) {
    if (cycle_of[start] != kUnseen) continue;
    Face face;
    std::size_t h = start;
    while (cycle_of[h] == kUnseen) {
      cycle_of[h] = cycle;
      face.push_back(from(h));
      h = next(h);
    }
    // Both sides of an edge on one walk: the edge separates nothing.
    for (std::size_t k = 0, c = start; k < face.size(); ++k, c = next(c)) {
      if (cycle_of[c ^ 1U] == cycle) {
        out.error = GeometryError{"is a bridge (the same region lies on both sides), so no faces can be derived",
                                  -1, static_cast<int>(c / 2)};
        return out;
      }
    }
    if (signed_area(points, face) > 0.0) out.faces.push_back(std::move(face));
    ++cycle;
  }
  return out;
}

namespace {

// Ear clipping in which an ear's tip must stand more than `min_height` off the line through its
// neighbours. Empty when no ear is left before the last triangle.
std::vector<std::array<int, 3>> clip_ears(const std::vector<Vec2>& points, const Face& face, double eps, double min_height) {
  const auto thin = [&](const Vec2& pa, const Vec2& pb, const Vec2& pc) {
    const double twice_area = orient(pa, pb, pc);
    const double longest = std::max({(pb - pa).norm(), (pc - pb).norm(), (pa - pc).norm()});
    return twice_area <= eps || twice_area <= min_height * longest;
  };
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> ring = face;
  while (ring.size() > 3) {
    const std::size_t k = ring.size();
    bool clipped = false;
    for (std::size_t i = 0; i < k && !clipped; ++i) {
      const int a = ring[(i + k - 1) % k];
      const int b = ring[i];
      const int c = ring[(i + 1) % k];
      const Vec2 &pa = points[a], &pb = points[b], &pc = points[c];
      if (thin(pa, pb, pc)) continue;  // reflex or (nearly) straight corner: not an ear
      bool blocked = false;
      for (int w : ring) {
        if (w == a || w == b || w == c) continue;
        const Vec2& p = points[w];
        if (orient(pa, pb, p) >= -eps && orient(pb, pc, p) >= -eps && orient(pc, pa, p) >= -eps) {
          blocked = true;
          break;
        }
      }
      if (blocked) continue;
      triangles.push_back({a, b, c});
      ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    if (!clipped) return {};
  }
  if (thin(points[ring[0]], points[ring[1]], points[ring[2]])) return {};
  triangles.push_back({ring[0], ring[1], ring[2]});
  return triangles;
}

// Distance of p from the segment ab.
double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double length2 = d.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(d) / length2, 0.0, 1.0) : 0.0;
  return (a + t * d - p).norm();
}

// The face without its corners that lie within `min_height` of the segment joining the kept
// corners on either side, and for each side of what is kept the dropped corners on it.
struct Straightened {
  Face ring;
  std::map<std::pair<int, int>, std::vector<int>> dropped_on;  // (from, to) in ring order
};

Straightened straighten(const std::vector<Vec2>& points, const Face& face, double min_height) {
  // Start at the first corner if it is one (the triangles then come in the same order as the
  // face's, and an exported file reads back the same), else at the sharpest.
  const std::size_t n = face.size();
  const auto height = [&](std::size_t i) {
    return distance_to_segment(points[face[i]], points[face[(i + n - 1) % n]], points[face[(i + 1) % n]]);
  };
  std::size_t first = 0;
  if (height(0) <= min_height)
    for (std::size_t i = 1; i < n; ++i)
      if (height(i) > height(first)) first = i;
  Straightened out;
  std::vector<int> dropped;
  for (std::size_t k = 0; k < n; ++k) {
    const int v = face[(first + k) % n];
    const int next = face[(first + k + 1) % n];
    if (k > 0) {
      // Drop v if it, and every corner dropped since the last kept one, lies on the chord from
      // that kept corner to v's successor.
      const Vec2& a = points[out.ring.back()];
      const Vec2& c = points[next];
      bool on_chord = distance_to_segment(points[v], a, c) <= min_height;
      for (int w : dropped) on_chord = on_chord && distance_to_segment(points[w], a, c) <= min_height;
      if (on_chord) {
        dropped.push_back(v);
        continue;
      }
      if (!dropped.empty()) out.dropped_on[{out.ring.back(), v}] = std::move(dropped);
      dropped.clear();
    }
    out.ring.push_back(v);
  }
  if (!dropped.empty()) out.dropped_on[{out.ring.back(), out.ring.front()}] = std::move(dropped);
  return out;
}

// Adds `tri` (counter-clockwise) to `out`, split into a fan from the opposite corner wherever one
// of its sides carries dropped corners; each side's list is used once.
void emit_split(const std::array<int, 3>& tri, std::map<std::pair<int, int>, std::vector<int>>& dropped_on,
                std::vector<std::array<int, 3>>& out) {
  for (std::size_t k = 0; k < 3; ++k) {
    const auto found = dropped_on.find({tri[k], tri[(k + 1) % 3]});
    if (found == dropped_on.end()) continue;
    std::vector<int> fan{tri[k]};
    fan.insert(fan.end(), found->second.begin(), found->second.end());
    fan.push_back(tri[(k + 1) % 3]);
    dropped_on.erase(found);
    const int apex = tri[(k + 2) % 3];
    for (std::size_t i = 0; i + 1 < fan.size(); ++i) emit_split({fan[i], fan[i + 1], apex}, dropped_on, out);
    return;
  }
  out.push_back(tri);
}

}  // namespace

std::vector<std::array<int, 3>> triangulate(const std::vector<Vec2>& points, const Face& face, double min_height) {
  if (face.size() < 3) return {};
  Eigen::AlignedBox2d box;
  for (int v : face) box.extend(points[v]);
  const double scale = box.diagonal().norm();
  const double eps = 1e-12 * scale * scale;
  if (!(min_height > 0.0)) return clip_ears(points, face, eps, 0.0);
  // A corner straight to within the builder's tolerance is no corner: the builder would call any
  // triangle with it as a tip degenerate. Triangulate the polygon without such corners, then
  // split each triangle on a side they lie on into a fan from its opposite corner (the fan's
  // triangles keep that triangle's height over the side).
  Straightened s = straighten(points, face, min_height);
  if (s.ring.size() < 3) return clip_ears(points, face, eps, 0.0);
  const std::vector<std::array<int, 3>> coarse = clip_ears(points, s.ring, eps, min_height);
  if (coarse.empty()) return clip_ears(points, face, eps, 0.0);
  std::vector<std::array<int, 3>> triangles;
  for (const auto& tri : coarse) emit_split(tri, s.dropped_on, triangles);
  return triangles;
}

}  // namespace foldkit::io::fold_detail
