#include "foldkit/geometry/generators.hpp"
#include "spec_builder.hpp"

namespace foldkit::geometry::generators {

// Net n covers x ∈ [4n, 4n + 4]·tile of the row y ∈ [0, tile], its caps x ∈ [4n + 1, 4n + 2]·tile
// on either side. Actors of net n: 6n + 1..6n + 4 the row from left to right, 6n + 5 the cap
// above, 6n + 6 the cap below.
PatternSpec cube_sheet(int cubes, double tile, JointDefaults j) {
  detail::require_count("cube_sheet", "cubes", cubes, 1);
  detail::require_positive("cube_sheet", "tile", tile);
  detail::require_joint_defaults("cube_sheet", j);

  auto p = [tile](int x, int y) { return Vec2(x * tile, y * tile); };
  detail::SpecBuilder builder("cube sheet of " + std::to_string(cubes) + " nets", j);
  for (int n = 0; n < cubes; ++n) {
    const int x0 = 4 * n;
    for (int k = 0; k < 4; ++k) builder.add_quad_actor(p(x0 + k, 0), p(x0 + k + 1, 0), p(x0 + k + 1, 1), p(x0 + k, 1));
    builder.add_quad_actor(p(x0 + 1, 1), p(x0 + 2, 1), p(x0 + 2, 2), p(x0 + 1, 2));
    builder.add_quad_actor(p(x0 + 1, -1), p(x0 + 2, -1), p(x0 + 2, 0), p(x0 + 1, 0));
  }
  // Every hinge of a net folds the same way to close the cube (valley: the cube rises on the
  // sheet's upper side); how nets then sit against each other depends on the chain's target
  // shape, so the hinges between nets stay unassigned.
  for (int n = 0; n < cubes; ++n) {
    const int x0 = 4 * n, first = 6 * n + 1;
    for (int k = 1; k < 4; ++k) builder.add_joint(p(x0 + k, 0), p(x0 + k, 1), first + k - 1, first + k, Assignment::Valley);
    builder.add_joint(p(x0 + 1, 1), p(x0 + 2, 1), first + 1, first + 4, Assignment::Valley);
    builder.add_joint(p(x0 + 1, 0), p(x0 + 2, 0), first + 1, first + 5, Assignment::Valley);
    if (n + 1 < cubes) builder.add_joint(p(x0 + 4, 0), p(x0 + 4, 1), first + 3, first + 6);
  }
  return std::move(builder).finish();
}

}  // namespace foldkit::geometry::generators
