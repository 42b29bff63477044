// The gate in front of foldkit serve's verbs (apps/verb_pool.hpp): at most `workers` slots held,
// at most `queue` callers waiting, the rest refused at once, deadlines kept, first come first
// served. Oracles: counters of held slots and the pool's own counts, waited for by polling rather
// than by sleeping a guessed time.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "verb_pool.hpp"

namespace {

using foldkit::apps::VerbPool;
using Grant = VerbPool::Grant;
using namespace std::chrono_literals;

VerbPool::Clock::time_point far() { return VerbPool::Clock::now() + 60s; }

// Polls until `done` holds (at most 10 s, so that a broken pool fails instead of hanging).
template <class F>
bool eventually(F done) {
  for (int i = 0; i < 10000 && !done(); ++i) std::this_thread::sleep_for(1ms);
  return done();
}

TEST(ServeVerbPool, AFullQueueIsRefusedAtOnce) {
  VerbPool pool(2, 1);
  ASSERT_EQ(pool.acquire(far()), Grant::Granted);
  ASSERT_EQ(pool.acquire(far()), Grant::Granted);
  EXPECT_EQ(pool.running(), 2u);
  std::atomic<int> waiter{-1};
  std::thread t([&] { waiter = static_cast<int>(pool.acquire(far())); });
  ASSERT_TRUE(eventually([&] { return pool.waiting() == 1; }));
  // Both slots held, the one place in the queue taken: refused without waiting for the deadline.
  const auto start = VerbPool::Clock::now();
  EXPECT_EQ(pool.acquire(far()), Grant::QueueFull);
  EXPECT_LT(VerbPool::Clock::now() - start, 30s);
  EXPECT_EQ(waiter.load(), -1);
  pool.release();
  t.join();
  EXPECT_EQ(waiter.load(), static_cast<int>(Grant::Granted));
  EXPECT_EQ(pool.running(), 2u);
  EXPECT_EQ(pool.waiting(), 0u);
  pool.release();
  pool.release();
  EXPECT_EQ(pool.running(), 0u);
}

TEST(ServeVerbPool, AQueueOfNoneRefusesWhenEverySlotIsHeld) {
  VerbPool pool(1, 0);
  ASSERT_EQ(pool.acquire(far()), Grant::Granted);
  EXPECT_EQ(pool.acquire(far()), Grant::QueueFull);
  pool.release();
  EXPECT_EQ(pool.acquire(far()), Grant::Granted);
  pool.release();
  EXPECT_THROW(VerbPool(0, 4), std::invalid_argument);
}

TEST(ServeVerbPool, DeadlinesAreKept) {
  VerbPool pool(1, 4);
  // A deadline already past is not started, even with a slot free.
  EXPECT_EQ(pool.acquire(VerbPool::Clock::now() - 1ms), Grant::DeadlinePassed);
  EXPECT_EQ(pool.running(), 0u);
  ASSERT_EQ(pool.acquire(far()), Grant::Granted);
  const auto deadline = VerbPool::Clock::now() + 50ms;
  EXPECT_EQ(pool.acquire(deadline), Grant::DeadlinePassed);
  EXPECT_GE(VerbPool::Clock::now(), deadline);
  EXPECT_EQ(pool.waiting(), 0u) << "a caller that gave up has left the queue";
  // One that gives up does not block the one behind it.
  std::atomic<int> early{-1}, late{-1};
  std::thread a([&] { early = static_cast<int>(pool.acquire(VerbPool::Clock::now() + 100ms)); });
  ASSERT_TRUE(eventually([&] { return pool.waiting() == 1; }));
  std::thread b([&] { late = static_cast<int>(pool.acquire(far())); });
  ASSERT_TRUE(eventually([&] { return pool.waiting() == 2; }));
  a.join();
  EXPECT_EQ(early.load(), static_cast<int>(Grant::DeadlinePassed));
  pool.release();
  b.join();
  EXPECT_EQ(late.load(), static_cast<int>(Grant::Granted));
  pool.release();
}

// 24 callers, 20 turns each, on 3 slots: a counter of slots held at once never passes 3, and
// every caller is served (the queue of 64 holds them all).
TEST(ServeVerbPool, NeverMoreThanWorkersAtOnce) {
  VerbPool pool(3, 64);
  std::atomic<int> held{0}, most{0}, granted{0}, over{0};
  std::vector<std::thread> callers;
  for (int c = 0; c < 24; ++c)
    callers.emplace_back([&] {
      for (int i = 0; i < 20; ++i) {
        if (pool.acquire(far()) != Grant::Granted) continue;
        ++granted;
        const int now = ++held;
        int seen = most.load();
        while (now > seen && !most.compare_exchange_weak(seen, now)) {
        }
        if (pool.running() > pool.workers()) ++over;
        std::this_thread::yield();
        --held;
        pool.release();
      }
    });
  for (auto& t : callers) t.join();
  EXPECT_EQ(granted.load(), 24 * 20);
  EXPECT_LE(most.load(), 3);
  EXPECT_GE(most.load(), 1);
  EXPECT_EQ(over.load(), 0);
  EXPECT_EQ(pool.running(), 0u);
  EXPECT_EQ(pool.waiting(), 0u);
}

// Waiting callers get their turn in the order they came.
TEST(ServeVerbPool, FirstComeFirstServed) {
  VerbPool pool(1, 8);
  ASSERT_EQ(pool.acquire(far()), Grant::Granted);
  std::vector<int> order;
  std::mutex order_mutex;
  std::vector<std::thread> callers;
  for (int c = 0; c < 6; ++c) {
    callers.emplace_back([&, c] {
      if (pool.acquire(far()) != Grant::Granted) return;
      {
        std::lock_guard<std::mutex> lock(order_mutex);
        order.push_back(c);
      }
      pool.release();
    });
    ASSERT_TRUE(eventually([&] { return pool.waiting() == static_cast<std::size_t>(c + 1); }));
  }
  pool.release();
  for (auto& t : callers) t.join();
  EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3, 4, 5}));
}

// Retry-After: the recent mean time a slot is held, shared among the slots, in whole seconds, at
// least 1.
TEST(ServeVerbPool, RetryAfterFollowsHowLongSlotsAreHeld) {
  VerbPool pool(2, 0);
  EXPECT_EQ(pool.retry_after_seconds(), 1);
  for (int i = 0; i < 40; ++i) {
    ASSERT_EQ(pool.acquire(far()), Grant::Granted);
    pool.release(std::chrono::seconds(10));
  }
  EXPECT_EQ(pool.retry_after_seconds(), 5);  // 10 s held, 2 slots
  for (int i = 0; i < 40; ++i) {
    ASSERT_EQ(pool.acquire(far()), Grant::Granted);
    pool.release(std::chrono::milliseconds(20));
  }
  EXPECT_EQ(pool.retry_after_seconds(), 1);
}

}  // namespace
