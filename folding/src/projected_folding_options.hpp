#pragma once
// The checked options of folding::fold_projected (internal to folding/).
#include <Eigen/Core>

#include "foldkit/folding/projected_folding.hpp"

namespace foldkit::folding::detail {

// The options fold_projected folds with: `options` checked (std::invalid_argument saying what is
// wrong), target angles (`toward`) turned into the desired velocity and a target fraction of the
// largest; `desired` is set to the velocity to fold along (the assignment's when none is given).
ProjectedFoldingOptions checked_options(const geometry::CreasePattern& pattern, const ProjectedFoldingOptions& options,
                                        Eigen::VectorXd& desired);

}  // namespace foldkit::folding::detail
