#include <cmath>

#include "foldkit/geometry/generators.hpp"
#include "spec_builder.hpp"

namespace foldkit::geometry::generators {
namespace {

constexpr double kPi = 3.14159265358979323846;

Assignment unassigned(int, int) { return Assignment::Unassigned; }

}  // namespace

PatternSpec strip(int panels, double panel_width, double height, JointDefaults j) {
  detail::require_count("strip", "panels", panels, 1);
  detail::require_positive("strip", "panel_width", panel_width);
  detail::require_positive("strip", "height", height);
  detail::require_joint_defaults("strip", j);
  detail::SpecBuilder builder("strip of " + std::to_string(panels) + " panels", j);
  auto corner = [&](int i, int k) { return Vec2(i * panel_width, k * height); };
  detail::add_quad_lattice(builder, 1, panels, corner, unassigned, unassigned);
  return std::move(builder).finish();
}

PatternSpec grid(int rows, int cols, double cell, JointDefaults j) {
  detail::require_count("grid", "rows", rows, 1);
  detail::require_count("grid", "cols", cols, 1);
  detail::require_positive("grid", "cell", cell);
  detail::require_joint_defaults("grid", j);
  detail::SpecBuilder builder("grid " + std::to_string(rows) + "x" + std::to_string(cols), j);
  auto corner = [&](int i, int k) { return Vec2(i * cell, k * cell); };
  detail::add_quad_lattice(builder, rows, cols, corner, unassigned, unassigned);
  return std::move(builder).finish();
}

PatternSpec circular_lattice(int rings, int spokes, double ring_width, JointDefaults j) {
  detail::require_count("circular_lattice", "rings", rings, 1);
  detail::require_count("circular_lattice", "spokes", spokes, 3);
  detail::require_positive("circular_lattice", "ring_width", ring_width);
  detail::require_joint_defaults("circular_lattice", j);

  // Point on circle k (0 = the centre) at spoke s; spoke `spokes` is spoke 0 again.
  std::vector<Vec2> directions;
  for (int s = 0; s < spokes; ++s) {
    const double a = 2 * kPi * s / spokes;
    directions.emplace_back(std::cos(a), std::sin(a));
  }
  auto point = [&](int k, int s) -> Vec2 { return (k * ring_width) * directions[s % spokes]; };
  auto actor = [&](int ring, int s) { return ring * spokes + s % spokes + 1; };

  detail::SpecBuilder builder(
      "circular lattice of " + std::to_string(rings) + " rings, " + std::to_string(spokes) + " spokes", j);
  for (int ring = 0; ring < rings; ++ring)
    for (int s = 0; s < spokes; ++s) {
      if (ring == 0)
        builder.add_fan_actor({point(0, 0), point(1, s), point(1, s + 1)});
      else
        builder.add_quad_actor(point(ring, s), point(ring + 1, s), point(ring + 1, s + 1), point(ring, s + 1));
    }
  for (int ring = 0; ring < rings; ++ring) {
    for (int s = 0; s < spokes; ++s)
      builder.add_joint(point(ring, s), point(ring + 1, s), actor(ring, s + spokes - 1), actor(ring, s));
    if (ring + 1 < rings)
      for (int s = 0; s < spokes; ++s)
        builder.add_joint(point(ring + 1, s), point(ring + 1, s + 1), actor(ring, s), actor(ring + 1, s));
  }
  return std::move(builder).finish();
}

}  // namespace foldkit::geometry::generators
