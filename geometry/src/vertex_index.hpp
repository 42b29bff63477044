#pragma once
#include <optional>
#include <utility>
#include <vector>

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

#include "foldkit/geometry/types.hpp"

namespace foldkit::geometry::detail {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using BPoint = bg::model::point<double, 2, bg::cs::cartesian>;
using BBox = bg::model::box<BPoint>;

inline BBox box_around(const Vec2& p, double r) { return BBox({p.x() - r, p.y() - r}, {p.x() + r, p.y() + r}); }

// Welds points closer than `tolerance` into one vertex (first come, first kept), so that
// triangles drawn separately share their corners.
class VertexIndex {
 public:
  explicit VertexIndex(double tolerance) : tolerance_(tolerance) {}
  int insert(const Vec2& p);
  std::optional<int> find(const Vec2& p) const;
  const std::vector<Vec2>& points() const { return points_; }

 private:
  double tolerance_;
  std::vector<Vec2> points_;
  bgi::rtree<std::pair<BPoint, int>, bgi::quadratic<16>> tree_;
};

}  // namespace foldkit::geometry::detail
