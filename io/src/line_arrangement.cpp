// Loose lines → a crease pattern (drawn_lines.hpp). CGAL's 2D arrangement with an exact kernel
// splits the lines where they cross and merges overlaps, with no hand-written intersection code
// (docs/FORMATS.md says why CGAL). The arrangement's vertices and edges, each edge with its
// kind, are then handed to the FOLD importer as a flat FOLD document, which derives the faces,
// joins the faces of one actor (facet lines: FOLD's J), triangulates them and builds the
// pattern; its messages are mapped back to the lines of the drawing.
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include <CGAL/Arr_consolidated_curve_data_traits_2.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include "foldkit/io/drawn_lines.hpp"
#include "foldkit/io/fold_format.hpp"
#include "foldkit/io/number_format.hpp"
#include "foldkit/io/parse_error.hpp"
#include "line_cleanup.hpp"

namespace foldkit::io {

namespace {

using detail::Edge;
using detail::EndGrid;
using detail::on_border;
using geometry::Vec2;
using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using SegmentTraits = CGAL::Arr_segment_traits_2<Kernel>;
using Traits = CGAL::Arr_consolidated_curve_data_traits_2<SegmentTraits, int>;
using Arrangement = CGAL::Arrangement_2<Traits>;

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
    for (std::size_t j : ends_at[{p.x(), p.y()}])
      if (j != i && detail::parallel(lines[i].b - lines[i].a, lines[j].b - lines[j].a)) return false;
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

// Throws at the first point where the outline ends: a closed outline has an even number of
// border pieces at every point.
void check_border_closed(const std::vector<DrawnLine>& lines, const std::vector<Vec2>& points, const std::vector<Edge>& edges,
                         const std::string& name) {
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
}

int mapped(const std::vector<int>& source, int line) {
  return line > 0 && static_cast<std::size_t>(line) < source.size() ? source[static_cast<std::size_t>(line)] : 0;
}

// What is left of a cut after the pieces outside the border went is inside the sheet, or on the
// border (where the border's kind wins). A CreasePattern is one sheet whose facets meet along
// creases, welded by position, so a slit through it cannot be expressed (docs/FORMATS.md).
void refuse_inner_cuts(const std::vector<DrawnLine>& lines, const std::vector<Edge>& edges, const std::string& name) {
  for (const Edge& e : edges) {
    if (on_border(lines, e)) continue;
    const auto cut = std::find_if(e.lines.begin(), e.lines.end(), [&](int l) { return lines[static_cast<std::size_t>(l)].kind == LineKind::Cut; });
    if (cut == e.lines.end()) continue;
    throw ParseError(name, lines[static_cast<std::size_t>(*cut)].line,
                     "a cut (green) inside the sheet: foldkit folds one sheet whose facets meet along creases, so cuts "
                     "through it (kirigami) are not read; a cut on the border is read as border");
  }
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
  // The tolerance is relative to the sheet: the border's extent. A stray line far outside it
  // (dropped below) must not coarsen it; with the drawing's extent, one line 600 sheets away made
  // the tolerance a hundredth of the sheet, and a second import of the result differed (fuzz find).
  Eigen::AlignedBox2d box, sheet;
  for (const DrawnLine& l : drawn) {
    box.extend(l.a), box.extend(l.b);
    if (l.kind == LineKind::Border) sheet.extend(l.a), sheet.extend(l.b);
  }
  const double diagonal = sheet.diagonal().norm();
  if (!(diagonal > 0.0) || !std::isfinite(diagonal))
    throw ParseError(name, drawn.front().line, "the border has no extent");
  const double tol = options.merge_tolerance * diagonal;
  EndGrid ends(box.min(), tol);
  std::vector<DrawnLine> lines = drawn;
  for (DrawnLine& l : lines) ends.snap(l.a), ends.snap(l.b);
  std::vector<Vec2> points;
  std::vector<Edge> edges;
  arrange(lines, tol, points, edges);
  detail::clean(lines, points, edges, ends, tol);
  std::set<int> loose = detail::prune_outside(lines, points, edges);
  const std::set<int> dangling = detail::prune_loose(lines, points, edges);
  loose.insert(dangling.begin(), dangling.end());
  if (edges.empty())
    throw ParseError(name, drawn.front().line, "the lines enclose no sheet: the border (black) must be a closed outline");
  if (std::none_of(edges.begin(), edges.end(), [&](const Edge& e) { return on_border(lines, e); }))
    throw ParseError(name, drawn.front().line, "the closed lines include no border line (black): the sheet's outline must be drawn");
  check_border_closed(lines, points, edges, name);
  refuse_inner_cuts(lines, edges, name);
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
