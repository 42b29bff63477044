#include "foldkit/planners/cube_chain.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace foldkit::planners {

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

// Sense in which a hinge between nets turns to keep the rest of the sheet level while the ring
// closes (the opposite of the ring's last roll, seen along the shared axis direction).
constexpr double kSwing = 1.0;

}  // namespace

geometry::FoldSequence fold_cube_chain(const geometry::CreasePattern& sheet, int cubes, double velocity) {
  if (cubes < 1 || cubes > kMaxCubeChain)
    throw std::invalid_argument("fold_cube_chain: " + std::to_string(cubes) + " cubes; the Fig. 8a sheet folds 1 to " +
                                std::to_string(kMaxCubeChain) +
                                " (every net closes on the hinge to the next, so all cubes share one edge)");
  if (!(velocity > 0) || !std::isfinite(velocity)) throw std::invalid_argument("fold_cube_chain: velocity must be positive");
  if (sheet.actors().size() != static_cast<std::size_t>(6 * cubes) || sheet.joints().size() != static_cast<std::size_t>(6 * cubes - 1))
    throw std::invalid_argument("fold_cube_chain: the sheet has " + std::to_string(sheet.actors().size()) + " actors and " +
                                std::to_string(sheet.joints().size()) + " joints; cube_sheet(" + std::to_string(cubes) +
                                ") has " + std::to_string(6 * cubes) + " and " + std::to_string(6 * cubes - 1));
  const double quarter = M_PI / 2;
  std::vector<std::pair<int, geometry::FoldCommand>> folds;
  int event = 0;
  const auto fold = [&](int joint, double angle) { folds.push_back({event, {joint, angle, velocity, 0}}); };
  for (int n = 0; n < cubes; ++n) {
    const int tile = 6 * n + 1;  // actor IDs: tiles tile … tile + 3, caps tile + 4 (above), tile + 5 (below)
    ++event;
    fold(hinge(sheet, tile + 1, tile + 4), -quarter);
    fold(hinge(sheet, tile + 1, tile + 5), -quarter);
    // The ring rolls from its far end, so that its free edge comes home along the inside of the
    // cube and nothing sweeps the space where the cubes before it sit.
    ++event;
    fold(hinge(sheet, tile + 2, tile + 3), -quarter);
    ++event;
    fold(hinge(sheet, tile + 1, tile + 2), -quarter);
    ++event;
    fold(hinge(sheet, tile, tile + 1), -quarter);
    if (n + 1 < cubes) {
      const int next = hinge(sheet, tile + 3, tile + 6);
      // Counter-turn: the rest of the sheet keeps its direction, level over the closing cube ...
      fold(next, kSwing * quarter);
      // ... then swings over the free quarter onto the cube's last face, back to back with it.
      ++event;
      fold(next, kSwing * M_PI);
    }
  }
  return geometry::make_sequence(sheet.title() + " folded into a chain of " + std::to_string(cubes) + " cubes", std::move(folds));
}

}  // namespace foldkit::planners
