#include "path_length.hpp"

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
  return std::make_shared<ob::RejectionInfSampler>(probDefn, maxNumberCalls);
}

}  // namespace foldkit::planners::detail
