#pragma once
// Collision checks along a projected-velocity fold, private to foldkit::folding.
#include <string>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/simulation/collision_world.hpp"
#include "foldkit/simulation/corner_motion.hpp"

namespace foldkit::folding {

/// Largest |fold angle| / π of a state (0 for a pattern without creases).
double fraction_of(const geometry::FoldState& s);

// Follows the path through a collision world, in order, with sub-steps so that no facet corner
// moves farther between two checks than the world's margin, up to a rigid motion of the sheet (its memory of stacked facets needs
// that). The pattern must outlive the checker.
class PathChecker {
 public:
  explicit PathChecker(const geometry::CreasePattern& pattern);

  // Empty when the straight motion from `a` to `b` crosses nothing, else what crossed.
  std::string crossing(const geometry::FoldState& a, const geometry::FoldState& b);

  // Starts the world's memory of the motion again at `x` (a state crossing-free on the path
  // checked so far), to check another motion from it.
  void restart(const geometry::FoldState& x);

 private:
  const geometry::CreasePattern& pattern_;
  geometry::KinematicTree tree_;
  double margin_;
  simulation::CollisionWorld world_;
  simulation::CornerMotion motion_;  // how far the facets move between two states, up to a rigid motion
  bool first_ = true;
};

}  // namespace foldkit::folding
