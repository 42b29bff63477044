#include "foldkit/geometry/generators.hpp"
#include "spec_builder.hpp"

namespace foldkit::geometry::generators {

// Net n: the row x ∈ [3n, 3n + 3]·tile of y ∈ [0, tile] (actors 6n + 1 … 6n + 3 from left to
// right), and on the middle tile a cap above (6n + 5, y ∈ [1, 2]·tile), a cap below (6n + 6,
// y ∈ [−1, 0]·tile) and beyond that the tile opposite the middle one (6n + 4, y ∈ [−2, −1]·tile).
// The cube of net n closes on its first tile's left edge, away from the hinge to the next net, so
// that net n + 1 folds back onto the cube's far face and the cubes line up face to face
// (docs/GENERATORS.md).
PatternSpec cube_sheet(int cubes, double tile, JointDefaults j) {
  detail::require_count("cube_sheet", "cubes", cubes, 1);
  detail::require_positive("cube_sheet", "tile", tile);
  detail::require_joint_defaults("cube_sheet", j);

  auto p = [tile](int x, int y) { return Vec2(x * tile, y * tile); };
  auto square = [&](detail::SpecBuilder& b, int x, int y) { b.add_quad_actor(p(x, y), p(x + 1, y), p(x + 1, y + 1), p(x, y + 1)); };
  detail::SpecBuilder builder("cube sheet of " + std::to_string(cubes) + " nets", j);
  for (int n = 0; n < cubes; ++n) {
    const int x0 = 3 * n;
    for (int k = 0; k < 3; ++k) square(builder, x0 + k, 0);
    square(builder, x0 + 1, -2);
    square(builder, x0 + 1, 1);
    square(builder, x0 + 1, -1);
  }
  // Every hinge of a net folds the same way to close the cube (valley: the cube rises on the
  // sheet's upper side); how nets then sit against each other depends on the chain's target
  // shape, so the hinges between nets stay unassigned.
  for (int n = 0; n < cubes; ++n) {
    const int x0 = 3 * n, first = 6 * n + 1;
    builder.add_joint(p(x0 + 1, 0), p(x0 + 1, 1), first, first + 1, Assignment::Valley);
    builder.add_joint(p(x0 + 2, 0), p(x0 + 2, 1), first + 1, first + 2, Assignment::Valley);
    builder.add_joint(p(x0 + 1, -1), p(x0 + 2, -1), first + 5, first + 3, Assignment::Valley);
    builder.add_joint(p(x0 + 1, 1), p(x0 + 2, 1), first + 1, first + 4, Assignment::Valley);
    builder.add_joint(p(x0 + 1, 0), p(x0 + 2, 0), first + 1, first + 5, Assignment::Valley);
    if (n + 1 < cubes) builder.add_joint(p(x0 + 3, 0), p(x0 + 3, 1), first + 2, first + 6);
  }
  return std::move(builder).finish();
}

}  // namespace foldkit::geometry::generators
