#pragma once
// The straight plan, computed while the planner searches (issue 35): in a space of straight
// paths (PlanSpace::straight_paths) whose start continues to the goal (PlanSetup::continues_to_goal),
// the path a planner finds is most often already shortest, and plan() then replaces it by its two
// ends (simplify); the waypoints and the replay of that two-state path do not depend on the
// planner. They are computed on threads of their own from the moment the setup is made, while the
// planner runs on the caller's: on a 2-core machine the plan's wall time is then about its setup,
// its planner time and what is left of the replay, instead of setup + planner + waypoints +
// replay (Miura 40×40: docs/PLANNING.md). When the planner's path is another, or none, this one is
// dropped: cancelled, its threads joined, nothing of it in the result.
#include <atomic>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <ompl/geometric/PathGeometric.h>

#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/planners/plan.hpp"
#include "foldkit/planners/plan_setup.hpp"
#include "replay_pipeline.hpp"

namespace foldkit::planners::detail {

class StraightPlan {
 public:
  // Whether plan() follows the straight path of `setup` with `options` ahead of its planner:
  // the space has straight paths and the start continues to the goal, the path would be
  // simplified by length (the default objective, no cost threshold) and replayed, with no start
  // sequence and no experience database (`experience`), and the plan is not made through flat
  // (`via_flat`).
  static bool wanted(const PlanSetup& setup, const PlanOptions& options, bool via_flat, bool experience);

  // Starts the waypoints of the path from setup.prefix.back() to setup.goal (as plan() writes
  // them into the planner's start and goal) on a thread of its own, each pushed into a
  // ReplayPipeline as it comes. `setup` and `options` must outlive this. The threads run at a
  // lower priority than the caller's (where the system allows it), so that on a busy machine the
  // planner keeps its core. Both threads come from `start` (empty: std::thread); when it throws
  // std::system_error, the straight plan does not run (matches() is false) and the plan makes its
  // waypoints and replay itself.
  StraightPlan(const PlanSetup& setup, const PlanOptions& options, const simulation::ThreadStarter& start = {});
  // Cancels what is still running and joins its threads (the waypoints' at the continuation's
  // next step).
  ~StraightPlan();
  StraightPlan(const StraightPlan&) = delete;
  StraightPlan& operator=(const StraightPlan&) = delete;

  // Whether `path` is this plan's: two states whose fold angles are, bit for bit, the ones it
  // started from and ends at (so its waypoints are those path_waypoints() gives `path`). False
  // when it could not start (its ends not states of the space, or no second thread).
  bool matches(const ompl::geometric::PathGeometric& path) const;
  // Waits for the waypoints and returns them (path_waypoints()'s, to the goal), or nothing when
  // they were not made here — the path jumps, its continuation falls short of the goal (the
  // halving that follows is left to the caller, see run()), or computing them threw: the caller
  // then computes them itself, which gives the same outcome. Back to the caller's priority from
  // here on. Once only.
  std::optional<std::vector<geometry::FoldState>> waypoints();
  // The replay of the waypoints, for finish_plan (which checks its events against the plan's).
  ReplayPipeline& pipeline() { return pipeline_; }

 private:
  void run();

  const PlanSetup& setup_;
  const PlanOptions& options_;
  ompl::geometric::PathGeometric path_;
  geometry::FoldState first_, last_;  // path_'s ends as setup.reader reads them
  // The threads' priority: lowered as each starts unless the plan was accepted before.
  void lower_priority();
  void forget_priority();
  void restore_priority();
  int nice_ = 0;  // the caller's
  std::mutex nice_mutex_;
  bool accepted_ = false;
  std::vector<int> lowered_;  // thread ids
  ReplayPipeline pipeline_;   // after what its thread's starter uses
  std::atomic<bool> cancelled_{false};
  bool ends_ok_ = false;  // set by the constructor, read by matches(); the thread never reads it
  std::optional<std::vector<geometry::FoldState>> dense_;  // the thread's until joined
  std::thread thread_;  // last: started once everything it uses is
};

}  // namespace foldkit::planners::detail
