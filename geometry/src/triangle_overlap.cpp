#include "foldkit/geometry/triangle_overlap.hpp"

#include <algorithm>
#include <limits>

#include "vertex_index.hpp"

namespace foldkit::geometry {
using namespace detail;
namespace {

// Overlap length of the projections of both triangles on the unit normal of edge (p, q).
double projected_overlap(const Tri2& a, const Tri2& b, const Vec2& p, const Vec2& q) {
  Vec2 n(p.y() - q.y(), q.x() - p.x());
  const double len = n.norm();
  if (len == 0.0) return std::numeric_limits<double>::infinity();
  n /= len;
  auto range = [&](const Tri2& t) {
    double lo = n.dot(t[0]), hi = lo;
    for (int k = 1; k < 3; ++k) {
      lo = std::min(lo, n.dot(t[k]));
      hi = std::max(hi, n.dot(t[k]));
    }
    return std::make_pair(lo, hi);
  };
  const auto [alo, ahi] = range(a);
  const auto [blo, bhi] = range(b);
  return std::min(ahi, bhi) - std::max(alo, blo);
}

BBox bounds(const Tri2& t) {
  BBox box(BPoint(t[0].x(), t[0].y()), BPoint(t[0].x(), t[0].y()));
  for (int k = 1; k < 3; ++k) bg::expand(box, BPoint(t[k].x(), t[k].y()));
  return box;
}

}  // namespace

bool triangles_overlap(const Tri2& a, const Tri2& b, double tolerance) {
  for (const Tri2* t : {&a, &b})
    for (int k = 0; k < 3; ++k)
      if (projected_overlap(a, b, (*t)[k], (*t)[(k + 1) % 3]) <= tolerance) return false;
  return true;
}

std::vector<std::pair<int, int>> overlapping_pairs(const std::vector<Tri2>& triangles, double tolerance) {
  std::vector<std::pair<BBox, int>> boxes;
  boxes.reserve(triangles.size());
  for (std::size_t i = 0; i < triangles.size(); ++i) boxes.emplace_back(bounds(triangles[i]), static_cast<int>(i));
  const bgi::rtree<std::pair<BBox, int>, bgi::quadratic<16>> tree(boxes.begin(), boxes.end());

  std::vector<std::pair<int, int>> pairs;
  for (const auto& [box, i] : boxes) {
    for (auto it = tree.qbegin(bgi::intersects(box)); it != tree.qend(); ++it) {
      const int j = it->second;
      if (j > i && triangles_overlap(triangles[i], triangles[j], tolerance)) pairs.emplace_back(i, j);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace foldkit::geometry
