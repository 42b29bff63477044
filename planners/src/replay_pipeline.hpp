#pragma once
// The replay of a plan on another thread while its waypoints are computed: internals of plan.cpp
// and plan_finish.cpp.
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/planners/plan.hpp"
#include "foldkit/planners/plan_setup.hpp"
#include "foldkit/simulation/simulate.hpp"

namespace foldkit::planners::detail {

// Starts the replay's thread: a thread running `body`, or an exception (std::system_error when
// the system gives no thread) with `body` not run. The pipeline's own starts a std::thread; a
// caller may wrap `body` (to lower the thread's priority, say); tests pass one that fails.
using ThreadStarter = std::function<std::thread(std::function<void()> body)>;

// Replays the events of a plan's waypoints (geometry::path_event, as plan_sequence makes them) as
// the waypoints come, on a thread of its own, so the replay of the early events overlaps the
// continuation of the later ones. The report is the one simulate() gives the whole sequence: the
// same events in the same order through simulation::SequenceReplay, whatever the threads' timing.
// Active only where plan_sequence is path_sequence (no start sequence), the plan is replayed and
// its thread could be started; inactive, it takes nothing and finish_plan replays the sequence
// itself. Its members are called one at a time, each call done before the next begins (one
// thread, or a pushing thread joined before finish()); the replay's thread is its own.
class ReplayPipeline {
 public:
  // A pipeline for the plan of `setup` with `options` (both must outlive it). Its thread comes
  // from `start` (empty: a std::thread); when that throws std::system_error or gives no thread
  // (not joinable), the pipeline is inactive instead: a plan does not fail for want of a second
  // thread. Other exceptions of `start` pass through.
  ReplayPipeline(const PlanSetup& setup, const PlanOptions& options, const ThreadStarter& start = {});
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
  // The report of `sequence`: waits for the replay of every event pushed and returns its report
  // when those events are exactly `sequence`'s (same count and order; each with the same number,
  // and folds with the same joint ids, lines, and angles and speeds bit for bit), so that it is
  // simulate()'s of `sequence`. Otherwise nothing, the replay cancelled unfinished: the caller
  // replays `sequence` itself. Rethrows what the replay threw (simulation::SequenceError) for
  // those events. Nothing when inactive, cancelled or finished before.
  std::optional<simulation::SimulationReport> finish(const geometry::FoldSequence& sequence);

 private:
  void run();

  const PlanSetup& setup_;
  const PlanOptions& options_;
  bool active_ = false;
  geometry::FoldState at_;  // the state the next event starts from
  std::size_t events_ = 0;

  std::mutex mutex_;
  std::condition_variable ready_;
  // Every event pushed, kept until finish() has compared them with the sequence. A deque, so that
  // the replay thread may read an event outside the lock while push() appends (push_back keeps
  // references to the elements valid); only push(), cancel() and finish() change it, never while
  // the replay thread runs, except push()'s append (under the lock).
  std::deque<geometry::FoldEvent> pushed_;
  bool closed_ = false, cancelled_ = false;
  std::optional<simulation::SimulationReport> report_;
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace foldkit::planners::detail
