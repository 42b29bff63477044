#include "plan_finish.hpp"

#include <algorithm>
#include <future>
#include <optional>
#include <stdexcept>
#include <utility>

#include "foldkit/planners/objectives.hpp"
#include "foldkit/simulation/simulate.hpp"
#include "replay_pipeline.hpp"

namespace foldkit::planners::detail {

using geometry::FoldState;

// Every path passes these, whichever way it was found.
PlanResult& finish_plan(const PlanSetup& setup, const PlanOptions& options, std::vector<FoldState> waypoints, PlanResult& result,
                        const std::string& success, ReplayPipeline* pipeline) {
  result.waypoints = std::move(waypoints);
  result.path_length = 0.0;
  for (std::size_t i = 0; i < result.waypoints.size(); ++i) {
    result.max_closure_error = std::max(result.max_closure_error, setup.system->max_error(result.waypoints[i]));
    if (i > 0) result.path_length += (result.waypoints[i].angles - result.waypoints[i - 1].angles).norm();
  }
  result.cost = path_cost(parse_objective(options.objective), *setup.pattern, result.waypoints);
  if (result.max_closure_error > 1e-6) {
    if (pipeline) pipeline->cancel();
    result.status = {geometry::StatusCode::ClosureViolated,
                     "the planned path is not closed (error " + std::to_string(result.max_closure_error) + " rad)"};
    return result;
  }
  result.sequence = plan_sequence(setup, options, result.waypoints);
  simulation::ReaderWait wait;
  if (options.sequence_ready) wait.reading = options.sequence_ready(result.sequence);
  if (options.replay) {
    // The pipeline replayed events as the waypoints came; its report is the plan's only when those
    // events are the sequence's (by their digest), else the sequence is replayed here.
    result.replay = pipeline ? pipeline->report(result.sequence)
                             : simulation::simulate(*setup.pattern, result.sequence, replay_options(options));
    result.max_closure_error = std::max(result.max_closure_error, result.replay->max_closure_error);
    if (!result.replay->status) {
      result.status = {result.replay->status.code, "the simulator rejects the plan: " + result.replay->status.message};
      return result;
    }
  }
  result.status = {geometry::StatusCode::Success, success};
  return result;
}

// Start → flat → goal: a plan from flat to the start, reversed, then one from flat to the goal,
// each in a driving space of its own, with the time left split between them. Every branch of a
// sheet's closed states passes through flat, so this joins ends that no motion of one driving
// space joins (another branch, or sheets of a multi-DOF pattern that meet only at singular
// states). `why`: why the direct way was given up.
PlanResult& plan_via_flat(const PlanSetup& setup, const PlanOptions& options, PlanResult& result, const std::string& why) {
  // A leg's refusal (a singular end, say) is this plan's failure, not an input error of its own
  // goal: the legs' ends are the start and goal already checked.
  const auto leg_plan = [&](const FoldState& goal, const PlanOptions& leg) {
    try {
      return plan(*setup.pattern, goal, leg);
    } catch (const std::invalid_argument& e) {
      PlanResult failed;
      failed.status = {geometry::StatusCode::NoProgress, e.what()};
      return failed;
    }
  };
  PlanOptions leg = options;
  leg.start.reset();
  leg.start_sequence = {};
  leg.experience.reset();  // each leg is another query (from flat); the way through flat is not stored
  leg.replay = false;
  leg.progress = nullptr;
  leg.sequence_ready = nullptr;  // a leg's sequence is not the plan's
  const double left = std::max(0.0, options.time - result.seconds);
  leg.time = std::max(1e-3, 0.5 * left);
  // Out of time stays out of time; any other failure of a leg is no progress.
  const auto failed = [&](const PlanResult& r, const char* end) -> PlanResult& {
    result.status = {r.status.code == geometry::StatusCode::LimitReached ? geometry::StatusCode::LimitReached
                                                                          : geometry::StatusCode::NoProgress,
                     "no plan: " + why + "; via flat: no plan from flat to the " + end + " (" + r.status.message + ")"};
    return result;
  };
  const PlanResult out = leg_plan(setup.start, leg);
  result.seconds += out.seconds;
  if (!out.status) return failed(out, "start");
  leg.time = std::max(1e-3, options.time - result.seconds);
  const PlanResult in = leg_plan(setup.goal, leg);
  result.seconds += in.seconds;
  if (!in.status) return failed(in, "goal");
  std::vector<FoldState> waypoints(out.waypoints.rbegin(), out.waypoints.rend());
  waypoints.insert(waypoints.end(), in.waypoints.begin() + 1, in.waypoints.end());
  result.fallback = result.via_flat = true;
  return finish_plan(setup, options, std::move(waypoints), result, "solved via flat (" + why + ")");
}

}  // namespace foldkit::planners::detail
