#include "foldkit/folding/cube_chain.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace foldkit::folding {

namespace {

// The ID of the joint between the actors with IDs a and b.
int hinge(const geometry::CreasePattern& sheet, int a, int b) {
  const auto ia = sheet.actor_index(a), ib = sheet.actor_index(b);
  if (ia && ib)
    for (const geometry::Joint& j : sheet.joints())
      if ((j.actors[0] == *ia && j.actors[1] == *ib) || (j.actors[0] == *ib && j.actors[1] == *ia)) return j.id;
  throw std::invalid_argument("not a cube sheet (docs/GENERATORS.md): no hinge between actors " + std::to_string(a) + " and " +
                              std::to_string(b));
}

}  // namespace

geometry::FoldSequence fold_cube_chain(const geometry::CreasePattern& sheet, int cubes, double speed) {
  if (cubes < 1) throw std::invalid_argument("fold_cube_chain: " + std::to_string(cubes) + " cubes; at least 1");
  if (!(speed > 0) || !std::isfinite(speed)) throw std::invalid_argument("fold_cube_chain: the speed must be positive");
  if (sheet.actors().size() != static_cast<std::size_t>(6 * cubes) || sheet.joints().size() != static_cast<std::size_t>(6 * cubes - 1))
    throw std::invalid_argument("fold_cube_chain: the sheet has " + std::to_string(sheet.actors().size()) + " actors and " +
                                std::to_string(sheet.joints().size()) + " joints; cube_sheet(" + std::to_string(cubes) +
                                ") has " + std::to_string(6 * cubes) + " and " + std::to_string(6 * cubes - 1));
  const double quarter = M_PI / 2;
  std::vector<std::pair<int, geometry::FoldCommand>> folds;
  int event = 0;
  const auto fold = [&](int joint, double angle, double joint_speed) { folds.push_back({event, {joint, angle, joint_speed, 0}}); };
  for (int n = 0; n < cubes; ++n) {
    // Actor IDs (docs/GENERATORS.md): first, first + 1, first + 2 the row (first + 1 carries the
    // caps), first + 3 the far cap, first + 4 the cap above, first + 5 the cap below.
    const int first = 6 * n + 1;
    // The row rolls up over its first tile while the hinge to the next net turns back by the sum
    // of both rolls, all in proportion: the rest of the sheet keeps its direction and rides above
    // the closing cube, landing face to face on its far side.
    ++event;
    fold(hinge(sheet, first, first + 1), -quarter, speed);
    fold(hinge(sheet, first + 1, first + 2), -quarter, speed);
    if (n + 1 < cubes) fold(hinge(sheet, first + 2, first + 6), M_PI, 2 * speed);
    // Then the caps close the sides, and the far cap the last face, inside the cube.
    ++event;
    fold(hinge(sheet, first + 1, first + 4), -quarter, speed);
    fold(hinge(sheet, first + 1, first + 5), -quarter, speed);
    ++event;
    fold(hinge(sheet, first + 5, first + 3), -quarter, speed);
  }
  return geometry::make_sequence(sheet.title() + " folded into a chain of " + std::to_string(cubes) + " cubes", std::move(folds));
}

}  // namespace foldkit::folding
