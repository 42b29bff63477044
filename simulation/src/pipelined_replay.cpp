#include "foldkit/simulation/pipelined_replay.hpp"

#include <cstring>
#include <system_error>
#include <utility>

namespace foldkit::simulation {
namespace {

// A 64-bit digest of everything of an event that the simulator reads (the line goes into its
// SequenceError), the angles and speeds by their bits (0.0 and -0.0 may replay differently):
// splitmix64's finaliser over each word, chained. Two different event lists agree by chance with
// probability about 2^-64; keeping every pushed event to compare them exactly cost a copy of the
// plan's folds (86 MB at Miura 100 × 100).
std::uint64_t mix(std::uint64_t h, std::uint64_t word) {
  std::uint64_t z = h ^ (word + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2));
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

std::uint64_t bits(double x) {
  std::uint64_t b = 0;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

std::uint64_t digest(std::uint64_t h, const geometry::FoldEvent& e) {
  h = mix(h, static_cast<std::uint64_t>(static_cast<std::int64_t>(e.number)));
  h = mix(h, e.folds.size());
  for (const geometry::FoldCommand& f : e.folds) {
    h = mix(h, (static_cast<std::uint64_t>(static_cast<std::uint32_t>(f.joint_id)) << 32) | static_cast<std::uint32_t>(f.line));
    h = mix(h, bits(f.angle));
    h = mix(h, bits(f.speed));
  }
  return h;
}

}  // namespace

PipelinedReplay::PipelinedReplay(const geometry::CreasePattern& pattern, const SimulationOptions& options, double speed,
                                 const ThreadStarter& start)
    : pattern_(pattern), options_(options), speed_(speed), at_(geometry::FoldState::flat(pattern)) {
  std::function<void()> body = [this] { run(); };
  try {
    thread_ = start ? start(std::move(body)) : std::thread(std::move(body));
  } catch (const std::system_error&) {
    // No thread to be had (resource limits): the caller replays the sequence itself.
  }
  active_ = thread_.joinable();  // a starter that gave no thread gave no replay either
}

PipelinedReplay::~PipelinedReplay() { cancel(); }

void PipelinedReplay::push(const geometry::FoldState& state) {
  if (!active_) return;
  auto event = geometry::path_event(pattern_, at_, state, speed_, static_cast<int>(events_) + 1);
  if (!event) return;
  at_ = state;
  ++events_;
  digest_ = digest(digest_, *event);
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!dead_) queue_.push_back(std::move(*event));  // none would replay it
  }
  ready_.notify_one();
}

void PipelinedReplay::cancel() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    cancelled_ = closed_ = true;
  }
  ready_.notify_one();
  // A replay that falls back on simulate() must not overlap this one's progress calls.
  if (thread_.joinable()) thread_.join();
  queue_ = {};  // nothing reads them any more
}

std::optional<SimulationReport> PipelinedReplay::finish(const geometry::FoldSequence& sequence) {
  if (!active_) return std::nullopt;
  std::uint64_t expected = 0;
  for (const geometry::FoldEvent& e : sequence.events) expected = digest(expected, e);
  if (events_ != sequence.events.size() || expected != digest_) {
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
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
  std::optional<SimulationReport> report = std::move(report_);
  report_.reset();  // a second finish() has nothing to give
  return report;
}

SimulationReport PipelinedReplay::report(const geometry::FoldSequence& sequence) {
  if (std::optional<SimulationReport> replayed = finish(sequence)) return std::move(*replayed);
  cancel();
  return simulate(pattern_, sequence, options_);
}

// The replay thread: events in the order pushed, until closed (the report) or cancelled (none).
void PipelinedReplay::run() {
  try {
    SequenceReplay replay(pattern_, options_);
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
    const std::lock_guard<std::mutex> lock(mutex_);
    dead_ = true;
    queue_.clear();
  }
}

}  // namespace foldkit::simulation
