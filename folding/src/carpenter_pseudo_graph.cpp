// Pointed pseudo-triangulations of the merged chain's vertices (carpenter_pseudo_graph.hpp).
#include "carpenter_pseudo_graph.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

namespace foldkit::folding::pseudo_detail {
namespace {

double cross(const Vec& a, const Vec& b) { return a.x() * b.y() - a.y() * b.x(); }

// A segment is refused where it passes within this fraction of its length of a vertex it does
// not end at: nearly collinear edges would make the mechanism's rigidity matrix near singular.
constexpr double kTouch = 1e-12;
// Pointedness asks for an angle this far beyond π (below the mechanism's event window, 1e-13, so
// that a vertex the step left just short of its event can still take edges).
constexpr double kPointedMargin = 1e-14;

double point_segment(const Vec& p, const Vec& s, const Vec& e) {
  const Vec r = e - s;
  const double t = std::clamp((p - s).dot(r) / r.squaredNorm(), 0.0, 1.0);
  return (s + t * r - p).norm();
}

// Neighbours of a, with `extra`, sorted counter-clockwise by direction.
std::vector<std::pair<double, int>> around(const Points& q, const PptGraph& g, int a, int extra) {
  std::vector<std::pair<double, int>> dir;
  for (int b : g.neighbours(a)) dir.emplace_back(std::atan2(q[b].y() - q[a].y(), q[b].x() - q[a].x()), b);
  if (extra >= 0) dir.emplace_back(std::atan2(q[extra].y() - q[a].y(), q[extra].x() - q[a].x()), extra);
  std::sort(dir.begin(), dir.end());
  return dir;
}

// The largest counter-clockwise gap between consecutive directions, and its index (from dir[k]
// to dir[k + 1], the last one wrapping to dir[0]).
std::pair<double, std::size_t> largest_gap(const std::vector<std::pair<double, int>>& dir) {
  double best = -1.0;
  std::size_t at = 0;
  for (std::size_t k = 0; k < dir.size(); ++k) {
    const double next = k + 1 < dir.size() ? dir[k + 1].first : dir[0].first + 2.0 * M_PI;
    if (next - dir[k].first > best) best = next - dir[k].first, at = k;
  }
  return {best, at};
}

// A uniform grid over the edges: each edge is entered in every cell its segment passes through
// (exactly, column by column), so a candidate only meets the edges in its own cells.
class EdgeGrid {
 public:
  EdgeGrid(const Points& q, const PptGraph& g) : q_(q) {
    Vec lo = q[0], hi = q[0];
    for (const Vec& p : q) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const double extent = std::max((hi - lo).maxCoeff(), 1e-300);
    // About one vertex per cell.
    cell_ = extent / std::max(1.0, std::ceil(std::sqrt(static_cast<double>(q.size()))));
    origin_ = lo - Vec::Constant(0.5 * cell_);
    nx_ = static_cast<int>((hi.x() - origin_.x()) / cell_) + 2;
    ny_ = static_cast<int>((hi.y() - origin_.y()) / cell_) + 2;
    cells_.assign(static_cast<std::size_t>(nx_) * ny_, {});
    for (const auto& [a, b] : g.edge_list()) add(a, b);
  }

  void add(int a, int b) {
    const int id = static_cast<int>(ends_.size());
    ends_.emplace_back(a, b);
    stamp_.push_back(0);
    visit(a, b, [&](std::vector<int>& c) {
      c.push_back(id);
      return false;
    });
  }

  // Whether ab meets an edge of the grid other than at a shared endpoint.
  bool meets(int a, int b) {
    ++round_;
    return visit(a, b, [&](std::vector<int>& c) {
      for (int id : c) {
        if (stamp_[id] == round_) continue;
        stamp_[id] = round_;
        const auto [u, w] = ends_[id];
        if (segments_meet(q_[a], q_[b], q_[u], q_[w])) return true;
      }
      return false;
    });
  }

 private:
  // Calls f on every cell that segment ab passes through, until f returns true.
  template <typename F>
  bool visit(int a, int b, F&& f) {
    Vec s = (q_[a] - origin_) / cell_, e = (q_[b] - origin_) / cell_;
    if (s.x() > e.x()) std::swap(s, e);
    const double pad = 1e-9;
    const int x0 = std::max(0, static_cast<int>(std::floor(s.x() - pad)));
    const int x1 = std::min(nx_ - 1, static_cast<int>(std::floor(e.x() + pad)));
    for (int ix = x0; ix <= x1; ++ix) {
      const double xa = std::max(s.x(), static_cast<double>(ix)), xb = std::min(e.x(), ix + 1.0);
      const double dx = e.x() - s.x();
      const double ya = dx > 0 ? s.y() + (xa - s.x()) / dx * (e.y() - s.y()) : s.y();
      const double yb = dx > 0 ? s.y() + (xb - s.x()) / dx * (e.y() - s.y()) : e.y();
      const int y0 = std::max(0, static_cast<int>(std::floor(std::min(ya, yb) - pad)));
      const int y1 = std::min(ny_ - 1, static_cast<int>(std::floor(std::max(ya, yb) + pad)));
      for (int iy = y0; iy <= y1; ++iy)
        if (f(cells_[static_cast<std::size_t>(iy) * nx_ + ix])) return true;
    }
    return false;
  }

  const Points& q_;
  Vec origin_;
  double cell_ = 1.0;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int>> cells_;
  std::vector<std::pair<int, int>> ends_;
  std::vector<unsigned> stamp_;
  unsigned round_ = 0;
};

bool excluded_pair(int a, int b, Excluded x) { return (a == x.first && b == x.second) || (a == x.second && b == x.first); }

// Adds ab when it keeps both ends pointed and meets no edge; true if added.
bool try_add(const Points& q, PptGraph& g, EdgeGrid& grid, int a, int b, Excluded excluded) {
  if (a == b || g.has(a, b) || excluded_pair(a, b, excluded)) return false;
  if (!pointed(q, g, a, b) || !pointed(q, g, b, a) || grid.meets(a, b)) return false;
  g.add(a, b);
  grid.add(a, b);
  return true;
}

std::size_t target(const PptGraph& g) { return g.vertices() < 2 ? 0 : 2 * static_cast<std::size_t>(g.vertices()) - 3; }

// Tries the candidate pairs (squared length, a, b) shortest first; returns the edges added.
int try_sorted(const Points& q, PptGraph& g, EdgeGrid& grid, std::vector<std::tuple<double, int, int>>& cand, Excluded x) {
  std::sort(cand.begin(), cand.end());
  int added = 0;
  for (const auto& [d, a, b] : cand) {
    if (g.edges() >= target(g)) break;
    added += try_add(q, g, grid, a, b, x);
  }
  return added;
}

}  // namespace

bool PptGraph::has(int a, int b) const {
  const auto& n = adj_[a].size() <= adj_[b].size() ? adj_[a] : adj_[b];
  const int other = adj_[a].size() <= adj_[b].size() ? b : a;
  return std::find(n.begin(), n.end(), other) != n.end();
}

void PptGraph::add(int a, int b) {
  if (a == b || has(a, b)) return;
  adj_[a].push_back(b);
  adj_[b].push_back(a);
  ++count_;
}

void PptGraph::remove(int a, int b) {
  if (!has(a, b)) return;
  adj_[a].erase(std::find(adj_[a].begin(), adj_[a].end(), b));
  adj_[b].erase(std::find(adj_[b].begin(), adj_[b].end(), a));
  --count_;
}

std::vector<std::pair<int, int>> PptGraph::edge_list() const {
  std::vector<std::pair<int, int>> e;
  for (int a = 0; a < vertices(); ++a)
    for (int b : adj_[a])
      if (a < b) e.emplace_back(a, b);
  std::sort(e.begin(), e.end());
  return e;
}

bool pointed(const Points& q, const PptGraph& g, int a, int extra) {
  const auto dir = around(q, g, a, extra);
  return dir.size() < 2 || largest_gap(dir).first > M_PI + kPointedMargin;
}

std::pair<int, int> reflex_gap(const Points& q, const PptGraph& g, int a) {
  const auto dir = around(q, g, a, -1);
  if (dir.size() < 2) return {-1, -1};
  const auto [gap, k] = largest_gap(dir);
  if (!(gap > M_PI)) return {-1, -1};
  return {dir[k].second, dir[(k + 1) % dir.size()].second};
}

bool segments_meet(const Vec& a, const Vec& b, const Vec& c, const Vec& d) {
  const bool ac = a == c, ad = a == d, bc = b == c, bd = b == d;
  if ((ac || ad) && (bc || bd)) return true;
  if (ac || ad || bc || bd) {  // one shared end: they meet elsewhere only when they overlap
    const Vec s = ac || ad ? a : b, x = ac || ad ? b : a, y = ac || bc ? d : c;
    const Vec u = x - s, w = y - s;
    return std::abs(cross(u, w)) <= kTouch * u.norm() * w.norm() && u.dot(w) > 0;
  }
  const double o1 = cross(b - a, c - a), o2 = cross(b - a, d - a), o3 = cross(d - c, a - c), o4 = cross(d - c, b - c);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  const double scale = std::max((b - a).norm(), (d - c).norm());
  return std::min({point_segment(a, c, d), point_segment(b, c, d), point_segment(c, a, b), point_segment(d, a, b)}) <=
         kTouch * scale;
}

std::vector<std::pair<int, int>> hull_edges(const Points& q) {
  const int m = static_cast<int>(q.size());
  std::vector<int> order(static_cast<std::size_t>(m));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return std::make_pair(q[a].x(), q[a].y()) < std::make_pair(q[b].x(), q[b].y()); });
  // Andrew's monotone chain: the lower hull left to right, then the upper one back.
  std::vector<int> h;
  auto turn_left = [&](std::size_t floor, int p) {
    while (h.size() >= floor + 2 && cross(q[h.back()] - q[h[h.size() - 2]], q[p] - q[h[h.size() - 2]]) <= 0) h.pop_back();
    h.push_back(p);
  };
  for (int i = 0; i < m; ++i) turn_left(0, order[i]);
  const std::size_t lower = h.size() - 1;
  for (int i = m - 2; i >= 0; --i) turn_left(lower, order[i]);
  h.pop_back();  // the first point again
  const int k = static_cast<int>(h.size());
  std::vector<std::pair<int, int>> e;
  for (int i = 0; i < k; ++i) e.emplace_back(h[i], h[(i + 1) % k]);
  return e;
}

int complete_global(const Points& q, PptGraph& g, Excluded excluded) {
  const int m = g.vertices();
  if (g.edges() >= target(g)) return 0;
  EdgeGrid grid(q, g);
  int added = 0;
  for (const auto& [a, b] : hull_edges(q)) added += try_add(q, g, grid, a, b, excluded);
  double mean = 0.0;
  for (const auto& [a, b] : g.edge_list()) mean += (q[b] - q[a]).norm();
  mean = g.edges() > 0 ? mean / static_cast<double>(g.edges()) : 1.0;
  Vec lo = q[0], hi = q[0];
  for (const Vec& p : q) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double diameter = (hi - lo).norm();
  // Vertices bucketed in cells of one mean edge, for the near pairs of the first bands; never
  // more cells than about 4 per vertex (a few long bars around a dense cluster would otherwise
  // ask for 4096² cells, scanned per vertex in the last bands).
  const double cell = std::max({mean, diameter / 4096.0, diameter / (2.0 * std::sqrt(static_cast<double>(m)) + 1.0)});
  const int nx = static_cast<int>((hi.x() - lo.x()) / cell) + 1, ny = static_cast<int>((hi.y() - lo.y()) / cell) + 1;
  std::vector<std::vector<int>> bucket(static_cast<std::size_t>(nx) * ny);
  auto cx = [&](int a) { return std::min(nx - 1, static_cast<int>((q[a].x() - lo.x()) / cell)); };
  auto cy = [&](int a) { return std::min(ny - 1, static_cast<int>((q[a].y() - lo.y()) / cell)); };
  for (int a = 0; a < m; ++a) bucket[static_cast<std::size_t>(cy(a)) * nx + cx(a)].push_back(a);
  double inner = 0.0;
  for (double outer = 2.0 * mean; g.edges() < target(g); inner = outer, outer *= 2.0) {
    const int reach = static_cast<int>(std::ceil(outer / cell));
    // Per vertex, shortest first: a band's pairs over all vertices would not fit in memory at
    // the last bands of 10,000 vertices (all pairs).
    for (int a = 0; a < m && g.edges() < target(g); ++a) {
      std::vector<std::tuple<double, int, int>> cand;
      for (int y = std::max(0, cy(a) - reach); y <= std::min(ny - 1, cy(a) + reach); ++y)
        for (int x = std::max(0, cx(a) - reach); x <= std::min(nx - 1, cx(a) + reach); ++x)
          for (int b : bucket[static_cast<std::size_t>(y) * nx + x]) {
            const double d = (q[b] - q[a]).squaredNorm();
            if (b > a && d > inner * inner && d <= outer * outer) cand.emplace_back(d, a, b);
          }
      added += try_sorted(q, g, grid, cand, excluded);
    }
    if (inner > diameter) break;
  }
  return added;
}

int complete_local(const Points& q, PptGraph& g, const std::vector<int>& region, Excluded excluded) {
  if (g.edges() >= target(g)) return 0;
  std::vector<int> r = region;
  std::sort(r.begin(), r.end());
  r.erase(std::unique(r.begin(), r.end()), r.end());
  std::vector<std::tuple<double, int, int>> cand;
  for (std::size_t i = 0; i < r.size(); ++i)
    for (std::size_t j = i + 1; j < r.size(); ++j)
      if (!g.has(r[i], r[j])) cand.emplace_back((q[r[j]] - q[r[i]]).squaredNorm(), r[i], r[j]);
  if (cand.empty()) return 0;
  EdgeGrid grid(q, g);
  return try_sorted(q, g, grid, cand, excluded);
}

std::vector<int> faces_around(const Points& q, const PptGraph& g, int a, int b) {
  // The face left of half-edge u → w continues with w → x, x the neighbour of w next clockwise
  // from u.
  auto next = [&](int u, int w) {
    const auto dir = around(q, g, w, -1);
    std::size_t k = 0;
    while (dir[k].second != u) ++k;
    return dir[(k + dir.size() - 1) % dir.size()].second;
  };
  std::vector<int> out;
  auto trace = [&](int u, int w) {
    const int u0 = u, w0 = w;
    for (std::size_t steps = 0; steps <= 2 * g.edges() + 2; ++steps) {
      out.push_back(u);
      const int x = next(u, w);
      u = w, w = x;
      if (u == u0 && w == w0) break;
    }
  };
  if (b >= 0) {
    trace(a, b);
    trace(b, a);
  } else {
    for (int x : g.neighbours(a)) trace(a, x);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

PptCheck check_ppt(const Points& q, const PptGraph& g) {
  PptCheck c;
  c.edge_count = g.edges() == target(g);
  c.pointed = true;
  for (int a = 0; a < g.vertices(); ++a) c.pointed = c.pointed && pointed(q, g, a);
  c.non_crossing = true;
  const auto e = g.edge_list();
  for (std::size_t i = 0; i < e.size(); ++i)
    for (std::size_t j = i + 1; j < e.size(); ++j)
      if (segments_meet(q[e[i].first], q[e[i].second], q[e[j].first], q[e[j].second])) c.non_crossing = false;
  return c;
}

}  // namespace foldkit::folding::pseudo_detail
