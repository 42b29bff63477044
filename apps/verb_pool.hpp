#pragma once
// The gate `foldkit serve` puts in front of its verbs: at most `workers` run at once, at most
// `queue` more wait for a turn (first come, first served), and any request beyond that is refused
// at once, so that a burst of clients gets answers instead of a 503 each (docs/SERVE.md,
// *Workers and the queue*).
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <mutex>

namespace foldkit::apps {

/// The default number of verbs `foldkit serve` runs at once: one per core
/// (std::thread::hardware_concurrency), at least 1.
std::size_t default_verb_workers();

/// A counting gate for the verbs of `foldkit serve`: `workers` slots, and a queue of at most
/// `queue` requests waiting for one, granted in the order they arrived.
///
/// Each verb runs as a child process that the request's HTTP thread waits on; the gate bounds how
/// many such processes share the machine's cores, and how many requests wait for them, so that a
/// burst beyond both is refused (503) rather than piling up without bound.
class VerbPool {
 public:
  /// The clock deadlines are given on.
  using Clock = std::chrono::steady_clock;

  /// How acquire() ended.
  enum class Grant {
    Granted,         ///< the caller holds a slot and must release() it
    QueueFull,       ///< every slot is held and the queue is full: refused at once
    DeadlinePassed,  ///< the deadline came (or had come) before a slot was free: not started
  };

  /// A gate of `workers` slots (at least 1; std::invalid_argument otherwise) and a queue of at
  /// most `queue` waiting callers (0: none wait, a caller finding every slot held is refused).
  VerbPool(std::size_t workers, std::size_t queue);

  VerbPool(const VerbPool&) = delete;
  VerbPool& operator=(const VerbPool&) = delete;

  /// Takes a slot: at once when one is free and nobody waits, else after waiting in the queue
  /// for the callers that arrived earlier. Refuses at once when the queue is full, and gives up
  /// at `deadline`; a deadline already past is refused even when a slot is free.
  Grant acquire(Clock::time_point deadline);

  /// Gives back a slot acquire() granted, and wakes the first waiting caller. `held`: how long
  /// the slot was held, for retry_after_seconds() (zero: not measured).
  void release(Clock::duration held = Clock::duration::zero());

  /// Slots: verbs that may run at once.
  std::size_t workers() const { return workers_; }
  /// How many callers may wait for a slot at most.
  std::size_t queue() const { return queue_; }
  /// Slots held now.
  std::size_t running() const;
  /// Callers waiting now.
  std::size_t waiting() const;

  /// Whole seconds after which a refused caller may find room (the Retry-After of a 503): the
  /// recent mean time a slot is held, divided among the slots, at least 1.
  long retry_after_seconds() const;

  /// A granted slot, released when it goes.
  class Slot {
   public:
    /// Holds the slot `pool` granted.
    explicit Slot(VerbPool& pool) : pool_(&pool), start_(Clock::now()) {}
    Slot(const Slot&) = delete;
    Slot& operator=(const Slot&) = delete;
    ~Slot() { pool_->release(Clock::now() - start_); }

   private:
    VerbPool* pool_;
    Clock::time_point start_;
  };

 private:
  bool first_in_line(std::uint64_t ticket) const;  // with mutex_ held

  const std::size_t workers_;
  const std::size_t queue_;
  mutable std::mutex mutex_;
  std::condition_variable turn_;           // a slot was released or a waiter left the line
  std::size_t running_ = 0;                // slots held
  std::deque<std::uint64_t> line_;         // tickets of the waiting callers, oldest first
  std::uint64_t next_ticket_ = 0;
  double mean_hold_ = 1.0;                 // seconds a slot is held, recent mean (starts at 1 s)
};

}  // namespace foldkit::apps
