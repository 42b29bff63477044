#pragma once
// A Miura-ori's closed states along its one-DOF fold, shared by the collision tests.
#include <vector>

#include <gtest/gtest.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/projection.hpp"

namespace foldkit::simulation::testing {

// Every crease at ±m (mountain +, valley −) for m = first, first + step, … ≤ last, each projected
// onto closure from the previous closed state (continuation). Fails the test when a projection
// does not converge, and returns the states found until then.
inline std::vector<geometry::FoldState> closed_miura_path(const geometry::CreasePattern& miura, double first, double step,
                                                          double last) {
  const geometry::ClosureSystem sys(miura);
  std::vector<geometry::FoldState> path;
  geometry::FoldState s = geometry::FoldState::flat(miura);
  for (double m = first; m <= last; m += step) {
    geometry::FoldState rough = s;
    for (std::size_t j = 0; j < miura.joints().size(); ++j)
      rough.angles[static_cast<Eigen::Index>(j)] = miura.joints()[j].assignment == geometry::Assignment::Mountain ? m : -m;
    const auto r = geometry::project(sys, rough);
    EXPECT_TRUE(r.status.ok()) << m;
    if (!r.status.ok()) break;
    path.push_back(s = r.state);
  }
  return path;
}

}  // namespace foldkit::simulation::testing
