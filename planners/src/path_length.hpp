#pragma once
// The path-length objective every plan optimises, with an informed sampler that works on
// foldkit's own state spaces. Private to foldkit::planners.
#include <functional>

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

/// The most uniform states OMPL's rejection sampler draws for one informed sample. BIT*, ABIT*
/// and AIT* ask for an unbounded number (UINT_MAX), and OMPL 1.5.2's AIT* draws until it gets a
/// sample without checking the time limit: once the best cost nears the heuristic's bound the
/// informed set has next to no measure, and AIT* with `rotation` on a degree-8 vertex drew for
/// over ten minutes of a 0.5 s run. After this many draws the sampler answers "not found" (BIT*
/// tries again within its batch's budget; AIT* keeps the last uniform state, a valid sample that
/// merely is not informed). InformedRRT*'s own default number of attempts.
constexpr unsigned int kRejectionDraws = 100;

/// OMPL's rejection sampler with at most kRejectionDraws draws per sample (fewer when the
/// planner asks for fewer). Once `stop` answers true (the plan's FoldValidity::expired(): its
/// time is up) a sample is one uniform draw, answered "not found": OMPL 1.5.2's BIT* fills a
/// batch (up to 200 tries of 100 draws) without looking at the time, and on the Resch pattern,
/// each draw a driving-space sample, one 10 s run went on for 184 s.
ompl::base::InformedSamplerPtr rejection_sampler(const ompl::base::ProblemDefinitionPtr& pdef, unsigned int max_calls,
                                                 std::function<bool()> stop = {});

class PathLength : public ompl::base::PathLengthOptimizationObjective {
 public:
  /// Path length on `si`'s space; `stop` as rejection_sampler()'s (empty: never).
  explicit PathLength(const ompl::base::SpaceInformationPtr& si, std::function<bool()> stop = {})
      : ompl::base::PathLengthOptimizationObjective(si), stop_(std::move(stop)) {}
  /// The direct sampler on real-vector, SE(2) and SE(3) spaces; the rejection sampler otherwise.
  ompl::base::InformedSamplerPtr allocInformedStateSampler(const ompl::base::ProblemDefinitionPtr& probDefn,
                                                           unsigned int maxNumberCalls) const override;

 private:
  std::function<bool()> stop_;
};

}  // namespace foldkit::planners::detail
