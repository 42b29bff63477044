#include "vertex_index.hpp"

namespace foldkit::geometry::detail {

std::optional<int> VertexIndex::find(const Vec2& p) const {
  std::optional<int> best;
  double best_d = tolerance_;
  for (auto it = tree_.qbegin(bgi::intersects(box_around(p, tolerance_))); it != tree_.qend(); ++it) {
    const double d = (points_[it->second] - p).norm();
    if (d <= best_d) {
      best_d = d;
      best = it->second;
    }
  }
  return best;
}

int VertexIndex::insert(const Vec2& p) {
  if (auto found = find(p)) return *found;
  const int id = static_cast<int>(points_.size());
  // −0 + 0 = +0: a corner written "-0" must not turn a crease direction from π to −π.
  const Vec2 q(p.x() + 0.0, p.y() + 0.0);
  points_.push_back(q);
  tree_.insert({BPoint(q.x(), q.y()), id});
  return id;
}

}  // namespace foldkit::geometry::detail
