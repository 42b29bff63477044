#include "verb_pool.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <thread>

namespace foldkit::apps {

std::size_t default_verb_workers() { return std::max(1u, std::thread::hardware_concurrency()); }

VerbPool::VerbPool(std::size_t workers, std::size_t queue) : workers_(workers), queue_(queue) {
  if (workers == 0) throw std::invalid_argument("a verb pool needs at least one worker");
}

bool VerbPool::first_in_line(std::uint64_t ticket) const { return running_ < workers_ && line_.front() == ticket; }

VerbPool::Grant VerbPool::acquire(Clock::time_point deadline) {
  std::unique_lock<std::mutex> lock(mutex_);
  // Past its time limit a verb would only be killed: it is not started.
  if (Clock::now() >= deadline) return Grant::DeadlinePassed;
  // A free slot goes to a newcomer only when nobody waits: the line is served in order.
  if (running_ < workers_ && line_.empty()) {
    ++running_;
    return Grant::Granted;
  }
  if (line_.size() >= queue_) return Grant::QueueFull;
  const std::uint64_t ticket = next_ticket_++;
  line_.push_back(ticket);
  const bool turn = turn_.wait_until(lock, deadline, [&] { return first_in_line(ticket); }) && Clock::now() < deadline;
  line_.erase(std::find(line_.begin(), line_.end(), ticket));
  // Whether this caller leaves with a slot or without, the one behind it may now be first with a
  // free slot (several slots may be free after a burst of releases).
  turn_.notify_all();
  if (!turn) return Grant::DeadlinePassed;
  ++running_;
  return Grant::Granted;
}

void VerbPool::release(Clock::duration held) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (running_ > 0) --running_;
    // A recent mean (the last ten or so), so that Retry-After follows the verbs being sent now.
    if (held > Clock::duration::zero()) mean_hold_ = 0.8 * mean_hold_ + 0.2 * std::chrono::duration<double>(held).count();
  }
  // Every waiter wakes and checks whether it is first in line: a condition variable cannot wake
  // one chosen thread, and the line is short (at most `queue`).
  turn_.notify_all();
}

std::size_t VerbPool::running() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return running_;
}

std::size_t VerbPool::waiting() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return line_.size();
}

long VerbPool::retry_after_seconds() const {
  std::lock_guard<std::mutex> lock(mutex_);
  // A full queue moves by one place each time a slot is released: about every mean_hold_ / workers_.
  const double seconds = std::ceil(mean_hold_ / static_cast<double>(workers_));
  return static_cast<long>(std::clamp(seconds, 1.0, 3600.0));
}

}  // namespace foldkit::apps
