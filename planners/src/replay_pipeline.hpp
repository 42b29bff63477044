#pragma once
// The replay of a plan on another thread while its waypoints are computed: internals of plan.cpp
// and plan_finish.cpp.
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/planners/plan.hpp"
#include "foldkit/planners/plan_setup.hpp"
#include "foldkit/simulation/simulate.hpp"

namespace foldkit::planners::detail {

// Replays the events of a plan's waypoints (geometry::path_event, as plan_sequence makes them) as
// the waypoints come, on a thread of its own, so the replay of the early events overlaps the
// continuation of the later ones. The report is the one simulate() gives the whole sequence: the
// same events in the same order through simulation::SequenceReplay, whatever the threads' timing.
// Active only where plan_sequence is path_sequence (no start sequence) and the plan is replayed;
// inactive, it takes nothing and finish_plan replays the sequence itself.
class ReplayPipeline {
 public:
  // A pipeline for the plan of `setup` with `options` (both must outlive it).
  ReplayPipeline(const PlanSetup& setup, const PlanOptions& options);
  // Stops the replay (cancel()) and waits for its thread.
  ~ReplayPipeline();
  ReplayPipeline(const ReplayPipeline&) = delete;
  ReplayPipeline& operator=(const ReplayPipeline&) = delete;

  // Whether it replays (else push() does nothing and finish() has no report).
  bool active() const { return active_; }
  // The next waypoint; its event, if any joint moves, goes to the replay.
  void push(const geometry::FoldState& waypoint);
  // How many events were handed to the replay.
  std::size_t events() const { return events_; }
  // The replay is not wanted: it stops at its next event, and this waits for its thread, so that
  // nothing (its progress calls) runs on it once cancel() returns.
  void cancel();
  // Waits for the replay of every event pushed and returns its report; rethrows what the replay
  // threw (simulation::SequenceError). Nothing when inactive or cancelled.
  std::optional<simulation::SimulationReport> finish();

 private:
  void run();

  const PlanSetup& setup_;
  const PlanOptions& options_;
  bool active_ = false;
  geometry::FoldState at_;  // the state the next event starts from
  std::size_t events_ = 0;

  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<geometry::FoldEvent> queue_;  // pushed, not yet replayed
  bool closed_ = false, cancelled_ = false;
  std::optional<simulation::SimulationReport> report_;
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace foldkit::planners::detail
