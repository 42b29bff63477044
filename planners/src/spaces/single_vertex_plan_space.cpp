// The exact single-vertex space in a plan: n − 3 active angles, the rest in closed form; the
// Carpenter fallback (Carpenter's rule on the sphere) when sampling finds nothing.
#include <algorithm>
#include <cmath>
#include <memory>

#include <ompl/base/ScopedState.h>

#include "foldkit/statespaces/single_vertex_space.hpp"
#include "space_common.hpp"

namespace foldkit::planners::spaces {

namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;
using geometry::FoldState;

class SingleVertexPlanSpace : public PlanSpace {
 public:
  using PlanSpace::PlanSpace;

  // The closed form cannot hold some singular states (a flat vertex whose passive axes line up):
  // such a start is left along a short closed segment to full rank (3) first.
  Eigen::Index lead_in_rank(const PlanSetup& setup, const PlanOptions&, const statespaces::AngleBounds& bounds) override {
    auto chain = std::make_shared<statespaces::SingleVertexChain>(*setup.pattern);
    space_ = std::make_shared<statespaces::SingleVertexStateSpace>(chain, bounds);
    ob::ScopedState<> probe(space_);
    return write(setup.start, probe.get()) ? 0 : 3;
  }

  void build(PlanSetup& setup, const PlanOptions& options, const statespaces::AngleBounds&) override {
    setup.space = space_;
    setup.reader = statespaces::single_vertex_reader(space_);
    use_space(setup, options);
  }

  bool write(const FoldState& state, ob::State* out) const override { return space_->from_fold_state(state, out); }

  // The motion is linear in the active angles: evenly spaced states at most `step` apart in
  // every crease.
  std::vector<FoldState> path_states(const PlanSetup& setup, og::PathGeometric path, double step, const StateSink& sink,
                                     const Stop&) const override {
    return states_along(setup, path, step,
                        [&](const ob::State* a, const ob::State* b, double s, ob::State* tmp, const Emit& out) {
                          const FoldState fa = space_->to_fold_state(a), fb = space_->to_fold_state(b);
                          const int parts = std::max(1, static_cast<int>(std::ceil((fb.angles - fa.angles).cwiseAbs().maxCoeff() / s)));
                          for (int k = 1; k < parts; ++k) {
                            space_->interpolate(a, b, static_cast<double>(k) / parts, tmp);
                            FoldState f;
                            if (!setup.reader(tmp, f)) break;
                            out(std::move(f));
                          }
                        },
                        sink);
  }

  Fallback fallback() const override { return Fallback::Carpenter; }

 private:
  std::shared_ptr<statespaces::SingleVertexStateSpace> space_;
};

}  // namespace

std::shared_ptr<PlanSpace> single_vertex_plan_space(const char* name) { return std::make_shared<SingleVertexPlanSpace>(name); }

}  // namespace foldkit::planners::spaces
