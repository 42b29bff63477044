// Loose lines → a crease pattern (drawn_lines.hpp). CGAL's 2D arrangement with an exact kernel
// splits the lines where they cross and merges overlaps, with no hand-written intersection code
// (docs/FORMATS.md says why CGAL). The arrangement's vertices and edges, each edge with its
// kind, are then handed to the FOLD importer as a flat FOLD document, which derives the faces,
// joins the faces of one actor (facet lines: FOLD's J), triangulates them and builds the
// pattern; its messages are mapped back to the lines of the drawing.
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include <CGAL/Arr_consolidated_curve_data_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include "foldkit/io/drawn_lines.hpp"
#include "foldkit/io/fold_format.hpp"
#include "foldkit/io/number_format.hpp"
#include "foldkit/io/parse_error.hpp"

namespace foldkit::io {

namespace {

using geometry::Vec2;
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using SegmentTraits = CGAL::Arr_segment_traits_2<Kernel>;
using Traits = CGAL::Arr_consolidated_curve_data_traits_2<SegmentTraits, int>;
using Arrangement = CGAL::Arrangement_2<Traits>;

struct Edge {
  int u = 0, v = 0;
  std::vector<int> lines;  // indices of the drawn lines it lies on
};

// The drawn lines' ends, distinct to `tol`: a hash grid of cell `tol` counted from the drawing's
// corner `origin` (a cell index stays below diagonal / tol = 1e5 wherever the drawing lies).
class EndGrid {
 public:
  EndGrid(const Vec2& origin, double tol) : origin_(origin), tol_(tol) {}
  // The nearest end within `reach` of p, or null.
  const Vec2* near(const Vec2& p, double reach) const {
    const long long i = cell(p.x() - origin_.x()), j = cell(p.y() - origin_.y());
    const auto r = static_cast<long long>(std::ceil(reach / tol_));
    const Vec2* best = nullptr;
    for (long long di = -r; di <= r; ++di)
      for (long long dj = -r; dj <= r; ++dj) {
        const auto it = grid_.find(key(i + di, j + dj));
        if (it == grid_.end()) continue;
        for (const Vec2& q : it->second)
          if ((q - p).norm() <= reach && (!best || (q - p).norm() < (*best - p).norm())) best = &q;
      }
    return best;
  }
  // p, or the end already within tol of it (then p is that end).
  void snap(Vec2& p) {
    if (const Vec2* q = near(p, tol_)) {
      p = *q;
      return;
    }
    grid_[key(cell(p.x() - origin_.x()), cell(p.y() - origin_.y()))].push_back(p);
  }

 private:
  long long cell(double x) const { return static_cast<long long>(std::floor(x / tol_)); }
  static long long key(long long i, long long j) { return i * 1000003LL ^ j; }
  Vec2 origin_;
  double tol_;
  std::unordered_map<long long, std::vector<Vec2>> grid_;
};

int rank(LineKind k) {  // which kind an edge drawn twice takes: the outline first
  switch (k) {
    case LineKind::Border: return 0;
    case LineKind::Cut: return 1;
    case LineKind::Mountain: return 2;
    case LineKind::Valley: return 3;
    case LineKind::Hinge: return 4;
    default: return 5;
  }
}

char fold_letter(LineKind k) {
  switch (k) {
    case LineKind::Border: return 'B';
    case LineKind::Cut: return 'C';
    case LineKind::Mountain: return 'M';
    case LineKind::Valley: return 'V';
    case LineKind::Hinge: return 'U';
    default: return 'J';  // facet: the faces on both sides are one actor
  }
}

// The arrangement of the lines. Each end is extended by `tol`, so that a line that stops short of
// another by rounding still meets it (the stubs this leaves are removed afterwards), except where
// a collinear line goes on from the same end (after snapping): the two already meet there, and
// extending both would lay two nearly collinear pieces side by side that never intersect.
void arrange(const std::vector<DrawnLine>& lines, double tol, std::vector<Vec2>& points, std::vector<Edge>& edges) {
  std::map<std::pair<double, double>, std::vector<std::size_t>> ends_at;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    ends_at[{lines[i].a.x(), lines[i].a.y()}].push_back(i);
    ends_at[{lines[i].b.x(), lines[i].b.y()}].push_back(i);
  }
  const auto extend = [&](std::size_t i, const Vec2& p) {
    const Vec2 d = lines[i].b - lines[i].a;
    for (std::size_t j : ends_at[{p.x(), p.y()}]) {
      const Vec2 f = lines[j].b - lines[j].a;
      if (j != i && std::abs(d.x() * f.y() - d.y() * f.x()) <= 1e-6 * d.norm() * f.norm()) return false;
    }
    return true;
  };
  std::vector<Traits::Curve_2> curves;
  std::map<std::pair<std::pair<double, double>, std::pair<double, double>>, int> drawn_once;
  std::map<int, std::vector<int>> duplicates;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const Vec2 d = lines[i].b - lines[i].a;
    if (d.norm() <= tol) continue;
    const Vec2 a = extend(i, lines[i].a) ? Vec2(lines[i].a - tol * d.normalized()) : lines[i].a;
    const Vec2 b = extend(i, lines[i].b) ? Vec2(lines[i].b + tol * d.normalized()) : lines[i].b;
    // A line drawn twice goes in once (CGAL 5.5's sweep asserts on some stacks of identical
    // overlapping curves, a fuzzer's find): its duplicates ride on the first one's data.
    std::pair<double, double> p(a.x(), a.y()), q(b.x(), b.y());
    if (q < p) std::swap(p, q);
    const auto [first, added] = drawn_once.emplace(std::make_pair(p, q), static_cast<int>(i));
    if (!added) {
      duplicates[first->second].push_back(static_cast<int>(i));
      continue;
    }
    curves.emplace_back(SegmentTraits::Curve_2(Kernel::Point_2(a.x(), a.y()), Kernel::Point_2(b.x(), b.y())), static_cast<int>(i));
  }
  Arrangement arr;
  CGAL::insert(arr, curves.begin(), curves.end());
  std::map<Arrangement::Vertex_const_handle, int> index;
  for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v) {
    index[v] = static_cast<int>(points.size());
    points.emplace_back(CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y()));
  }
  for (auto e = arr.edges_begin(); e != arr.edges_end(); ++e) {
    Edge out{index.at(e->source()), index.at(e->target()), {}};
    for (auto it = e->curve().data().begin(); it != e->curve().data().end(); ++it) {
      out.lines.push_back(*it);
      const auto more = duplicates.find(*it);
      if (more != duplicates.end()) out.lines.insert(out.lines.end(), more->second.begin(), more->second.end());
    }
    std::sort(out.lines.begin(), out.lines.end());
    edges.push_back(std::move(out));
  }
}

// Splits every edge at the vertices that lie on it to 2.5 tolerances: merging moves points by up
// to that, and an end not extended (a collinear line goes on from it) may stop that close to
// another line; unsplit, such a line would pass over a vertex and the pieces would overlap. The
// vertices are bucketed in a grid of 256 × 256 cells over the drawing.
void split_at_vertices(const std::vector<Vec2>& points, std::vector<Edge>& edges, double tol) {
  std::vector<char> used(points.size(), 0);
  Eigen::AlignedBox2d box;
  for (const Edge& e : edges) used[static_cast<std::size_t>(e.u)] = used[static_cast<std::size_t>(e.v)] = 1;
  for (std::size_t v = 0; v < points.size(); ++v)
    if (used[v]) box.extend(points[v]);
  if (box.isEmpty()) return;
  const double h = std::max(box.diagonal().norm() / 256.0, 2.5 * tol);
  const auto cell = [&](double x, double lo) { return static_cast<long long>(std::floor((x - lo) / h)); };
  std::unordered_map<long long, std::vector<int>> grid;
  const auto key = [](long long i, long long j) { return i * 1000003LL ^ j; };
  for (std::size_t v = 0; v < points.size(); ++v)
    if (used[v]) grid[key(cell(points[v].x(), box.min().x()), cell(points[v].y(), box.min().y()))].push_back(static_cast<int>(v));
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
    const long long i0 = cell(std::min(a.x(), a.x() + d.x()) - reach, box.min().x()), i1 = cell(std::max(a.x(), a.x() + d.x()) + reach, box.min().x());
    const long long j0 = cell(std::min(a.y(), a.y() + d.y()) - reach, box.min().y()), j1 = cell(std::max(a.y(), a.y() + d.y()) + reach, box.min().y());
    if ((i1 - i0 + 1) * (j1 - j0 + 1) > static_cast<long long>(grid.size())) {
      // A long slanted piece covers more cells than hold points: every point, once.
      for (const auto& [k, list] : grid)
        for (int w : list) consider(w);
    } else {
      for (long long i = i0; i <= i1; ++i)
        for (long long j = j0; j <= j1; ++j) {
          const auto it = grid.find(key(i, j));
          if (it != grid.end())
            for (int w : it->second) consider(w);
        }
    }
    if (on.empty()) {
      out.push_back(e);
      continue;
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

// Removes the overshoot stubs (an edge ≤ 2.5 tol long ending in a vertex of nobody else) and
// merges the vertices of edges as short (the overlap of two collinear lines extended past their
// common end, near-meetings of three or more lines).
void clean(const std::vector<DrawnLine>& lines, std::vector<Vec2>& points, std::vector<Edge>& edges, const EndGrid& ends, double tol) {
  for (bool removed = true; removed;) {
    removed = false;
    std::vector<int> degree(points.size(), 0);
    for (const Edge& e : edges) ++degree[e.u], ++degree[e.v];
    const auto stub = [&](const Edge& e) {
      return (degree[e.u] == 1 || degree[e.v] == 1) && (points[e.u] - points[e.v]).norm() <= 2.5 * tol;
    };
    const auto end = std::remove_if(edges.begin(), edges.end(), stub);
    removed = end != edges.end();
    edges.erase(end, edges.end());
  }
  std::vector<int> parent(points.size());
  std::iota(parent.begin(), parent.end(), 0);
  const std::function<int(int)> find = [&](int x) { return parent[x] == x ? x : parent[x] = find(parent[x]); };
  for (const Edge& e : edges)
    if ((points[e.u] - points[e.v]).norm() <= 2.5 * tol) parent[find(e.u)] = find(e.v);
  // Where a merged cluster of points goes: where two lines of the drawing cross, if they cross
  // in it (a straight crease stays straight through its vertex); else where a drawn line ends, if
  // one ends there (the extension moved the points it made off the ends by up to its length).
  std::vector<std::vector<int>> lines_at(points.size());
  for (const Edge& e : edges)
    for (int p : {e.u, e.v}) lines_at[static_cast<std::size_t>(p)].insert(lines_at[static_cast<std::size_t>(p)].end(), e.lines.begin(), e.lines.end());
  const auto crossing = [&](int p) {
    const auto& at = lines_at[static_cast<std::size_t>(p)];
    for (std::size_t a = 0; a < at.size(); ++a)
      for (std::size_t b = a + 1; b < at.size(); ++b) {
        const Vec2 d = lines[at[a]].b - lines[at[a]].a, f = lines[at[b]].b - lines[at[b]].a;
        if (std::abs(d.x() * f.y() - d.y() * f.x()) > 1e-6 * d.norm() * f.norm()) return true;
      }
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
  std::vector<Edge> merged_edges;
  for (Edge e : edges) {
    e.u = find(e.u);
    e.v = find(e.v);
    if (e.u != e.v) merged_edges.push_back(std::move(e));
  }
  split_at_vertices(points, merged_edges, tol);
  std::map<std::pair<int, int>, std::size_t> seen;
  std::vector<Edge> kept;
  for (Edge e : merged_edges) {
    const auto key = std::minmax(e.u, e.v);
    const auto [it, added] = seen.emplace(key, kept.size());
    if (added) {
      kept.push_back(std::move(e));
    } else {
      std::vector<int>& into = kept[it->second].lines;
      into.insert(into.end(), e.lines.begin(), e.lines.end());
      std::sort(into.begin(), into.end());
      into.erase(std::unique(into.begin(), into.end()), into.end());
    }
  }
  edges = std::move(kept);
}

// The FOLD document of the cleaned arrangement, one vertex or edge per text line; `source` gets
// the drawing's line for each text line (1-based; 0 where none).
std::string fold_text(const std::vector<DrawnLine>& lines, const std::vector<Vec2>& points, const std::vector<Edge>& edges,
                      const std::string& name, std::vector<int>& source) {
  std::vector<int> used(points.size(), -1), first_line(points.size(), 0);
  std::vector<int> order;
  for (const Edge& e : edges)
    for (int p : {e.u, e.v})
      if (used[p] < 0) {
        used[p] = static_cast<int>(order.size());
        order.push_back(p);
        first_line[p] = lines[e.lines.front()].line;
      }
  std::ostringstream out;
  source.assign(2, 0);  // line 0 (unused) and the opening brace
  const auto emit = [&](const std::string& text, int from) {
    out << text << '\n';
    source.push_back(from);
  };
  out << "{\n";
  emit("\"file_spec\": 1.2, \"file_creator\": \"foldkit: lines of " + name + "\", \"frame_classes\": [\"creasePattern\"],", 0);
  emit("\"vertices_coords\": [", 0);
  for (std::size_t k = 0; k < order.size(); ++k) {
    const Vec2& p = points[order[k]];  // y up, as foldkit's patterns and its SVG writer
    emit("[" + format_number(p.x()) + ", " + format_number(-p.y()) + "]" + (k + 1 < order.size() ? "," : ""), first_line[order[k]]);
  }
  emit("],", 0);
  std::vector<LineKind> kind(edges.size());
  std::vector<int> from(edges.size());
  bool any_target = false;
  for (std::size_t k = 0; k < edges.size(); ++k) {
    int best = edges[k].lines.front();
    for (int l : edges[k].lines)
      if (rank(lines[l].kind) < rank(lines[best].kind)) best = l;
    kind[k] = lines[best].kind;
    from[k] = best;
    any_target = any_target || lines[best].target.has_value();
  }
  const auto list = [&](const std::string& key, const std::function<std::string(std::size_t)>& item, bool last) {
    emit("\"" + key + "\": [", 0);
    for (std::size_t k = 0; k < edges.size(); ++k) emit(item(k) + (k + 1 < edges.size() ? "," : ""), lines[from[k]].line);
    emit(last ? "]" : "],", 0);
  };
  list("edges_vertices", [&](std::size_t k) { return "[" + std::to_string(used[edges[k].u]) + ", " + std::to_string(used[edges[k].v]) + "]"; }, false);
  list("edges_assignment", [&](std::size_t k) { return std::string("\"") + fold_letter(kind[k]) + "\""; }, !any_target);
  if (any_target)  // FOLD's sign: positive = valley, degrees
    list("edges_foldAngle", [&](std::size_t k) {
      const auto& t = lines[from[k]].target;
      return t ? format_number(-*t * 180.0 / M_PI) : std::string("null");
    }, true);
  out << "}\n";
  return out.str();
}

bool on_border(const std::vector<DrawnLine>& lines, const Edge& e) {
  return std::any_of(e.lines.begin(), e.lines.end(), [&](int l) { return lines[l].kind == LineKind::Border; });
}

// Removes the edges outside the sheet: a crease drawn past the border may close faces out there
// with other such lines. Inside is where a ray from the edge's midpoint crosses the border an
// odd number of times (even-odd, so a border with holes works too). Returns their lines.
std::set<int> prune_outside(const std::vector<DrawnLine>& lines, const std::vector<Vec2>& points, std::vector<Edge>& edges) {
  std::vector<const Edge*> border;
  for (const Edge& e : edges)
    if (on_border(lines, e)) border.push_back(&e);
  const auto inside = [&](const Vec2& m) {
    bool odd = false;
    for (const Edge* b : border) {
      const Vec2 &p = points[b->u], &q = points[b->v];
      if ((p.y() > m.y()) != (q.y() > m.y()) && m.x() < p.x() + (m.y() - p.y()) * (q.x() - p.x()) / (q.y() - p.y())) odd = !odd;
    }
    return odd;
  };
  std::set<int> outside;
  std::vector<Edge> kept;
  for (Edge& e : edges) {
    if (on_border(lines, e) || inside(0.5 * (points[e.u] + points[e.v]))) {
      kept.push_back(std::move(e));
    } else {
      for (int l : e.lines) outside.insert(lines[l].line);
    }
  }
  edges = std::move(kept);
  return outside;
}

// Removes what bounds no face: edges with an end no other edge reaches, repeatedly (a crease
// drawn past the border, one that ends inside a facet, a line outside the sheet). Returns the
// drawing's lines they came from.
std::set<int> prune_loose(const std::vector<DrawnLine>& lines, std::vector<Vec2>& points, std::vector<Edge>& edges) {
  std::set<int> loose;
  for (bool removed = true; removed;) {
    std::vector<int> degree(points.size(), 0);
    for (const Edge& e : edges) ++degree[e.u], ++degree[e.v];
    const auto end = std::remove_if(edges.begin(), edges.end(), [&](const Edge& e) {
      if (degree[e.u] > 1 && degree[e.v] > 1) return false;
      for (int l : e.lines) loose.insert(lines[l].line);
      return true;
    });
    removed = end != edges.end();
    edges.erase(end, edges.end());
  }
  return loose;
}

int mapped(const std::vector<int>& source, int line) {
  return line > 0 && static_cast<std::size_t>(line) < source.size() ? source[static_cast<std::size_t>(line)] : 0;
}

}  // namespace

const char* to_string(LineKind kind) {
  switch (kind) {
    case LineKind::Border: return "border";
    case LineKind::Mountain: return "mountain";
    case LineKind::Valley: return "valley";
    case LineKind::Cut: return "cut";
    case LineKind::Facet: return "facet";
    default: return "hinge";
  }
}

PatternFile pattern_from_lines(const std::vector<DrawnLine>& drawn, const std::string& name, const LineImportOptions& options) {
  if (!(options.merge_tolerance > 0.0 && options.merge_tolerance <= 1e-2))
    throw std::invalid_argument("pattern_from_lines: the merge tolerance must be in (0, 0.01]");
  if (drawn.empty()) throw ParseError(name, 0, "no lines: nothing is drawn with a stroke of a crease-pattern colour");
  if (std::none_of(drawn.begin(), drawn.end(), [](const DrawnLine& l) { return l.kind == LineKind::Border; }))
    throw ParseError(name, drawn.front().line, "no border line (black): the sheet's outline must be drawn");
  Eigen::AlignedBox2d box;
  for (const DrawnLine& l : drawn) box.extend(l.a), box.extend(l.b);
  const double diagonal = box.diagonal().norm();
  if (!(diagonal > 0.0) || !std::isfinite(diagonal)) throw ParseError(name, drawn.front().line, "the lines have no extent");
  const double tol = options.merge_tolerance * diagonal;
  EndGrid ends(box.min(), tol);
  std::vector<DrawnLine> lines = drawn;
  for (DrawnLine& l : lines) ends.snap(l.a), ends.snap(l.b);
  std::vector<Vec2> points;
  std::vector<Edge> edges;
  arrange(lines, tol, points, edges);
  clean(lines, points, edges, ends, tol);
  std::set<int> loose = prune_outside(lines, points, edges);
  const std::set<int> dangling = prune_loose(lines, points, edges);
  loose.insert(dangling.begin(), dangling.end());
  if (edges.empty())
    throw ParseError(name, drawn.front().line, "the lines enclose no sheet: the border (black) must be a closed outline");
  if (std::none_of(edges.begin(), edges.end(), [&](const Edge& e) { return on_border(lines, e); }))
    throw ParseError(name, drawn.front().line, "the closed lines include no border line (black): the sheet's outline must be drawn");
  // The outline is closed where every point of it has an even number of border pieces.
  std::vector<int> border_degree(points.size(), 0), border_line(points.size(), 0);
  for (const Edge& e : edges)
    if (on_border(lines, e))
      for (int p : {e.u, e.v}) {
        ++border_degree[static_cast<std::size_t>(p)];
        for (int l : e.lines)
          if (lines[l].kind == LineKind::Border) border_line[static_cast<std::size_t>(p)] = lines[l].line;
      }
  for (std::size_t p = 0; p < points.size(); ++p)
    if (border_degree[p] % 2 == 1)
      throw ParseError(name, border_line[p], "the border (black) does not close: it ends at (" + format_number(points[p].x()) + ", " +
                                                 format_number(points[p].y()) + ") in the file's coordinates");
  std::vector<int> source;
  const std::string text = fold_text(lines, points, edges, name, source);
  FoldImport fold = [&] {
    try {
      return parse_fold(text, name, options.build);
    } catch (const ParseError& e) {
      throw ParseError(name, mapped(source, e.line()), e.message() + " (in the pattern the lines draw)");
    }
  }();
  for (auto& w : fold.warnings) w.line = mapped(source, w.line);
  if (!loose.empty()) {
    std::string which;
    int shown = 0;
    for (int l : loose)
      if (shown++ < 12) which += (shown > 1 ? ", " : "") + std::to_string(l);
    if (loose.size() > 12) which += " and " + std::to_string(loose.size() - 12) + " more";
    fold.warnings.insert(fold.warnings.begin(), geometry::Diagnostic{geometry::Severity::Warning, *loose.begin(),
        "the lines at line" + std::string(loose.size() > 1 ? "s " : " ") + which +
            " bound no face (outside the border, or ending inside a facet): those parts are ignored"});
  }
  return {std::move(fold.pattern), std::move(fold.state), std::move(fold.warnings)};
}

}  // namespace foldkit::io
