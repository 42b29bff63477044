#pragma once
// What the plan spaces share (internals of planners/src/spaces/), and each space's factory: the
// registration of a new space is its factory here and its row in plan_space.cpp's table.
#include <functional>
#include <memory>
#include <vector>

#include <ompl/base/State.h>
#include <ompl/geometric/PathGeometric.h>

#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/planners/plan.hpp"
#include "foldkit/planners/plan_setup.hpp"
#include "foldkit/planners/plan_space.hpp"
#include "foldkit/statespaces/closure_constraint.hpp"

namespace foldkit::planners::spaces {

// setup.si on setup.space (setup.reader set first), with the motion validator of every space but
// the constrained ones (those bring their own).
void use_space(PlanSetup& setup, const PlanOptions& options);

// Takes the next state of a path (states_along's, in order).
using Emit = std::function<void(geometry::FoldState)>;

// The states strictly between `a` and `b` on a space's own motion from one to the other, at most
// `step` apart per crease where the space can tell, given in order to `out`; `tmp` is scratch.
using Motion = std::function<void(const ompl::base::State* a, const ompl::base::State* b, double step, ompl::base::State* tmp,
                                  const Emit& out)>;

// The path's states with `motion` between each pair of neighbours; `sink` (when set) gets each as
// soon as it is computed.
std::vector<geometry::FoldState> states_along(const PlanSetup& setup, const ompl::geometric::PathGeometric& path, double step,
                                              const Motion& motion, const PlanSpace::StateSink& sink);

// Each takes its name from plan_space.cpp's table.
std::shared_ptr<PlanSpace> single_vertex_plan_space(const char* name);
std::shared_ptr<PlanSpace> driving_plan_space(const char* name);
std::shared_ptr<PlanSpace> constrained_plan_space(const char* name, statespaces::ConstrainedKind kind);

}  // namespace foldkit::planners::spaces
