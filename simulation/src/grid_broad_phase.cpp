#include "grid_broad_phase.hpp"

#include <algorithm>
#include <cmath>

namespace foldkit::simulation::detail {

namespace {

bool overlap(const Eigen::Vector3d& lo_a, const Eigen::Vector3d& hi_a, const Eigen::Vector3d& lo_b,
             const Eigen::Vector3d& hi_b) {
  for (int k = 0; k < 3; ++k)
    if (lo_a[k] > hi_b[k] || lo_b[k] > hi_a[k]) return false;
  return true;
}

struct Grid {
  Eigen::Vector3d origin;
  double width = 1.0;
  Eigen::Vector3i dims;

  Eigen::Vector3i cell(const Eigen::Vector3d& p) const {
    Eigen::Vector3i c;
    for (int k = 0; k < 3; ++k)
      c[k] = std::clamp(static_cast<int>(std::floor((p[k] - origin[k]) / width)), 0, dims[k] - 1);
    return c;
  }
  int index(const Eigen::Vector3i& c) const { return (c.z() * dims.y() + c.y()) * dims.x() + c.x(); }
};

// A grid whose cells are about as wide as the mean box, and never more cells than 8 per box (a
// few huge boxes among small ones widen the cells instead of multiplying them).
Grid make_grid(const std::vector<Eigen::Vector3d>& lo, const std::vector<Eigen::Vector3d>& hi) {
  Grid g;
  Eigen::Vector3d low = lo[0], high = hi[0];
  double mean = 0.0;
  for (std::size_t i = 0; i < lo.size(); ++i) {
    low = low.cwiseMin(lo[i]);
    high = high.cwiseMax(hi[i]);
    mean += (hi[i] - lo[i]).maxCoeff();
  }
  mean /= static_cast<double>(lo.size());
  const Eigen::Vector3d extent = high - low;
  g.origin = low;
  g.width = std::max({mean, 1e-9 * extent.maxCoeff(), 1e-300});
  const double most = 8.0 * static_cast<double>(lo.size()) + 8.0;
  for (;;) {
    double cells = 1.0;
    for (int k = 0; k < 3; ++k) cells *= std::floor(extent[k] / g.width) + 1.0;
    if (cells <= most) break;
    g.width *= 1.5;
  }
  for (int k = 0; k < 3; ++k) g.dims[k] = static_cast<int>(std::floor(extent[k] / g.width)) + 1;
  return g;
}

}  // namespace

void GridBroadPhase::overlapping(const std::vector<Eigen::Vector3d>& lo, const std::vector<Eigen::Vector3d>& hi,
                                 std::vector<std::pair<int, int>>& pairs) {
  pairs.clear();
  const int n = static_cast<int>(lo.size());
  if (n < 2) return;
  bool finite = true;
  for (int i = 0; i < n; ++i) finite = finite && lo[i].allFinite() && hi[i].allFinite();
  if (!finite) {  // no grid to put such boxes in: every pair, compared as FCL compares them
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b)
        if (overlap(lo[a], hi[a], lo[b], hi[b])) pairs.emplace_back(a, b);
    return;
  }
  const Grid g = make_grid(lo, hi);
  const int cells = g.dims.prod();
  // Counting sort of the boxes into the cells they cover.
  first_.resize(n);
  last_.resize(n);
  cell_start_.assign(static_cast<std::size_t>(cells) + 1, 0);
  for (int i = 0; i < n; ++i) {
    first_[i] = g.cell(lo[i]);
    last_[i] = g.cell(hi[i]);
    for (int z = first_[i].z(); z <= last_[i].z(); ++z)
      for (int y = first_[i].y(); y <= last_[i].y(); ++y)
        for (int x = first_[i].x(); x <= last_[i].x(); ++x) ++cell_start_[g.index({x, y, z}) + 1];
  }
  for (int c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_members_.resize(static_cast<std::size_t>(cell_start_[cells]));
  cell_fill_.assign(cell_start_.begin(), cell_start_.end() - 1);
  for (int i = 0; i < n; ++i)
    for (int z = first_[i].z(); z <= last_[i].z(); ++z)
      for (int y = first_[i].y(); y <= last_[i].y(); ++y)
        for (int x = first_[i].x(); x <= last_[i].x(); ++x) cell_members_[cell_fill_[g.index({x, y, z})]++] = i;
  // Each overlapping pair from the cell of its intersection's low corner only.
  found_.clear();
  for (int c = 0; c < cells; ++c)
    for (int p = cell_start_[c]; p < cell_start_[c + 1]; ++p)
      for (int q = p + 1; q < cell_start_[c + 1]; ++q) {
        const int a = cell_members_[p], b = cell_members_[q];
        // The cell of the intersection's low corner, max(lo_a, lo_b), is the larger of the boxes'
        // first cells on each axis (the cell of a coordinate is monotone in it): integers only.
        if (g.index(first_[a].cwiseMax(first_[b])) != c || !overlap(lo[a], hi[a], lo[b], hi[b])) continue;
        found_.emplace_back(std::min(a, b), std::max(a, b));
      }
  // Sorted: a counting sort by first box, then each (short) run by second.
  per_first_.assign(static_cast<std::size_t>(n) + 1, 0);
  for (const auto& [a, b] : found_) ++per_first_[a + 1];
  for (int i = 0; i < n; ++i) per_first_[i + 1] += per_first_[i];
  pairs.resize(found_.size());
  order_.assign(per_first_.begin(), per_first_.end() - 1);
  for (const auto& pair : found_) pairs[order_[pair.first]++] = pair;
  for (int i = 0; i < n; ++i) std::sort(pairs.begin() + per_first_[i], pairs.begin() + per_first_[i + 1]);
}

}  // namespace foldkit::simulation::detail
