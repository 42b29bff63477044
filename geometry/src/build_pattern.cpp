#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <limits>
#include <unordered_map>
#include <unordered_set>

#include <boost/pending/disjoint_sets.hpp>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/triangle_overlap.hpp"
#include "vertex_index.hpp"

namespace foldkit::geometry {
namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr std::size_t kMaxOverlapReports = 20;
// Squares of coordinates (cross products, norms) must stay finite and normal in double.
constexpr double kLargestCoordinate = 1e100;
constexpr double kSmallestExtent = 1e-100;

std::string point_text(const Vec2& p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%.9g, %.9g)", p.x(), p.y());
  return buf;
}

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// One mesh edge and the triangles (global indices) that use it.
struct MeshEdge {
  int a = 0, b = 0;
  std::vector<int> triangles;
  int joint = -1;  // joint index once a joint covers it
};

struct TriangleRef {
  int actor = 0;
  std::array<int, 3> v{};
  int line = 0;
};

}  // namespace

namespace detail {

class PatternBuilder {
 public:
  PatternBuilder(const PatternSpec& spec, const BuildOptions& options) : spec_(spec), options_(options) {}

  BuildResult run() {
    check_fields();
    if (!failed()) weld_vertices();
    if (failed()) return std::move(result_);  // the checks below need finite, welded geometry
    // These report independently, so that one run lists every problem of a file.
    check_overlaps();
    collect_edges();
    check_actor_connectivity();
    resolve_joints();
    cover_unjointed_edges();
    find_boundary();
    build_stars();
    if (!failed()) assemble();
    return std::move(result_);
  }

 private:
  bool failed() const { return has_errors(result_.diagnostics); }
  void error(int line, std::string message) { result_.diagnostics.push_back({Severity::Error, line, std::move(message)}); }
  void warn(int line, std::string message) { result_.diagnostics.push_back({Severity::Warning, line, std::move(message)}); }
  std::string actor_name(int index) const { return "actor " + std::to_string(spec_.actors[index].id); }

  void check_fields() {
    if (spec_.actors.empty()) error(0, "the pattern has no actors");
    for (std::size_t i = 0; i < spec_.actors.size(); ++i) {
      const ActorSpec& a = spec_.actors[i];
      auto [it, fresh] = actor_by_id_.emplace(a.id, static_cast<int>(i));
      if (!fresh)
        error(a.line, "duplicate actor ID " + std::to_string(a.id) + " (also at line " +
                          std::to_string(spec_.actors[it->second].line) + ")");
      if (a.triangles.empty()) error(a.line, actor_name(static_cast<int>(i)) + " has no triangles");
      for (const TriangleSpec& t : a.triangles)
        for (const Vec2& c : t.corners) {
          if (!c.allFinite()) error(t.line, actor_name(static_cast<int>(i)) + ": triangle coordinate is not finite");
          else if (c.cwiseAbs().maxCoeff() > kLargestCoordinate)
            error(t.line, actor_name(static_cast<int>(i)) + ": coordinate " + point_text(c) + " is outside ±1e100");
        }
    }
    std::unordered_map<int, int> joint_lines;
    for (const JointSpec& j : spec_.joints) {
      const std::string name = "joint " + std::to_string(j.id);
      auto [it, fresh] = joint_lines.emplace(j.id, j.line);
      if (!fresh) error(j.line, "duplicate joint ID " + std::to_string(j.id) + " (also at line " + std::to_string(it->second) + ")");
      if (!j.coords[0].allFinite() || !j.coords[1].allFinite()) error(j.line, name + ": coordinate is not finite");
      if (!std::isfinite(j.spring) || j.spring < 0.0) error(j.line, name + ": spring constant must be finite and non-negative");
      if (!std::isfinite(j.damping) || j.damping < 0.0)
        error(j.line, name + ": damping constant must be finite and non-negative");
      if (j.max_torque && !(std::isfinite(*j.max_torque) && *j.max_torque > 0.0))
        error(j.line, name + ": maximum torque must be positive and finite (N·m)");
      for (int id : j.actor_ids)
        if (!actor_by_id_.count(id)) error(j.line, name + " names actor " + std::to_string(id) + ", which does not exist");
      if (j.actor_ids[0] == j.actor_ids[1]) error(j.line, name + " joins actor " + std::to_string(j.actor_ids[0]) + " to itself");
    }
    const PhysicsSpec& physics = spec_.physics;
    if (physics.density && !(std::isfinite(*physics.density) && *physics.density > 0.0))
      error(physics.density_line, "density must be positive and finite (kg/m²)");
    if (physics.gravity && !physics.gravity->allFinite()) error(physics.gravity_line, "gravity is not finite");
    if (physics.fixed_actor && !actor_by_id_.count(*physics.fixed_actor))
      error(physics.fixed_actor_line, "fixed actor " + std::to_string(*physics.fixed_actor) + " does not exist");
  }

  void weld_vertices() {
    Eigen::AlignedBox2d box;
    for (const ActorSpec& a : spec_.actors)
      for (const TriangleSpec& t : a.triangles)
        for (const Vec2& c : t.corners) box.extend(c);
    const double diagonal = box.diagonal().stableNorm();
    if (!(diagonal >= kSmallestExtent)) {
      char buf[120];
      std::snprintf(buf, sizeof buf, "the pattern's extent %.3g is below 1e-100: scale it up", diagonal);
      error(0, buf);
      return;
    }
    tolerance_ = options_.merge_tolerance * diagonal;
    index_.emplace(tolerance_);
    for (std::size_t ai = 0; ai < spec_.actors.size(); ++ai) {
      for (const TriangleSpec& t : spec_.actors[ai].triangles) {
        TriangleRef ref{static_cast<int>(ai), {}, t.line};
        for (int k = 0; k < 3; ++k) ref.v[k] = index_->insert(t.corners[k]);
        const auto& pts = index_->points();
        const Vec2 &p0 = pts[ref.v[0]], &p1 = pts[ref.v[1]], &p2 = pts[ref.v[2]];
        const double twice_area = cross(p1 - p0, p2 - p0);
        const double longest = std::max({(p1 - p0).norm(), (p2 - p1).norm(), (p0 - p2).norm()});
        if (ref.v[0] == ref.v[1] || ref.v[1] == ref.v[2] || ref.v[0] == ref.v[2] ||
            std::abs(twice_area) <= tolerance_ * longest) {
          error(t.line, actor_name(ref.actor) + ": degenerate triangle " + point_text(p0) + " " + point_text(p1) + " " +
                            point_text(p2) + " (zero area)");
          continue;
        }
        if (twice_area < 0) std::swap(ref.v[1], ref.v[2]);  // keep every triangle counter-clockwise
        triangles_.push_back(ref);
      }
    }
  }

  void check_overlaps() {
    const auto& pts = index_->points();
    std::vector<Tri2> tris;
    tris.reserve(triangles_.size());
    for (const TriangleRef& t : triangles_) tris.push_back({pts[t.v[0]], pts[t.v[1]], pts[t.v[2]]});
    const auto pairs = overlapping_pairs(tris, tolerance_);
    for (std::size_t k = 0; k < pairs.size() && k < kMaxOverlapReports; ++k) {
      const TriangleRef &a = triangles_[pairs[k].first], &b = triangles_[pairs[k].second];
      error(b.line, "triangle of " + actor_name(b.actor) + " overlaps a triangle of " + actor_name(a.actor) +
                        (a.line ? " (line " + std::to_string(a.line) + ")" : std::string()));
    }
    if (pairs.size() > kMaxOverlapReports)
      error(0, std::to_string(pairs.size() - kMaxOverlapReports) + " more overlapping triangle pairs");
  }

  void collect_edges() {
    for (std::size_t ti = 0; ti < triangles_.size(); ++ti) {
      for (int k = 0; k < 3; ++k) {
        const int a = triangles_[ti].v[k], b = triangles_[ti].v[(k + 1) % 3];
        auto [it, fresh] = edge_by_key_.emplace(edge_key(a, b), static_cast<int>(edges_.size()));
        if (fresh) edges_.push_back({std::min(a, b), std::max(a, b), {}, -1});
        edges_[it->second].triangles.push_back(static_cast<int>(ti));
      }
    }
    const auto& pts = index_->points();
    for (const MeshEdge& e : edges_) {
      if (e.triangles.size() > 2)
        error(triangles_[e.triangles[2]].line, "edge " + point_text(pts[e.a]) + "-" + point_text(pts[e.b]) + " is used by " +
                                                   std::to_string(e.triangles.size()) + " triangles");
    }
  }

  bool is_shared(const MeshEdge& e) const {
    return e.triangles.size() == 2 && triangles_[e.triangles[0]].actor != triangles_[e.triangles[1]].actor;
  }

  void check_actor_connectivity() {
    std::vector<int> rank(triangles_.size()), parent(triangles_.size());
    boost::disjoint_sets<int*, int*> sets(rank.data(), parent.data());
    for (std::size_t t = 0; t < triangles_.size(); ++t) sets.make_set(static_cast<int>(t));
    for (const MeshEdge& e : edges_)
      if (e.triangles.size() == 2 && !is_shared(e)) sets.union_set(e.triangles[0], e.triangles[1]);
    std::vector<int> pieces(spec_.actors.size(), 0);
    std::vector<bool> seen_root(triangles_.size(), false);
    for (std::size_t t = 0; t < triangles_.size(); ++t) {
      const int root = sets.find_set(static_cast<int>(t));
      if (!seen_root[root]) {
        seen_root[root] = true;
        ++pieces[triangles_[t].actor];
      }
    }
    for (std::size_t a = 0; a < pieces.size(); ++a)
      if (pieces[a] > 1)
        error(spec_.actors[a].line, actor_name(static_cast<int>(a)) + " is not connected: its triangles form " +
                                        std::to_string(pieces[a]) + " separate pieces (triangles must share edges)");
  }

  bool joins(const MeshEdge& e, int actor_a, int actor_b) const {
    if (!is_shared(e) || e.joint >= 0) return false;
    const int a1 = triangles_[e.triangles[0]].actor, a2 = triangles_[e.triangles[1]].actor;
    return (a1 == actor_a && a2 == actor_b) || (a1 == actor_b && a2 == actor_a);
  }

  // Walks shared edges of the two actors from one end of the joint segment to the other.
  std::optional<std::vector<int>> trace_segment(int v0, int v1, int actor_a, int actor_b) const {
    // Nearly every joint is one mesh edge: look it up rather than scan the vertex's edges,
    // which would be quadratic at a vertex of very high degree.
    if (const int direct = edge_between(v0, v1); direct >= 0 && joins(edges_[direct], actor_a, actor_b))
      return std::vector<int>{v0, v1};
    const auto& pts = index_->points();
    const Vec2 origin = pts[v0], axis = pts[v1] - pts[v0];
    const double length = axis.norm();
    if (v0 == v1 || length <= tolerance_) return std::nullopt;
    const Vec2 dir = axis / length;
    std::vector<int> chain{v0};
    int current = v0;
    double reached = 0.0;
    while (current != v1) {
      int next = -1;
      for (int ei : incident_[current]) {
        const MeshEdge& e = edges_[ei];
        if (!joins(e, actor_a, actor_b)) continue;
        const int other = e.a == current ? e.b : e.a;
        const Vec2 rel = pts[other] - origin;
        const double along = rel.dot(dir);
        if (std::abs(cross(dir, rel)) <= tolerance_ && along > reached + tolerance_ && along <= length + tolerance_) {
          next = other;
          reached = along;
          break;
        }
      }
      if (next < 0) return std::nullopt;
      chain.push_back(next);
      current = next;
    }
    return chain;
  }

  int edge_between(int a, int b) const {
    const auto it = edge_by_key_.find(edge_key(a, b));
    return it == edge_by_key_.end() ? -1 : it->second;
  }

  void resolve_joints() {
    incident_.assign(index_->points().size(), {});
    for (std::size_t ei = 0; ei < edges_.size(); ++ei) {
      incident_[edges_[ei].a].push_back(static_cast<int>(ei));
      incident_[edges_[ei].b].push_back(static_cast<int>(ei));
    }
    for (const JointSpec& js : spec_.joints) {
      const std::string name = "joint " + std::to_string(js.id);
      const int a = actor_by_id_.at(js.actor_ids[0]), b = actor_by_id_.at(js.actor_ids[1]);
      std::array<int, 2> ends{};
      bool ok = true;
      for (int k = 0; k < 2; ++k) {
        auto v = index_->find(js.coords[k]);
        if (!v) {
          error(js.line, name + ": end " + point_text(js.coords[k]) + " is not a vertex of any triangle");
          ok = false;
        } else {
          ends[k] = *v;
        }
      }
      if (!ok) continue;
      auto chain = trace_segment(ends[0], ends[1], a, b);
      if (!chain) {
        error(js.line, name + ": segment " + point_text(js.coords[0]) + "-" + point_text(js.coords[1]) +
                           " is not an edge shared by actors " + std::to_string(js.actor_ids[0]) + " and " +
                           std::to_string(js.actor_ids[1]) + " (or another joint already covers it)");
        continue;
      }
      const int joint_index = static_cast<int>(joints_.size());
      for (std::size_t k = 0; k + 1 < chain->size(); ++k) edges_[edge_between((*chain)[k], (*chain)[k + 1])].joint = joint_index;
      joints_.push_back({js.id, ends, {a, b}, js.spring, js.damping, js.assignment, js.line, js.max_torque});
      chains_.push_back(std::move(*chain));
    }
  }

  void cover_unjointed_edges() {
    const auto& pts = index_->points();
    std::unordered_set<int> used;
    long long next_id = 1;
    for (const Joint& j : joints_) {
      used.insert(j.id);
      next_id = std::max(next_id, static_cast<long long>(j.id) + 1);
    }
    // Past INT_MAX, new joints take the smallest free positive IDs instead.
    auto take_id = [&] {
      if (next_id > std::numeric_limits<int>::max()) next_id = 1;
      while (used.count(static_cast<int>(next_id))) ++next_id;
      used.insert(static_cast<int>(next_id));
      return static_cast<int>(next_id++);
    };
    for (MeshEdge& e : edges_) {
      if (!is_shared(e) || e.joint >= 0) continue;
      const TriangleRef &t0 = triangles_[e.triangles[0]], &t1 = triangles_[e.triangles[1]];
      const std::string where = "edge " + point_text(pts[e.a]) + "-" + point_text(pts[e.b]) + " is shared by " +
                                actor_name(t0.actor) + " and " + actor_name(t1.actor) + " but has no joint";
      if (!options_.auto_joints) {
        error(t1.line, where);
        continue;
      }
      e.joint = static_cast<int>(joints_.size());
      const int id = take_id();
      joints_.push_back({id, {e.a, e.b}, {t0.actor, t1.actor}, options_.auto_spring, options_.auto_damping,
                         Assignment::Unassigned, 0});
      chains_.push_back({e.a, e.b});
      warn(t1.line, where + ": added joint " + std::to_string(id));
    }
  }

  void find_boundary() {
    on_boundary_.assign(index_->points().size(), false);
    for (const MeshEdge& e : edges_) {
      if (e.triangles.size() != 1) continue;
      boundary_edges_.push_back({e.a, e.b});
      on_boundary_[e.a] = on_boundary_[e.b] = true;
    }
    // A corner lying inside another triangle's edge leaves both sides looking like boundary.
    const auto& pts = index_->points();
    detail::bgi::rtree<std::pair<detail::BPoint, int>, detail::bgi::quadratic<16>> tree;
    for (std::size_t v = 0; v < pts.size(); ++v)
      if (on_boundary_[v]) tree.insert({detail::BPoint(pts[v].x(), pts[v].y()), static_cast<int>(v)});
    for (const MeshEdge& e : edges_) {
      if (e.triangles.size() != 1) continue;
      const int a = e.a, b = e.b;
      // Grown by the tolerance: an axis-parallel edge has a box of zero height.
      detail::BBox box(detail::BPoint(std::min(pts[a].x(), pts[b].x()) - tolerance_, std::min(pts[a].y(), pts[b].y()) - tolerance_),
                       detail::BPoint(std::max(pts[a].x(), pts[b].x()) + tolerance_, std::max(pts[a].y(), pts[b].y()) + tolerance_));
      const Vec2 dir = (pts[b] - pts[a]).normalized();
      for (auto it = tree.qbegin(detail::bgi::intersects(box)); it != tree.qend(); ++it) {
        const int v = it->second;
        if (v == a || v == b) continue;
        const Vec2 rel = pts[v] - pts[a];
        const double along = rel.dot(dir);
        if (std::abs(cross(dir, rel)) <= tolerance_ && along > tolerance_ && along < (pts[b] - pts[a]).norm() - tolerance_)
          error(triangles_[e.triangles[0]].line, "vertex " + point_text(pts[v]) + " lies inside the edge " + point_text(pts[a]) + "-" + point_text(pts[b]) +
                       " without splitting it (T-junction): triangles must meet corner to corner");
      }
    }
  }

  void build_stars() {
    const auto& pts = index_->points();
    std::vector<double> corner_sum(pts.size(), 0.0);
    std::vector<int> line_at(pts.size(), 0);
    for (const TriangleRef& t : triangles_)
      for (int k = 0; k < 3; ++k) {
        if (!line_at[t.v[k]]) line_at[t.v[k]] = t.line;
        const Vec2 u = pts[t.v[(k + 1) % 3]] - pts[t.v[k]], w = pts[t.v[(k + 2) % 3]] - pts[t.v[k]];
        corner_sum[t.v[k]] += std::atan2(std::abs(cross(u, w)), u.dot(w));
      }
    std::vector<std::vector<std::pair<double, int>>> rays(pts.size());
    for (std::size_t j = 0; j < chains_.size(); ++j) {
      const auto& c = chains_[j];
      for (std::size_t k = 0; k < c.size(); ++k) {
        if (k + 1 < c.size()) rays[c[k]].emplace_back(std::atan2((pts[c[k + 1]] - pts[c[k]]).y(), (pts[c[k + 1]] - pts[c[k]]).x()), j);
        if (k > 0) rays[c[k]].emplace_back(std::atan2((pts[c[k - 1]] - pts[c[k]]).y(), (pts[c[k - 1]] - pts[c[k]]).x()), j);
      }
    }
    for (std::size_t v = 0; v < pts.size(); ++v) {
      if (on_boundary_[v]) continue;
      if (std::abs(corner_sum[v] - kTwoPi) > options_.angle_tolerance) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "interior vertex %s: facet angles sum to %.9g degrees, not 360 (a gap or an overlap)",
                      point_text(pts[v]).c_str(), corner_sum[v] * 180.0 / M_PI);
        error(line_at[v], buf);
        continue;
      }
      auto& r = rays[v];
      std::sort(r.begin(), r.end());
      VertexStar star;
      star.vertex = static_cast<int>(v);
      for (std::size_t k = 0; k < r.size(); ++k) {
        star.directions.push_back(r[k].first);
        star.joints.push_back(r[k].second);
        const double next = k + 1 < r.size() ? r[k + 1].first : r[0].first + kTwoPi;
        star.sectors.push_back(r.size() == 1 ? kTwoPi : next - r[k].first);
      }
      stars_.push_back(std::move(star));
    }
  }

  void assemble() {
    CreasePattern p;
    p.title_ = spec_.title;
    p.physics_ = spec_.physics;
    p.vertices_ = index_->points();
    for (const ActorSpec& a : spec_.actors) p.actors_.push_back({a.id, {}, a.line});
    for (const TriangleRef& t : triangles_) p.actors_[t.actor].triangles.push_back({t.v, t.line});
    p.joints_ = std::move(joints_);
    p.boundary_edges_ = std::move(boundary_edges_);
    p.on_boundary_ = std::move(on_boundary_);
    p.stars_ = std::move(stars_);
    p.graph_ = FacetGraph(p.actors_.size());
    for (std::size_t j = 0; j < p.joints_.size(); ++j)
      boost::add_edge(p.joints_[j].actors[0], p.joints_[j].actors[1], static_cast<int>(j), p.graph_);
    p.actor_by_id_ = std::move(actor_by_id_);
    for (std::size_t j = 0; j < p.joints_.size(); ++j) p.joint_by_id_.emplace(p.joints_[j].id, static_cast<int>(j));
    result_.pattern = std::move(p);
  }

  const PatternSpec& spec_;
  const BuildOptions& options_;
  BuildResult result_;
  double tolerance_ = 0.0;
  std::optional<detail::VertexIndex> index_;
  std::unordered_map<int, int> actor_by_id_;
  std::vector<TriangleRef> triangles_;
  std::vector<MeshEdge> edges_;
  std::unordered_map<std::uint64_t, int> edge_by_key_;
  std::vector<std::vector<int>> incident_;
  std::vector<Joint> joints_;
  std::vector<std::vector<int>> chains_;
  std::vector<std::array<int, 2>> boundary_edges_;
  std::vector<bool> on_boundary_;
  std::vector<VertexStar> stars_;
};

}  // namespace detail

BuildResult build_pattern(const PatternSpec& spec, const BuildOptions& options) { return detail::PatternBuilder(spec, options).run(); }

CreasePattern build_or_throw(const PatternSpec& spec, const BuildOptions& options) {
  BuildResult r = build_pattern(spec, options);
  if (r.pattern) return std::move(*r.pattern);
  std::ostringstream out;
  out << "invalid crease pattern";
  for (const Diagnostic& d : r.diagnostics)
    if (d.severity == Severity::Error) out << "\n  " << format(d, spec.title.empty() ? "pattern" : spec.title);
  throw std::invalid_argument(out.str());
}

}  // namespace foldkit::geometry
