#include "replay_pipeline.hpp"

#include <cstdint>
#include <cstring>
#include <system_error>
#include <utility>

namespace foldkit::planners::detail {
namespace {

// Bit for bit, not ==: 0.0 and -0.0 are equal numbers but may replay differently (signed results).
bool same_bits(double a, double b) {
  std::uint64_t x = 0, y = 0;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return x == y;
}

// Everything of an event that the simulator reads (the line goes into its SequenceError).
bool same_event(const geometry::FoldEvent& a, const geometry::FoldEvent& b) {
  if (a.number != b.number || a.folds.size() != b.folds.size()) return false;
  for (std::size_t i = 0; i < a.folds.size(); ++i) {
    const geometry::FoldCommand &f = a.folds[i], &g = b.folds[i];
    if (f.joint_id != g.joint_id || f.line != g.line || !same_bits(f.angle, g.angle) || !same_bits(f.speed, g.speed))
      return false;
  }
  return true;
}

}  // namespace

ReplayPipeline::ReplayPipeline(const PlanSetup& setup, const PlanOptions& options, const ThreadStarter& start)
    : setup_(setup), options_(options), active_(options.replay && options.start_sequence.events.empty()) {
  if (!active_) return;
  at_ = geometry::FoldState::flat(*setup.pattern);
  std::function<void()> body = [this] { run(); };
  try {
    thread_ = start ? start(std::move(body)) : std::thread(std::move(body));
  } catch (const std::system_error&) {
    // No thread to be had (resource limits): the replay after the waypoints, as without a pipeline.
  }
  active_ = thread_.joinable();  // a starter that gave no thread gave no replay either
}

ReplayPipeline::~ReplayPipeline() { cancel(); }

void ReplayPipeline::push(const geometry::FoldState& waypoint) {
  if (!active_) return;
  auto event = geometry::path_event(*setup_.pattern, at_, waypoint, options_.speed, static_cast<int>(events_) + 1);
  if (!event) return;
  at_ = waypoint;
  ++events_;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    pushed_.push_back(std::move(*event));
  }
  ready_.notify_one();
}

void ReplayPipeline::cancel() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    cancelled_ = closed_ = true;
  }
  ready_.notify_one();
  // A replay that falls back on simulate() must not overlap this one's progress calls.
  if (thread_.joinable()) thread_.join();
  pushed_ = {};  // nothing reads them any more
}

std::optional<simulation::SimulationReport> ReplayPipeline::finish(const geometry::FoldSequence& sequence) {
  if (!active_) return std::nullopt;
  // The replay thread only reads pushed_, and no push() runs during finish(): no lock needed.
  bool same = pushed_.size() == sequence.events.size();
  for (std::size_t i = 0; same && i < pushed_.size(); ++i) same = same_event(pushed_[i], sequence.events[i]);
  if (!same) {
    // A report of other events is no report of `sequence`, however close they are.
    cancel();
    return std::nullopt;
  }
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    closed_ = true;
  }
  ready_.notify_one();
  if (thread_.joinable()) thread_.join();
  pushed_ = {};
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
  std::optional<simulation::SimulationReport> report = std::move(report_);
  report_.reset();  // a second finish() has nothing to give
  return report;
}

// The replay thread: events in the order pushed, until closed (the report) or cancelled (none).
// The options are finish_plan's: collisions and progress as the sequential replay has them.
void ReplayPipeline::run() {
  try {
    simulation::SimulationOptions so;
    so.collisions = options_.collisions;
    so.progress = options_.progress;
    simulation::SequenceReplay replay(*setup_.pattern, so);
    std::size_t done = 0;
    for (;;) {
      const geometry::FoldEvent* event = nullptr;  // stays valid while push() appends (a deque)
      std::size_t known = 0;  // the whole is not known yet: the progress counts the events pushed so far
      {
        std::unique_lock<std::mutex> lock(mutex_);
        ready_.wait(lock, [&] { return cancelled_ || closed_ || done < pushed_.size(); });
        if (cancelled_) return;
        if (done == pushed_.size()) break;  // closed, every event replayed
        event = &pushed_[done++];
        known = pushed_.size();
      }
      replay.add(*event, known);
    }
    report_ = replay.finish();
  } catch (...) {
    error_ = std::current_exception();
  }
}

}  // namespace foldkit::planners::detail
