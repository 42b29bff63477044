#pragma once
// The O(m²) all-pairs checks of the planar Carpenter's rule on two cores, private to
// foldkit::folding. Issue 36 asks for 10,000 links on 2 cores; at 1,000–2,000 links the checks of
// the carried field and of every step were a fifth to a quarter of the run, and each pass is a
// few milliseconds, so one extra thread per pass (no pool) costs little beside it.
#include <cmath>
#include <exception>
#include <future>
#include <system_error>

namespace foldkit::folding::detail {

// Below this many vertices a pass is under ~0.1 ms, where starting a thread would not pay.
constexpr int kTwoThreadsFrom = 400;

// The first a of the second half: pairs (a, b > a) over a in [0, split) are about as many as over
// [split, m), i.e. m²/4 = split·m − split²/2, split = m·(1 − 1/√2).
inline int pair_split(int m) { return static_cast<int>(m * (1.0 - std::sqrt(0.5))); }

// Runs body(first, last, half) for a in [0, split) (half 0, always on the calling thread) and
// [split, m) (half 1): on a second thread when m ≥ kTwoThreadsFrom and a thread can be had, else
// after half 0 on the calling thread. Each half writes only its own state, so the caller's
// results (merged in half order) do not depend on where half 1 ran. An exception in either half
// is rethrown here, after both ended.
template <typename Body>
void for_two_halves(int m, Body&& body) {
  const int split = pair_split(m);
  if (m < kTwoThreadsFrom) {
    body(0, split, 0);
    body(split, m, 1);
    return;
  }
  std::future<void> second;
  try {
    second = std::async(std::launch::async, [&] { body(split, m, 1); });
  } catch (const std::system_error&) {  // no thread to be had: both halves here
    body(0, split, 0);
    body(split, m, 1);
    return;
  }
  std::exception_ptr first_error;
  try {
    body(0, split, 0);
  } catch (...) {
    first_error = std::current_exception();
  }
  second.get();  // waits; rethrows the second half's exception
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace foldkit::folding::detail
