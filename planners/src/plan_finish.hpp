#pragma once
// The end of plan() (a found path checked, written as CMML and replayed) and its way through flat
// when the driving space finds no direct path: internals of plan.cpp.
#include <string>
#include <vector>

#include "foldkit/planners/plan.hpp"
#include "foldkit/planners/plan_setup.hpp"

namespace foldkit::planners::detail {

// Closure along `waypoints`, the CMML and the simulator's replay, into `result`; its status is
// Success with the message `success` when all pass.
PlanResult& finish_plan(const PlanRequest& req, const PlanSetup& setup, std::vector<geometry::FoldState> waypoints,
                        PlanResult& result, const std::string& success);

// Start → flat → goal as two plans from flat (PlanRequest::fallback in the driving space), in the
// time `result.time` leaves of req.time; `why` says why the direct way was given up.
PlanResult& plan_via_flat(const PlanRequest& req, const PlanSetup& setup, PlanResult& result, const std::string& why);

}  // namespace foldkit::planners::detail
