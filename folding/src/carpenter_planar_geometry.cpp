// Planar-chain facts the Carpenter's-rule loop and its callers share: simplicity, turning
// angles, straight/convex, and the distance/length figures of a motion.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "foldkit/folding/carpenter.hpp"

namespace foldkit::folding {
namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Orientation of c relative to the line a→b: +1 left, −1 right, 0 on it.
int orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const double o = cross(b - a, c - a);
  return (o > 0) - (o < 0);
}

bool on_segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return std::min(a.x(), b.x()) <= c.x() && c.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= c.y() &&
         c.y() <= std::max(a.y(), b.y());
}

// Closed segments ab and cd share a point (touching counts).
bool segments_meet(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                   const Eigen::Vector2d& d) {
  const int o1 = orientation(a, b, c), o2 = orientation(a, b, d), o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) || (o3 == 0 && on_segment(c, d, a)) ||
         (o4 == 0 && on_segment(c, d, b));
}

std::string point_text(const Frame2& p, std::size_t i) {
  return "point " + std::to_string(i + 1) + " (" + std::to_string(p[i].x()) + ", " + std::to_string(p[i].y()) + ")";
}

double turn(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const Eigen::Vector2d u = b - a, w = c - b;
  return std::atan2(cross(u, w), u.dot(w));
}

}  // namespace

void check_simple_chain(const PlanarChain& chain) {
  const Frame2& p = chain.points;
  const std::size_t n = p.size();
  if (chain.closed ? n < 3 : n < 2)
    throw std::invalid_argument(std::string(chain.closed ? "a closed chain needs at least 3 points" : "a chain needs at least 2 points") +
                                ", got " + std::to_string(n));
  for (std::size_t i = 0; i < n; ++i)
    if (!p[i].allFinite()) throw std::invalid_argument(point_text(p, i) + " is not finite");
  const std::size_t bars = chain.closed ? n : n - 1;
  auto end = [&](std::size_t b) { return (b + 1) % n; };
  for (std::size_t b = 0; b < bars; ++b)
    if (p[b] == p[end(b)])
      throw std::invalid_argument("zero-length bar between " + point_text(p, b) + " and point " + std::to_string(end(b) + 1));
  // Neighbouring bars meet at their shared joint; they overlap only when folded back (turn π).
  for (std::size_t b = 0; b + 1 < bars || (chain.closed && b < bars); ++b) {
    const std::size_t j = end(b);
    const Eigen::Vector2d u = p[j] - p[b], w = p[end(j)] - p[j];
    if (cross(u, w) == 0.0 && u.dot(w) < 0.0)
      throw std::invalid_argument("the bars at " + point_text(p, j) + " fold back onto each other");
  }
  for (std::size_t a = 0; a < bars; ++a)
    for (std::size_t b = a + 2; b < bars; ++b) {
      if (chain.closed && a == 0 && b == bars - 1) continue;  // neighbours across the closing joint
      if (segments_meet(p[a], p[end(a)], p[b], p[end(b)]))
        throw std::invalid_argument("not simple: bar " + std::to_string(a + 1) + " (points " + std::to_string(a + 1) + "-" +
                                    std::to_string(end(a) + 1) + ") meets bar " + std::to_string(b + 1) + " (points " +
                                    std::to_string(b + 1) + "-" + std::to_string(end(b) + 1) + ")");
    }
}

std::vector<double> turning_angles(const Frame2& p, bool closed) {
  std::vector<double> out;
  const std::size_t n = p.size();
  if (closed) {
    for (std::size_t i = 0; i < n; ++i) out.push_back(turn(p[(i + n - 1) % n], p[i], p[(i + 1) % n]));
  } else {
    for (std::size_t i = 1; i + 1 < n; ++i) out.push_back(turn(p[i - 1], p[i], p[i + 1]));
  }
  return out;
}

bool is_straight(const Frame2& frame, double tolerance) {
  for (double t : turning_angles(frame, false))
    if (std::abs(t) > tolerance) return false;
  return true;
}

bool is_convex(const Frame2& frame, double tolerance) {
  if (frame.size() < 3) return false;
  double total = 0.0;
  bool left = false, right = false;
  for (double t : turning_angles(frame, true)) {
    total += t;
    left = left || t > tolerance;
    right = right || t < -tolerance;
  }
  return !(left && right) && std::abs(std::abs(total) - 2.0 * M_PI) < 1e-6;
}

MotionCheck check_motion(const std::vector<Frame2>& frames, bool closed) {
  MotionCheck c;
  if (frames.empty()) return c;
  const Frame2& first = frames.front();
  const std::size_t n = first.size();
  const std::size_t bars = closed ? n : (n == 0 ? 0 : n - 1);
  double growth = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const Frame2& p = frames[f];
    for (std::size_t b = 0; b < bars; ++b) {
      const std::size_t e = (b + 1) % n;
      c.max_length_error = std::max(c.max_length_error, std::abs((p[e] - p[b]).norm() - (first[e] - first[b]).norm()));
    }
    if (f == 0) continue;
    const Frame2& q = frames[f - 1];
    // A pair whose squared distance did not shrink grew by ≥ 0 (sqrt is monotone), so once the
    // minimum is ≤ 0 it needs no square roots: the check stays exact and O(n²) cheap flops.
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) {
        const Eigen::Vector2d dp = p[j] - p[i], dq = q[j] - q[i];
        if (growth <= 0.0 && dp.squaredNorm() >= dq.squaredNorm()) continue;
        growth = std::min(growth, dp.norm() - dq.norm());
      }
  }
  c.min_distance_growth = std::isinf(growth) ? 0.0 : growth;
  return c;
}

std::vector<Frame2> reversed(const std::vector<Frame2>& frames) { return {frames.rbegin(), frames.rend()}; }

namespace {

constexpr CarpenterPlanarMethod kMethods[] = {CarpenterPlanarMethod::CarriedField, CarpenterPlanarMethod::Lp,
                                              CarpenterPlanarMethod::PseudoTriangulation};

}  // namespace

const char* to_string(CarpenterPlanarMethod method) {
  switch (method) {
    case CarpenterPlanarMethod::Lp: return "lp";
    case CarpenterPlanarMethod::PseudoTriangulation: return "pseudo";
    default: return "carried";
  }
}

CarpenterPlanarMethod parse_carpenter_method(const std::string& name) {
  for (const auto m : kMethods)
    if (name == to_string(m)) return m;
  throw std::invalid_argument("unknown Carpenter method '" + name + "' (carried, lp or pseudo)");
}

std::vector<std::string> carpenter_method_names() {
  std::vector<std::string> names{to_string(CarpenterPlanarOptions{}.method)};
  for (const auto m : kMethods)
    if (names.front() != to_string(m)) names.emplace_back(to_string(m));
  return names;
}

}  // namespace foldkit::folding
