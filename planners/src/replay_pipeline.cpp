#include "replay_pipeline.hpp"

#include <utility>

namespace foldkit::planners::detail {

ReplayPipeline::ReplayPipeline(const PlanSetup& setup, const PlanOptions& options)
    : setup_(setup), options_(options), active_(options.replay && options.start_sequence.events.empty()) {
  if (!active_) return;
  at_ = geometry::FoldState::flat(*setup.pattern);
  thread_ = std::thread([this] { run(); });
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
    queue_.push_back(std::move(*event));
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
}

std::optional<simulation::SimulationReport> ReplayPipeline::finish() {
  if (!active_) return std::nullopt;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    closed_ = true;
  }
  ready_.notify_one();
  if (thread_.joinable()) thread_.join();
  if (error_) std::rethrow_exception(error_);
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
      geometry::FoldEvent event;
      std::size_t known = 0;  // the whole is not known yet: the progress counts the events pushed so far
      {
        std::unique_lock<std::mutex> lock(mutex_);
        ready_.wait(lock, [&] { return cancelled_ || closed_ || !queue_.empty(); });
        if (cancelled_) return;
        if (queue_.empty()) break;  // closed, every event replayed
        event = std::move(queue_.front());
        queue_.pop_front();
        known = ++done + queue_.size();
      }
      replay.add(event, known);
    }
    report_ = replay.finish();
  } catch (...) {
    error_ = std::current_exception();
  }
}

}  // namespace foldkit::planners::detail
