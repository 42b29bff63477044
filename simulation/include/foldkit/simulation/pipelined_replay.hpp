#pragma once
/// @file
/// simulate() of a path of fold states that is still being computed: each state's event is
/// replayed on a thread of its own as soon as the state is known, so that a folder's or planner's
/// replay overlaps its own work (issue 35: `foldkit fold` and `foldkit plan`).
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <future>
#include <mutex>
#include <optional>
#include <thread>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/simulation/simulate.hpp"

namespace foldkit::simulation {

/// Waits, as it goes, for whoever reads a sequence while its replay runs (`foldkit fold` and
/// `foldkit plan` write their CMML meanwhile), so that the reader is done before the sequence
/// moves on, on every way out, exceptions included.
struct ReaderWait {
  std::future<void> reading;  ///< the reader's; may be empty (invalid)
  ~ReaderWait() {
    if (reading.valid()) reading.wait();
  }
};

/// Starts a replay's thread: a thread running `body`, or an exception (std::system_error when the
/// system gives no thread) with `body` not run. Empty: a plain std::thread.
using ThreadStarter = std::function<std::thread(std::function<void()> body)>;

/// The events of a path of fold states from the flat sheet (geometry::path_event of each state
/// from the last, as geometry::path_sequence makes them), replayed through SequenceReplay on a
/// thread of its own as the states are pushed. Its report is simulate()'s of the whole sequence:
/// the same events in the same order, whatever the threads' timing.
///
/// Its members are called one at a time, each call done before the next begins (one thread, or a
/// pushing thread joined before finish()). The options' progress is called from the replay's
/// thread. Inactive when no thread could be started: push() then takes nothing and finish() has
/// no report (the caller replays the sequence itself).
class PipelinedReplay {
 public:
  /// A replay of `pattern` (which must outlive it) with `options`, the events at `speed` (rad/s,
  /// as path_sequence's `max_speed`). Its thread comes from `start`; when that throws
  /// std::system_error or gives no thread, the replay is inactive instead. Other exceptions of
  /// `start` pass through. Options simulate() refuses (std::invalid_argument) are thrown by
  /// finish(), the replay being made on its thread.
  PipelinedReplay(const geometry::CreasePattern& pattern, const SimulationOptions& options, double speed,
                  const ThreadStarter& start = {});
  /// Stops the replay (cancel()) and waits for its thread.
  ~PipelinedReplay();
  PipelinedReplay(const PipelinedReplay&) = delete;
  PipelinedReplay& operator=(const PipelinedReplay&) = delete;

  /// Whether it replays.
  bool active() const { return active_; }
  /// The next state of the path; its event, if any joint moves, goes to the replay.
  /// @throws std::invalid_argument as path_event()
  void push(const geometry::FoldState& state);
  /// How many events were handed to the replay.
  std::size_t events() const { return events_; }
  /// The replay is not wanted: it stops at its next event, and this waits for its thread, so that
  /// nothing (its progress calls) runs on it once cancel() returns.
  void cancel();
  /// The report of `sequence`: waits for the replay of every event pushed and returns its report
  /// when those events are `sequence`'s — the same count, and the same 64-bit digest of their
  /// order, numbers, joint ids, lines, and angles' and speeds' bits (other events pass with
  /// probability about 2^-64; the events themselves are not kept) — so that it is simulate()'s of
  /// `sequence`. Otherwise nothing, the replay cancelled unfinished: the caller replays `sequence`
  /// itself. Rethrows what the replay threw (SequenceError) for those events. Nothing when
  /// inactive, cancelled or finished before.
  std::optional<SimulationReport> finish(const geometry::FoldSequence& sequence);
  /// simulate()'s report of `sequence` with this replay's options: finish()'s when it has one,
  /// else (inactive, other events, cancelled) `sequence` replayed here, on the caller's thread,
  /// once the replay's thread has ended (their progress calls never overlap).
  SimulationReport report(const geometry::FoldSequence& sequence);

 private:
  void run();

  const geometry::CreasePattern& pattern_;
  SimulationOptions options_;
  double speed_;
  bool active_ = false;
  geometry::FoldState at_;  // the state the next event starts from
  std::size_t events_ = 0;
  std::uint64_t digest_ = 0;  // of the events pushed, for finish() (the pushing thread's)

  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<geometry::FoldEvent> queue_;  // pushed, not yet replayed (under mutex_)
  bool closed_ = false, cancelled_ = false;
  bool dead_ = false;  // the replay threw: push() queues nothing more (under mutex_)
  std::optional<SimulationReport> report_;
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace foldkit::simulation
