// The joint-angle box: the space of a pattern without a closed loop, where every state is closed.
#include <memory>

#include <ompl/base/spaces/RealVectorStateSpace.h>

#include "space_common.hpp"

namespace foldkit::planners {

namespace {

namespace ob = ompl::base;
using geometry::FoldState;

class JointPlanSpace : public PlanSpace {
 public:
  using PlanSpace::PlanSpace;

  Eigen::Index lead_in_rank(const PlanSetup&, const PlanOptions&, const statespaces::AngleBounds&) override { return 0; }

  void build(PlanSetup& setup, const PlanOptions& options, const statespaces::AngleBounds& bounds) override {
    const auto n = static_cast<Eigen::Index>(setup.pattern->joints().size());
    auto box = std::make_shared<ob::RealVectorStateSpace>(static_cast<unsigned int>(n));
    ob::RealVectorBounds b(static_cast<unsigned int>(n));
    for (Eigen::Index j = 0; j < n; ++j) {
      b.setLow(static_cast<unsigned int>(j), bounds.lower[j]);
      b.setHigh(static_cast<unsigned int>(j), bounds.upper[j]);
    }
    box->setBounds(b);
    setup.space = box;
    setup.reader = [n](const ob::State* s, FoldState& f) {
      f.angles = Eigen::Map<const Eigen::VectorXd>(s->as<ob::RealVectorStateSpace::StateType>()->values, n);
      return true;
    };
    spaces::use_space(setup, options);
  }

  bool write(const FoldState& state, ob::State* out) const override {
    auto* v = out->as<ob::RealVectorStateSpace::StateType>();
    for (Eigen::Index j = 0; j < state.angles.size(); ++j) v->values[j] = state.angles[j];
    return true;
  }
};

}  // namespace

std::shared_ptr<PlanSpace> make_joint_plan_space() { return std::make_shared<JointPlanSpace>("joint"); }

}  // namespace foldkit::planners
