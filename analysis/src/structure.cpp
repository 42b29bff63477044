#include "foldkit/analysis/structure.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>

#include <Eigen/Geometry>

#include "foldkit/geometry/kinematics.hpp"

namespace foldkit::analysis {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

struct Segment {
  Vector3d p, q;
};

struct Facet {
  std::vector<std::array<Vector3d, 3>> triangles;
  std::vector<Segment> outline;
  Vector3d lo, hi;  // bounding box
};

// The edges of an actor's triangles that no other of its triangles shares.
std::vector<std::array<int, 2>> outline_edges(const geometry::Actor& actor) {
  std::map<std::array<int, 2>, int> count;
  for (const auto& t : actor.triangles)
    for (int k = 0; k < 3; ++k) {
      std::array<int, 2> e{t.v[k], t.v[(k + 1) % 3]};
      if (e[0] > e[1]) std::swap(e[0], e[1]);
      ++count[e];
    }
  std::vector<std::array<int, 2>> out;
  for (const auto& t : actor.triangles)  // in triangle order, so "first outline edge" is stable
    for (int k = 0; k < 3; ++k) {
      std::array<int, 2> e{t.v[k], t.v[(k + 1) % 3]};
      std::array<int, 2> key = e;
      if (key[0] > key[1]) std::swap(key[0], key[1]);
      if (count[key] == 1) out.push_back(e);
    }
  return out;
}

double cross2(const Vector2d& a, const Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Sutherland–Hodgman: the part of `subject` inside the counter-clockwise triangle `clip`.
std::vector<Vector2d> clip_polygon(std::vector<Vector2d> subject, const std::array<Vector2d, 3>& clip) {
  for (int k = 0; k < 3 && !subject.empty(); ++k) {
    const Vector2d a = clip[k], b = clip[(k + 1) % 3];
    const auto inside = [&](const Vector2d& p) { return cross2(b - a, p - a) >= 0.0; };
    std::vector<Vector2d> out;
    for (std::size_t i = 0; i < subject.size(); ++i) {
      const Vector2d p = subject[i], q = subject[(i + 1) % subject.size()];
      const bool pin = inside(p), qin = inside(q);
      if (pin) out.push_back(p);
      if (pin != qin) {
        const double dp = cross2(b - a, p - a), dq = cross2(b - a, q - a);
        out.push_back(p + (q - p) * (dp / (dp - dq)));
      }
    }
    subject = std::move(out);
  }
  return subject;
}

// Area and area-weighted centroid of a polygon.
std::pair<double, Vector2d> polygon_area(const std::vector<Vector2d>& poly) {
  double area = 0.0;
  Vector2d c = Vector2d::Zero();
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vector2d& p = poly[i];
    const Vector2d& q = poly[(i + 1) % poly.size()];
    const double w = cross2(p, q);
    area += w;
    c += (p + q) * w;
  }
  area *= 0.5;
  if (std::abs(area) > 0) c /= (6.0 * area);
  return {std::abs(area), c};
}

// e1 in the plane with normal n, perpendicular to e3 and pointing towards `inside`.
Eigen::Matrix3d edge_axes(const Vector3d& e3, const Vector3d& n, const Vector3d& origin, const Vector3d& inside) {
  Vector3d e1 = n.cross(e3).normalized();
  if ((inside - origin).dot(e1) < 0) e1 = -e1;
  Eigen::Matrix3d f;
  f.col(0) = e1;
  f.col(1) = e3.cross(e1);
  f.col(2) = e3;
  return f;
}

class Detector {
 public:
  Detector(const geometry::CreasePattern& pattern, const std::vector<Eigen::Isometry3d>& poses, double tolerance)
      : pattern_(pattern) {
    const auto& verts = pattern.vertices();
    const auto at = [&](int actor, int v) { return Vector3d(poses[actor] * Vector3d(verts[v].x(), verts[v].y(), 0.0)); };
    double total_area = 0.0;
    for (std::size_t i = 0; i < pattern.actors().size(); ++i) {
      const auto& actor = pattern.actors()[i];
      const int ai = static_cast<int>(i);
      Facet f;
      Module m;
      m.id = actor.id;
      m.centroid.setZero();
      for (const auto& t : actor.triangles) {
        const std::array<Vector3d, 3> p{at(ai, t.v[0]), at(ai, t.v[1]), at(ai, t.v[2])};
        const double area = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]).norm();
        m.area += area;
        m.centroid += area * (p[0] + p[1] + p[2]) / 3.0;
        f.triangles.push_back(p);
      }
      if (m.area > 0) m.centroid /= m.area;
      m.normal = poses[ai].linear() * Vector3d::UnitZ();
      for (const auto& e : outline_edges(actor)) f.outline.push_back({at(ai, e[0]), at(ai, e[1])});
      f.lo = f.hi = f.triangles.front()[0];
      for (const auto& t : f.triangles)
        for (const auto& p : t) f.lo = f.lo.cwiseMin(p), f.hi = f.hi.cwiseMax(p);
      total_area += m.area;
      structure_.modules.push_back(m);
      facets_.push_back(std::move(f));
    }
    const double n = static_cast<double>(std::max<std::size_t>(1, structure_.modules.size()));
    structure_.tile = total_area > 0 ? std::sqrt(total_area / n) : 1.0;
    tol_ = tolerance * structure_.tile;
    for (std::size_t j = 0; j < pattern.joints().size(); ++j) add_hinge(static_cast<int>(j), poses);
  }

  Structure run() {
    const int n = static_cast<int>(facets_.size());
    // Sweep along x so that only pairs whose boxes overlap are examined.
    std::vector<int> order(n);
    for (int i = 0; i < n; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return facets_[a].lo.x() < facets_[b].lo.x(); });
    for (int oi = 0; oi < n; ++oi) {
      const int i = order[oi];
      for (int oj = oi + 1; oj < n; ++oj) {
        const int j = order[oj];
        if (facets_[j].lo.x() > facets_[i].hi.x() + tol_) break;
        if ((facets_[j].lo.array() > facets_[i].hi.array() + tol_).any() ||
            (facets_[i].lo.array() > facets_[j].hi.array() + tol_).any())
          continue;
        const int a = std::min(i, j), b = std::max(i, j);
        if (!try_face(a, b) && !joined_.count({a, b})) try_edge(a, b);
      }
    }
    std::sort(structure_.connections.begin(), structure_.connections.end(), [](const Connection& x, const Connection& y) {
      return std::tie(x.kind, x.a, x.b, x.joint) < std::tie(y.kind, y.a, y.b, y.joint);
    });
    return std::move(structure_);
  }

 private:
  void add_hinge(int j, const std::vector<Eigen::Isometry3d>& poses) {
    const auto& joint = pattern_.joints()[j];
    const int a = joint.actors[0], b = joint.actors[1];
    const auto& verts = pattern_.vertices();
    const Vector3d p = poses[a] * Vector3d(verts[joint.v[0]].x(), verts[joint.v[0]].y(), 0.0);
    const Vector3d q = poses[a] * Vector3d(verts[joint.v[1]].x(), verts[joint.v[1]].y(), 0.0);
    Connection c;
    c.kind = ConnectionKind::Hinged;
    c.a = a;
    c.b = b;
    c.joint = j;
    c.origin = 0.5 * (p + q);
    c.extent = (q - p).norm();
    c.axes = edge_axes((q - p).normalized(), structure_.modules[a].normal, c.origin, structure_.modules[a].centroid);
    structure_.connections.push_back(c);
    joined_.insert({std::min(a, b), std::max(a, b)});
  }

  bool try_face(int a, int b) {
    const Module& ma = structure_.modules[a];
    for (const auto& t : facets_[b].triangles)
      for (const auto& p : t)
        if (std::abs((p - ma.centroid).dot(ma.normal)) > tol_) return false;
    const Segment& first = facets_[a].outline.front();
    const Vector3d u = (first.q - first.p).normalized();
    const Vector3d v = ma.normal.cross(u);
    const auto flat = [&](const Vector3d& p) { return Vector2d((p - ma.centroid).dot(u), (p - ma.centroid).dot(v)); };
    double area = 0.0;
    Vector2d centre = Vector2d::Zero();
    for (const auto& ta : facets_[a].triangles) {
      std::array<Vector2d, 3> clip{flat(ta[0]), flat(ta[1]), flat(ta[2])};
      if (cross2(clip[1] - clip[0], clip[2] - clip[0]) < 0) std::swap(clip[1], clip[2]);
      for (const auto& tb : facets_[b].triangles) {
        const auto [piece_area, piece_centre] = polygon_area(clip_polygon({flat(tb[0]), flat(tb[1]), flat(tb[2])}, clip));
        area += piece_area;
        centre += piece_area * piece_centre;
      }
    }
    if (area <= tol_ * structure_.tile) return false;
    centre /= area;
    Connection c;
    c.kind = ConnectionKind::Face;
    c.a = a;
    c.b = b;
    c.origin = ma.centroid + centre.x() * u + centre.y() * v;
    c.extent = area;
    c.axes.col(0) = u;
    c.axes.col(1) = v;
    c.axes.col(2) = ma.normal;
    structure_.connections.push_back(c);
    return true;
  }

  void try_edge(int a, int b) {
    bool found = false;
    Vector3d p0 = Vector3d::Zero(), dir = Vector3d::UnitX();
    double lo = 0, hi = 0;
    for (const Segment& sa : facets_[a].outline) {
      const Vector3d d = sa.q - sa.p;
      const double len = d.norm();
      if (len <= tol_) continue;
      const Vector3d e = d / len;
      for (const Segment& sb : facets_[b].outline) {
        const auto off_line = [&](const Vector3d& x) { return ((x - sa.p) - (x - sa.p).dot(e) * e).norm(); };
        if (off_line(sb.p) > tol_ || off_line(sb.q) > tol_) continue;
        const double t0 = (sb.p - sa.p).dot(e), t1 = (sb.q - sa.p).dot(e);
        const double from = std::max(0.0, std::min(t0, t1)), to = std::min(len, std::max(t0, t1));
        if (to - from <= tol_) continue;
        if (!found) {
          found = true;
          p0 = sa.p;
          dir = e;
          lo = (sa.p + from * e - p0).dot(dir);
          hi = (sa.p + to * e - p0).dot(dir);
        }
        lo = std::min({lo, (sa.p + from * e - p0).dot(dir), (sa.p + to * e - p0).dot(dir)});
        hi = std::max({hi, (sa.p + from * e - p0).dot(dir), (sa.p + to * e - p0).dot(dir)});
      }
    }
    if (!found) return;
    Connection c;
    c.kind = ConnectionKind::Edge;
    c.a = a;
    c.b = b;
    c.origin = p0 + 0.5 * (lo + hi) * dir;
    c.extent = hi - lo;
    c.axes = edge_axes(dir, structure_.modules[a].normal, c.origin, structure_.modules[a].centroid);
    structure_.connections.push_back(c);
  }

  const geometry::CreasePattern& pattern_;
  Structure structure_;
  std::vector<Facet> facets_;
  std::set<std::pair<int, int>> joined_;
  double tol_ = 0.0;
};

}  // namespace

const char* to_string(ConnectionKind kind) {
  switch (kind) {
    case ConnectionKind::Hinged: return "hinged";
    case ConnectionKind::Face: return "face";
    case ConnectionKind::Edge: return "edge";
  }
  return "?";
}

std::optional<ConnectionKind> connection_kind(std::string_view name) {
  if (name == "hinged") return ConnectionKind::Hinged;
  if (name == "face") return ConnectionKind::Face;
  if (name == "edge") return ConnectionKind::Edge;
  return std::nullopt;
}

Matrix6 default_stiffness(ConnectionKind kind) {
  Matrix6 k = Matrix6::Zero();
  k.diagonal() << 1e6, 1e6, 1e6, 1e1, 1e1, 1e1;
  if (kind == ConnectionKind::Hinged) k(5, 5) = 1.0;
  return k;
}

Structure build_structure(const geometry::CreasePattern& pattern, const geometry::FoldState& state,
                          const DetectOptions& options) {
  return build_structure(pattern, geometry::facet_poses(pattern, geometry::make_tree(pattern), state), options);
}

Structure build_structure(const geometry::CreasePattern& pattern, const std::vector<Eigen::Isometry3d>& poses,
                          const DetectOptions& options) {
  if (pattern.actors().empty()) return {};
  if (poses.size() != pattern.actors().size()) throw std::invalid_argument("build_structure: one pose per actor");
  return Detector(pattern, poses, options.tolerance).run();
}

}  // namespace foldkit::analysis
