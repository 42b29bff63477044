#pragma once
// The end of plan() (a found path checked, written as CMML and replayed) and its way through flat
// when the driving space finds no direct path: internals of plan.cpp.
#include <string>
#include <vector>

#include "foldkit/planners/plan.hpp"
#include "foldkit/planners/plan_setup.hpp"

namespace foldkit::planners::detail {

class ReplayPipeline;

// Closure along `waypoints`, the CMML and the simulator's replay, into `result`; its status is
// Success with the message `success` when all pass. With an active `pipeline` whose events are
// the sequence's (ReplayPipeline::report, by their digest), its replay is the plan's; else (none,
// inactive, or other events) the sequence is replayed here, and the pipeline is cancelled.
PlanResult& finish_plan(const PlanSetup& setup, const PlanOptions& options, std::vector<geometry::FoldState> waypoints,
                        PlanResult& result, const std::string& success, ReplayPipeline* pipeline = nullptr);

// Start → flat → goal as two plans from flat (PlanOptions::fallback in the driving space), in the
// time `result.seconds` leaves of options.time; `why` says why the direct way was given up.
PlanResult& plan_via_flat(const PlanSetup& setup, const PlanOptions& options, PlanResult& result, const std::string& why);

}  // namespace foldkit::planners::detail
