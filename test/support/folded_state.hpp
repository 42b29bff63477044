#pragma once
// A closed folded state for tests: the pattern's assignment direction (valley −angle, every
// other crease +angle) projected onto the closure manifold to 1e-12 rad, signs kept.
#include <stdexcept>

#include <Eigen/Core>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/projection.hpp"

namespace foldkit::test {

inline geometry::FoldState folded_along_assignment(const geometry::CreasePattern& p, double angle) {
  Eigen::VectorXd g(static_cast<Eigen::Index>(p.joints().size()));
  for (std::size_t j = 0; j < p.joints().size(); ++j)
    g[static_cast<Eigen::Index>(j)] = p.joints()[j].assignment == geometry::Assignment::Valley ? -angle : angle;
  geometry::ProjectionOptions po;
  po.tolerance = 1e-12;
  const auto r = geometry::project(geometry::ClosureSystem(p), geometry::FoldState{g}, po);
  if (!r.status.ok()) throw std::runtime_error("folded_along_assignment: " + r.status.message);
  return r.state;
}

}  // namespace foldkit::test
