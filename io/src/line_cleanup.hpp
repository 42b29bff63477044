#pragma once
// Cleaning the arrangement of drawn lines (line_arrangement.cpp) into the pieces of a sheet:
// snapping ends, merging what the merge tolerance makes one, splitting pieces at points that lie
// on them, dropping what lies outside the border or bounds no face. Internal to foldkit::io.
#include <cmath>
#include <set>
#include <unordered_map>
#include <vector>

#include "foldkit/io/drawn_lines.hpp"

namespace foldkit::io::detail {

using geometry::Vec2;

// One piece of the arrangement: its two points and the drawn lines it lies on.
struct Edge {
  int u = 0, v = 0;
  std::vector<int> lines;  // indices of the drawn lines
};

// Whether two directions are parallel to 1e-6 rad.
inline bool parallel(const Vec2& d, const Vec2& f) { return std::abs(d.x() * f.y() - d.y() * f.x()) <= 1e-6 * d.norm() * f.norm(); }

// Square cells of side `h` counted from `origin`, hashed into one key: the buckets of the grids
// below. Counting from the drawing's corner keeps a cell index small wherever the drawing lies.
struct GridCells {
  Vec2 origin;
  double h;
  long long cell(double x, double lo) const;
  long long key(long long i, long long j) const { return i * 1000003LL ^ j; }
  long long key_of(const Vec2& p) const { return key(cell(p.x(), origin.x()), cell(p.y(), origin.y())); }
};

// The drawn lines' ends, distinct to `tol` (a grid of cells `tol`).
class EndGrid {
 public:
  EndGrid(const Vec2& origin, double tol) : cells_{origin, tol} {}
  // The nearest end within `reach` of p, or null.
  const Vec2* near(const Vec2& p, double reach) const;
  // p, or the end already within tol of it (then p is that end).
  void snap(Vec2& p);

 private:
  GridCells cells_;
  std::unordered_map<long long, std::vector<Vec2>> grid_;
};

// Removes the overshoot stubs the extension left and merges the points of pieces up to 2.5 `tol`
// long; a merged cluster goes to the crossing of two lines in it, else to the drawn end it
// stands for. Then splits the pieces at the points on them and merges pieces drawn twice.
void clean(const std::vector<DrawnLine>& lines, std::vector<Vec2>& points, std::vector<Edge>& edges, const EndGrid& ends, double tol);

// Whether a piece lies on a border line.
bool on_border(const std::vector<DrawnLine>& lines, const Edge& e);

// Removes the pieces outside the border (even-odd); returns the file lines they came from.
std::set<int> prune_outside(const std::vector<DrawnLine>& lines, const std::vector<Vec2>& points, std::vector<Edge>& edges);

// Removes, repeatedly, pieces with an end no other piece reaches (they bound no face); returns
// the file lines they came from.
std::set<int> prune_loose(const std::vector<DrawnLine>& lines, const std::vector<Vec2>& points, std::vector<Edge>& edges);

}  // namespace foldkit::io::detail
