#pragma once
// The replay of a plan on another thread while its waypoints are computed: internals of plan.cpp
// and plan_finish.cpp, over simulation::PipelinedReplay.
#include <cstddef>
#include <optional>

#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/planners/plan.hpp"
#include "foldkit/planners/plan_setup.hpp"
#include "foldkit/simulation/pipelined_replay.hpp"
#include "foldkit/simulation/simulate.hpp"

namespace foldkit::planners::detail {

using simulation::ThreadStarter;

// The replay a plan's options ask for (collisions and progress as they say; simulate()'s
// defaults otherwise), piped or not.
simulation::SimulationOptions replay_options(const PlanOptions& options);

// Replays the events of a plan's waypoints (geometry::path_event, as plan_sequence makes them) as
// the waypoints come, on a thread of its own (simulation::PipelinedReplay), so the replay of the
// early events overlaps the continuation of the later ones; its report is simulate()'s of the
// whole sequence. Active only where plan_sequence is path_sequence (no start sequence), the plan
// is replayed and its thread could be started; inactive, it takes nothing and finish_plan
// replays the sequence itself. Its members are called one at a time, each call done before the
// next begins (one thread, or a pushing thread joined before finish()).
class ReplayPipeline {
 public:
  // A pipeline for the plan of `setup` with `options` (both must outlive it): finish_plan's
  // replay (collisions and progress as the options say). Its thread comes from `start` (empty:
  // a std::thread); when that throws std::system_error or gives no thread, the pipeline is
  // inactive instead: a plan does not fail for want of a second thread.
  ReplayPipeline(const PlanSetup& setup, const PlanOptions& options, const ThreadStarter& start = {});

  // Whether it replays (else push() does nothing and finish() has no report).
  bool active() const { return replay_ && replay_->active(); }
  // The next waypoint; its event, if any joint moves, goes to the replay.
  void push(const geometry::FoldState& waypoint) {
    if (active()) replay_->push(waypoint);
  }
  // How many events were handed to the replay.
  std::size_t events() const { return replay_ ? replay_->events() : 0; }
  // The replay is not wanted: it stops at its next event, and this waits for its thread.
  void cancel() {
    if (replay_) replay_->cancel();
  }
  // simulation::PipelinedReplay::finish: the report of `sequence` when the events pushed are
  // its events, else nothing (the replay cancelled; the caller replays `sequence`).
  std::optional<simulation::SimulationReport> finish(const geometry::FoldSequence& sequence) {
    return active() ? replay_->finish(sequence) : std::nullopt;
  }
  // simulate()'s report of `sequence` with replay_options(): the pipeline's when it replayed
  // exactly its events, else `sequence` replayed here (simulation::PipelinedReplay::report).
  simulation::SimulationReport report(const geometry::FoldSequence& sequence) {
    return replay_ ? replay_->report(sequence) : simulation::simulate(*pattern_, sequence, options_);
  }

 private:
  const geometry::CreasePattern* pattern_;
  simulation::SimulationOptions options_;
  std::optional<simulation::PipelinedReplay> replay_;
};

}  // namespace foldkit::planners::detail
