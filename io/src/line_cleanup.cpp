#include "line_cleanup.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numeric>

namespace foldkit::io::detail {

namespace {

// Removes, repeatedly, the pieces with an end no other piece reaches that are at most
// `max_length` long; returns the file lines they came from.
std::set<int> remove_loose_ends(const std::vector<DrawnLine>& lines, const std::vector<Vec2>& points, std::vector<Edge>& edges,
                                double max_length) {
  std::set<int> removed_lines;
  for (bool removed = true; removed;) {
    std::vector<int> degree(points.size(), 0);
    for (const Edge& e : edges) ++degree[static_cast<std::size_t>(e.u)], ++degree[static_cast<std::size_t>(e.v)];
    const auto end = std::remove_if(edges.begin(), edges.end(), [&](const Edge& e) {
      if (degree[static_cast<std::size_t>(e.u)] > 1 && degree[static_cast<std::size_t>(e.v)] > 1) return false;
      if ((points[static_cast<std::size_t>(e.u)] - points[static_cast<std::size_t>(e.v)]).norm() > max_length) return false;
      for (int l : e.lines) removed_lines.insert(lines[static_cast<std::size_t>(l)].line);
      return true;
    });
    removed = end != edges.end();
    edges.erase(end, edges.end());
  }
  return removed_lines;
}

// Splits every edge at the points that lie on it to 2.5 tolerances: merging moves points by up
// to that, and an end not extended (a collinear line goes on from it) may stop that close to
// another line; unsplit, such a line would pass over a point and the pieces would overlap. The
// points are bucketed in a grid of 256 × 256 cells over the drawing.
void split_at_points(const std::vector<Vec2>& points, std::vector<Edge>& edges, double tol) {
  std::vector<char> used(points.size(), 0);
  Eigen::AlignedBox2d box;
  for (const Edge& e : edges) used[static_cast<std::size_t>(e.u)] = used[static_cast<std::size_t>(e.v)] = 1;
  for (std::size_t v = 0; v < points.size(); ++v)
    if (used[v]) box.extend(points[v]);
  if (box.isEmpty()) return;
  const GridCells cells{box.min(), std::max(box.diagonal().norm() / 256.0, 2.5 * tol)};
  std::unordered_map<long long, std::vector<int>> grid;
  for (std::size_t v = 0; v < points.size(); ++v)
    if (used[v]) grid[cells.key_of(points[v])].push_back(static_cast<int>(v));
  const double reach = 2.5 * tol;
  std::vector<Edge> out;
  for (const Edge& e : edges) {
    const Vec2 a = points[static_cast<std::size_t>(e.u)], d = points[static_cast<std::size_t>(e.v)] - a;
    std::vector<std::pair<double, int>> on;
    const auto consider = [&](int w) {
      if (w == e.u || w == e.v) return;
      const double t = (points[static_cast<std::size_t>(w)] - a).dot(d) / d.squaredNorm();
      if (t * d.norm() > reach && (1 - t) * d.norm() > reach && (a + t * d - points[static_cast<std::size_t>(w)]).norm() <= reach)
        on.emplace_back(t, w);
    };
    const Vec2 lo = a.cwiseMin(a + d) - Vec2::Constant(reach), hi = a.cwiseMax(a + d) + Vec2::Constant(reach);
    const long long i0 = cells.cell(lo.x(), box.min().x()), i1 = cells.cell(hi.x(), box.min().x());
    const long long j0 = cells.cell(lo.y(), box.min().y()), j1 = cells.cell(hi.y(), box.min().y());
    if (static_cast<double>(i1 - i0 + 1) * static_cast<double>(j1 - j0 + 1) > static_cast<double>(grid.size())) {
      // A long slanted piece covers more cells than hold points: every point, once.
      for (const auto& [k, list] : grid)
        for (int w : list) consider(w);
    } else {
      for (long long i = i0; i <= i1; ++i)
        for (long long j = j0; j <= j1; ++j) {
          const auto it = grid.find(cells.key(i, j));
          if (it != grid.end())
            for (int w : it->second) consider(w);
        }
    }
    std::sort(on.begin(), on.end());
    int from = e.u;
    for (const auto& [t, w] : on) {
      out.push_back({from, w, e.lines});
      from = w;
    }
    out.push_back({from, e.v, e.lines});
  }
  edges = std::move(out);
}

// Where each merged cluster of points goes (see clean()).
void place_clusters(const std::vector<DrawnLine>& lines, std::vector<Vec2>& points, const std::vector<Edge>& edges,
                    const std::function<int(int)>& find, const EndGrid& ends, double tol) {
  std::vector<std::vector<int>> lines_at(points.size());
  for (const Edge& e : edges)
    for (int p : {e.u, e.v}) lines_at[static_cast<std::size_t>(p)].insert(lines_at[static_cast<std::size_t>(p)].end(), e.lines.begin(), e.lines.end());
  const auto crossing = [&](int p) {
    const auto& at = lines_at[static_cast<std::size_t>(p)];
    const auto dir = [&](int l) { return lines[static_cast<std::size_t>(l)].b - lines[static_cast<std::size_t>(l)].a; };
    for (std::size_t a = 0; a < at.size(); ++a)
      for (std::size_t b = a + 1; b < at.size(); ++b)
        if (!parallel(dir(at[a]), dir(at[b]))) return true;
    return false;
  };
  std::map<int, std::vector<int>> members;
  for (std::size_t v = 0; v < points.size(); ++v)
    if (find(static_cast<int>(v)) != static_cast<int>(v)) members[find(static_cast<int>(v))].push_back(static_cast<int>(v));
  for (auto& [root, others] : members) {
    others.push_back(root);
    const auto cross = std::find_if(others.begin(), others.end(), crossing);
    if (cross != others.end()) {
      points[static_cast<std::size_t>(root)] = points[static_cast<std::size_t>(*cross)];
      continue;
    }
    const Vec2* end = nullptr;
    for (int w : others) {
      const Vec2& q = points[static_cast<std::size_t>(w)];
      const Vec2* e = ends.near(q, 2.5 * tol);
      if (e && (!end || (*e - q).norm() < (*end - q).norm())) end = e;
    }
    if (end) points[static_cast<std::size_t>(root)] = *end;
  }
}

}  // namespace

long long GridCells::cell(double x, double lo) const {
  // Clamped to ±2^40 cells, so that key() cannot overflow: a stray line 1e118 tolerances away
  // (outside the sheet, dropped later) is in the outermost cell. Distances are checked exactly,
  // so a clamped cell only holds more points.
  constexpr double kLimit = 1099511627776.0;
  return static_cast<long long>(std::clamp(std::floor((x - lo) / h), -kLimit, kLimit));
}

const Vec2* EndGrid::near(const Vec2& p, double reach) const {
  const long long i = cells_.cell(p.x(), cells_.origin.x()), j = cells_.cell(p.y(), cells_.origin.y());
  const auto r = static_cast<long long>(std::ceil(reach / cells_.h));
  const Vec2* best = nullptr;
  for (long long di = -r; di <= r; ++di)
    for (long long dj = -r; dj <= r; ++dj) {
      const auto it = grid_.find(cells_.key(i + di, j + dj));
      if (it == grid_.end()) continue;
      for (const Vec2& q : it->second)
        if ((q - p).norm() <= reach && (!best || (q - p).norm() < (*best - p).norm())) best = &q;
    }
  return best;
}

void EndGrid::snap(Vec2& p) {
  if (const Vec2* q = near(p, cells_.h)) {
    p = *q;
    return;
  }
  grid_[cells_.key_of(p)].push_back(p);
}

void clean(const std::vector<DrawnLine>& lines, std::vector<Vec2>& points, std::vector<Edge>& edges, const EndGrid& ends, double tol) {
  remove_loose_ends(lines, points, edges, 2.5 * tol);  // the extension's stubs
  std::vector<int> parent(points.size());
  std::iota(parent.begin(), parent.end(), 0);
  const std::function<int(int)> find = [&](int x) { return parent[x] == x ? x : parent[x] = find(parent[x]); };
  for (const Edge& e : edges)
    if ((points[e.u] - points[e.v]).norm() <= 2.5 * tol) parent[find(e.u)] = find(e.v);
  place_clusters(lines, points, edges, find, ends, tol);
  std::vector<Edge> merged;
  for (Edge e : edges) {
    e.u = find(e.u);
    e.v = find(e.v);
    if (e.u != e.v) merged.push_back(std::move(e));
  }
  split_at_points(points, merged, tol);
  std::map<std::pair<int, int>, std::size_t> seen;
  std::vector<Edge> kept;
  for (Edge e : merged) {
    const auto [it, added] = seen.emplace(std::minmax(e.u, e.v), kept.size());
    if (added) {
      kept.push_back(std::move(e));
      continue;
    }
    std::vector<int>& into = kept[it->second].lines;
    into.insert(into.end(), e.lines.begin(), e.lines.end());
    std::sort(into.begin(), into.end());
    into.erase(std::unique(into.begin(), into.end()), into.end());
  }
  edges = std::move(kept);
}

bool on_border(const std::vector<DrawnLine>& lines, const Edge& e) {
  return std::any_of(e.lines.begin(), e.lines.end(), [&](int l) { return lines[static_cast<std::size_t>(l)].kind == LineKind::Border; });
}

std::set<int> prune_outside(const std::vector<DrawnLine>& lines, const std::vector<Vec2>& points, std::vector<Edge>& edges) {
  std::vector<const Edge*> border;
  for (const Edge& e : edges)
    if (on_border(lines, e)) border.push_back(&e);
  // Even-odd: a ray from m crosses the border an odd number of times (a border with holes too).
  const auto inside = [&](const Vec2& m) {
    bool odd = false;
    for (const Edge* b : border) {
      const Vec2 &p = points[static_cast<std::size_t>(b->u)], &q = points[static_cast<std::size_t>(b->v)];
      if ((p.y() > m.y()) != (q.y() > m.y()) && m.x() < p.x() + (m.y() - p.y()) * (q.x() - p.x()) / (q.y() - p.y())) odd = !odd;
    }
    return odd;
  };
  std::set<int> outside;
  std::vector<Edge> kept;
  for (Edge& e : edges) {
    if (on_border(lines, e) || inside(0.5 * (points[static_cast<std::size_t>(e.u)] + points[static_cast<std::size_t>(e.v)]))) {
      kept.push_back(std::move(e));
    } else {
      for (int l : e.lines) outside.insert(lines[static_cast<std::size_t>(l)].line);
    }
  }
  edges = std::move(kept);
  return outside;
}

std::set<int> prune_loose(const std::vector<DrawnLine>& lines, const std::vector<Vec2>& points, std::vector<Edge>& edges) {
  return remove_loose_ends(lines, points, edges, std::numeric_limits<double>::infinity());
}

}  // namespace foldkit::io::detail
