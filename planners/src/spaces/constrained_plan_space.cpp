// OMPL's Projected, Atlas and TangentBundle spaces on the closure constraint, in a plan.
#include <memory>

#include <ompl/base/spaces/constraint/AtlasStateSpace.h>

#include "foldkit/geometry/mobility.hpp"
#include "space_common.hpp"

namespace foldkit::planners::spaces {

namespace {

namespace ob = ompl::base;
using geometry::FoldState;

class ConstrainedPlanSpace : public PlanSpace {
 public:
  ConstrainedPlanSpace(const char* name, statespaces::ConstrainedKind kind) : PlanSpace(name), kind_(kind) {}

  // The constraint's codimension: at a singular start (flat) the Jacobian loses rank, charts
  // cannot be anchored and projections may flip branches, so the plan starts from a nearby
  // regular state instead. With PlanOptions::search_margin the ambient box the sampler draws
  // from is that of start and goal, widened.
  Eigen::Index lead_in_rank(const PlanSetup& setup, const PlanOptions& options, const statespaces::AngleBounds& bounds) override {
    const FoldState& start = setup.start;
    statespaces::AngleBounds box = bounds;
    if (options.search_margin >= 0.0) {
      box.lower = box.lower.array().max(start.angles.cwiseMin(setup.goal.angles).array() - options.search_margin).matrix();
      box.upper = box.upper.array().min(start.angles.cwiseMax(setup.goal.angles).array() + options.search_margin).matrix();
    }
    constrained_ = statespaces::make_constrained(*setup.pattern, setup.goal, kind_, box, options.numerical_jacobian, 2.5 * options.resolution);
    const auto rank = static_cast<Eigen::Index>(constrained_.constraint->getCoDimension());
    return geometry::mobility(*setup.system, start).rank < rank ? rank : 0;
  }

  void build(PlanSetup& setup, const PlanOptions&, const statespaces::AngleBounds&) override {
    setup.space = constrained_.space;
    setup.si = constrained_.si;
    setup.reader = statespaces::constrained_reader();
  }

  bool write(const FoldState& state, ob::State* out) const override {
    out->as<ob::ConstrainedStateSpace::StateType>()->copy(state.angles);
    return true;
  }

  void anchor(ob::State* start, ob::State* goal) const override {
    if (kind_ == statespaces::ConstrainedKind::Projected) return;
    auto atlas = std::static_pointer_cast<ob::AtlasStateSpace>(constrained_.space);
    atlas->anchorChart(start);
    atlas->anchorChart(goal);
  }

 private:
  statespaces::ConstrainedKind kind_;
  statespaces::ConstrainedSetup constrained_;
};

}  // namespace

std::shared_ptr<PlanSpace> constrained_plan_space(const char* name, statespaces::ConstrainedKind kind) {
  return std::make_shared<ConstrainedPlanSpace>(name, kind);
}

}  // namespace foldkit::planners::spaces
