#pragma once
#include <optional>
#include "foldkit/geometry/generators.hpp"
#include <cmath>
#include <random>
#include <vector>

#include "foldkit/geometry/pattern_spec.hpp"

namespace foldkit::test {

// An axis-aligned square actor of side `size` with its lower-left corner at (x, y).
inline geometry::ActorSpec square_actor(int id, double x, double y, double size = 1.0) {
  using geometry::Vec2;
  const Vec2 a(x, y), b(x + size, y), c(x + size, y + size), d(x, y + size);
  return {id, {{{a, b, c}, 0}, {{a, c, d}, 0}}, 0};
}

inline geometry::JointSpec joint(int id, geometry::Vec2 p, geometry::Vec2 q, int a1, int a2) {
  return {id, {p, q}, {a1, a2}, 1.0, 0.1, geometry::Assignment::Unassigned, 0, std::nullopt};
}

// 2 × 2 unit squares (IDs 1..4 counter-clockwise from the lower left) with their four creases.
inline geometry::PatternSpec two_by_two() {
  using geometry::Vec2;
  geometry::PatternSpec s;
  s.title = "2x2";
  s.actors = {square_actor(1, 0, 0), square_actor(2, 1, 0), square_actor(3, 1, 1), square_actor(4, 0, 1)};
  s.joints = {joint(1, Vec2(1, 0), Vec2(1, 1), 1, 2), joint(2, Vec2(1, 1), Vec2(2, 1), 2, 3),
              joint(3, Vec2(1, 1), Vec2(1, 2), 3, 4), joint(4, Vec2(0, 1), Vec2(1, 1), 4, 1)};
  return s;
}

// Two 1 × 2 actors side by side whose joint (ID 7) runs from (1,0) to (1,2) straight through
// the vertex (1,1), which splits the shared line into two mesh edges.
inline geometry::PatternSpec straight_crease_through_vertex() {
  using geometry::Vec2;
  geometry::PatternSpec s;
  geometry::ActorSpec left{1, {}, 0}, right{2, {}, 0};
  left.triangles = {{{Vec2(0, 0), Vec2(1, 0), Vec2(1, 1)}, 0}, {{Vec2(0, 0), Vec2(1, 1), Vec2(0, 2)}, 0},
                    {{Vec2(0, 2), Vec2(1, 1), Vec2(1, 2)}, 0}};
  right.triangles = {{{Vec2(1, 0), Vec2(2, 0), Vec2(1, 1)}, 0}, {{Vec2(1, 1), Vec2(2, 0), Vec2(2, 2)}, 0},
                     {{Vec2(1, 1), Vec2(2, 2), Vec2(1, 2)}, 0}};
  s.actors = {left, right};
  s.joints = {joint(7, Vec2(1, 0), Vec2(1, 2), 1, 2)};
  return s;
}

// n random positive sector angles summing to 2π, none below `smallest` (default 0.05).
using geometry::generators::random_sectors;

}  // namespace foldkit::test
