#include "path_length.hpp"

#include <algorithm>
#include <utility>

#include <ompl/base/samplers/informed/RejectionInfSampler.h>

namespace foldkit::planners::detail {

namespace ob = ompl::base;

bool has_direct_informed_sampler(const ob::SpaceInformationPtr& si) {
  const int type = si->getStateSpace()->getType();
  return type == ob::STATE_SPACE_REAL_VECTOR || type == ob::STATE_SPACE_SE2 || type == ob::STATE_SPACE_SE3;
}

ob::InformedSamplerPtr PathLength::allocInformedStateSampler(const ob::ProblemDefinitionPtr& probDefn,
                                                             unsigned int maxNumberCalls) const {
  if (has_direct_informed_sampler(si_))
    return ob::PathLengthOptimizationObjective::allocInformedStateSampler(probDefn, maxNumberCalls);
  return rejection_sampler(probDefn, maxNumberCalls, stop_);
}

namespace {

// OMPL's rejection sampler that stops drawing once the plan's time is up (path_length.hpp).
class BoundedRejection : public ob::RejectionInfSampler {
 public:
  BoundedRejection(const ob::ProblemDefinitionPtr& pdef, unsigned int draws, std::function<bool()> stop)
      : ob::RejectionInfSampler(pdef, draws), stop_(std::move(stop)), uniform_(pdef->getSpaceInformation()->allocStateSampler()) {}
  bool sampleUniform(ob::State* state, const ob::Cost& max_cost) override {
    if (!stopped()) return ob::RejectionInfSampler::sampleUniform(state, max_cost);
    uniform_->sampleUniform(state);  // AIT* checks the state whatever the answer: a real one
    return false;
  }
  bool sampleUniform(ob::State* state, const ob::Cost& min_cost, const ob::Cost& max_cost) override {
    if (!stopped()) return ob::RejectionInfSampler::sampleUniform(state, min_cost, max_cost);
    uniform_->sampleUniform(state);
    return false;
  }

 private:
  bool stopped() const { return stop_ && stop_(); }
  std::function<bool()> stop_;
  ob::StateSamplerPtr uniform_;
};

}  // namespace

ob::InformedSamplerPtr rejection_sampler(const ob::ProblemDefinitionPtr& pdef, unsigned int max_calls, std::function<bool()> stop) {
  return std::make_shared<BoundedRejection>(pdef, std::min(max_calls, kRejectionDraws), std::move(stop));
}

}  // namespace foldkit::planners::detail
