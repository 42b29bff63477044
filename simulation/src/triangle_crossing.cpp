#include "triangle_crossing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

namespace foldkit::simulation::detail {
namespace {

// Signed distances of `t`'s corners from the plane of `p`; empty when `p` is degenerate.
std::optional<std::array<double, 3>> distances(const Tri3& t, const Tri3& p) {
  Eigen::Vector3d n = (p[1] - p[0]).cross(p[2] - p[0]);
  const double len = n.norm();
  if (!(len > 0.0)) return std::nullopt;
  n /= len;
  return std::array<double, 3>{n.dot(t[0] - p[0]), n.dot(t[1] - p[0]), n.dot(t[2] - p[0])};
}

bool straddles(const std::array<double, 3>& d, double tolerance) {
  const auto [lo, hi] = std::minmax({d[0], d[1], d[2]});
  return lo < -tolerance && hi > tolerance;
}

// How far the corners reach through the plane on the side that reaches less.
double reach(const std::array<double, 3>& d) {
  const auto [lo, hi] = std::minmax({d[0], d[1], d[2]});
  return std::min(-lo, hi);
}

// The interval, along `direction`, of the points where `t` meets the other plane: corners
// within `tolerance` of it, and edge crossings between corners on opposite sides.
std::array<double, 2> cut(const Tri3& t, const std::array<double, 3>& d, const Eigen::Vector3d& direction,
                          double tolerance) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  auto take = [&](const Eigen::Vector3d& x) {
    const double s = direction.dot(x);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  };
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (std::abs(d[i]) <= tolerance) take(t[i]);
    if ((d[i] < -tolerance && d[j] > tolerance) || (d[i] > tolerance && d[j] < -tolerance))
      take(t[i] + (t[j] - t[i]) * (d[i] / (d[i] - d[j])));
  }
  return {lo, hi};
}

}  // namespace

std::optional<TriangleCrossing> triangles_cross(const Tri3& a, const Tri3& b, double tolerance) {
  const auto da = distances(a, b);  // a's corners against b's plane
  const auto db = distances(b, a);
  if (!da || !db || !straddles(*da, tolerance) || !straddles(*db, tolerance)) return std::nullopt;
  const Eigen::Vector3d na = (a[1] - a[0]).cross(a[2] - a[0]);
  const Eigen::Vector3d nb = (b[1] - b[0]).cross(b[2] - b[0]);
  Eigen::Vector3d line = na.cross(nb);
  const double len = line.norm();
  if (!(len > 0.0)) return std::nullopt;
  line /= len;
  const auto ca = cut(a, *da, line, tolerance);
  const auto cb = cut(b, *db, line, tolerance);
  const double lo = std::max(ca[0], cb[0]);
  const double hi = std::min(ca[1], cb[1]);
  if (!(hi - lo > tolerance)) return std::nullopt;
  // A point on both planes: the component of the midpoint along `line`, plus the closest point
  // of the planes' common line to the origin.
  const double oa = na.dot(a[0]);
  const double ob = nb.dot(b[0]);
  const Eigen::Vector3d base = (oa * nb - ob * na).cross(na.cross(nb)) / na.cross(nb).squaredNorm();
  return TriangleCrossing{base + line * (0.5 * (lo + hi) - line.dot(base)), std::min(reach(*da), reach(*db))};
}

}  // namespace foldkit::simulation::detail
