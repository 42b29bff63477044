#pragma once
// Flaps for the dynamic tests: a fixed base (actor 1, the unit square left of x = 0) and a flap
// (actor 2) on x ≥ 0 hinged to it by joint 1 along the y axis from (0, 0) to (0, 1). The flap's
// centroid distance from the hinge and its inertia about it are computed here independently of
// foldkit::dynamics (polygon formulas).
#include <cmath>
#include <string>
#include <vector>

#include "foldkit/geometry/crease_pattern.hpp"

namespace foldkit::test {

struct Flap {
  std::string name;
  std::vector<geometry::Vec2> polygon;  // convex, counter-clockwise, first edge (0,1) → (0,0) on the hinge
};

inline std::vector<Flap> flap_shapes() {
  return {{"square", {{0, 1}, {0, 0}, {1, 0}, {1, 1}}},
          {"long rectangle", {{0, 1}, {0, 0}, {2.5, 0}, {2.5, 1}}},
          {"triangle", {{0, 1}, {0, 0}, {0.8, 0.3}}},
          {"trapezoid", {{0, 1}, {0, 0}, {1.5, 0.25}, {1.5, 0.75}}}};
}

// Area, first moment about the hinge (∫x dA) and second moment about it (∫x² dA) of a convex
// polygon, by the shoelace-style sums of its edges.
struct PolygonMoments {
  double area = 0.0, first = 0.0, second = 0.0;
};
inline PolygonMoments moments(const std::vector<geometry::Vec2>& p) {
  PolygonMoments m;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto& a = p[i];
    const auto& b = p[(i + 1) % p.size()];
    const double cross = a.x() * b.y() - b.x() * a.y();
    m.area += cross / 2.0;
    m.first += cross * (a.x() + b.x()) / 6.0;
    m.second += cross * (a.x() * a.x() + a.x() * b.x() + b.x() * b.x()) / 12.0;
  }
  return m;
}

// The base square and the flap, fanned into triangles from its first corner; joint 1 on the hinge
// with the given spring and damping constants. Extra flaps on the base's left edge can be added.
inline geometry::PatternSpec flap_spec(const Flap& flap, double spring = 0.0, double damping = 0.0) {
  geometry::PatternSpec s;
  s.title = flap.name;
  s.actors.push_back({1, {{{{{-1, 0}, {0, 0}, {0, 1}}}}, {{{{-1, 0}, {0, 1}, {-1, 1}}}}}});
  geometry::ActorSpec f{2, {}};
  for (std::size_t i = 1; i + 1 < flap.polygon.size(); ++i)
    f.triangles.push_back({{flap.polygon[0], flap.polygon[i], flap.polygon[i + 1]}});
  s.actors.push_back(f);
  s.joints.push_back({1, {{{0, 0}, {0, 1}}}, {1, 2}, spring, damping});
  return s;
}

// A second, small flap (actor 3, joint 2) on the base's left edge: a motor on it keeps the clock
// running while joint 1 swings free.
inline void add_clock_flap(geometry::PatternSpec& s) {
  s.actors.push_back({3, {{{{{-1, 0}, {-1, 1}, {-1.2, 0.5}}}}}});
  s.joints.push_back({2, {{{-1, 0}, {-1, 1}}}, {1, 3}, 0.0, 0.0});
}

}  // namespace foldkit::test
