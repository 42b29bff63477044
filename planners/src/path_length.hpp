#pragma once
// The path-length objective every plan optimises, with an informed sampler that works on
// foldkit's own state spaces. Private to foldkit::planners.
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>

namespace foldkit::planners::detail {

/// OMPL's path length (the space's own distance) whose informed sampler (BIT*, ABIT*, AIT*,
/// Informed RRT*, SORRT*, CForest) is OMPL's direct ellipsoidal one only where that one works, on
/// real-vector, SE(2) and SE(3) spaces (the joint box of a sheet without loops), and OMPL's
/// rejection sampler elsewhere: uniform states of the space's own sampler, kept when start →
/// state → goal by the space's distance could still beat the best cost. The direct sampler
/// throws on the single-vertex and driving spaces, and on a constrained space it would sample
/// the ambient box, off the closure manifold.
/// Whether OMPL's direct ellipsoidal informed sampler works on the space: real-vector, SE(2) and
/// SE(3) spaces (the joint box of a sheet without loops); none of foldkit's own.
bool has_direct_informed_sampler(const ompl::base::SpaceInformationPtr& si);

class PathLength : public ompl::base::PathLengthOptimizationObjective {
 public:
  using ompl::base::PathLengthOptimizationObjective::PathLengthOptimizationObjective;
  /// The direct sampler on real-vector, SE(2) and SE(3) spaces; the rejection sampler otherwise.
  ompl::base::InformedSamplerPtr allocInformedStateSampler(const ompl::base::ProblemDefinitionPtr& probDefn,
                                                           unsigned int maxNumberCalls) const override;
};

}  // namespace foldkit::planners::detail
