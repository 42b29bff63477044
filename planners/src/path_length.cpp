#include "path_length.hpp"

#include <ompl/base/samplers/informed/RejectionInfSampler.h>

namespace foldkit::planners::detail {

namespace ob = ompl::base;

ob::InformedSamplerPtr PathLength::allocInformedStateSampler(const ob::ProblemDefinitionPtr& probDefn,
                                                             unsigned int maxNumberCalls) const {
  const int type = si_->getStateSpace()->getType();
  if (type == ob::STATE_SPACE_REAL_VECTOR || type == ob::STATE_SPACE_SE2 || type == ob::STATE_SPACE_SE3)
    return ob::PathLengthOptimizationObjective::allocInformedStateSampler(probDefn, maxNumberCalls);
  return std::make_shared<ob::RejectionInfSampler>(probDefn, maxNumberCalls);
}

}  // namespace foldkit::planners::detail
