#pragma once
// The O(m²) all-pairs checks of the planar Carpenter's rule on two cores, and the coordinate
// arrays and squared-distance kernel they scan with; private to foldkit::folding. Issue 36 asks
// for 10,000 links on 2 cores; at 1,000–2,000 links the checks of the carried field and of every
// step were a fifth to a quarter of the run, and each pass is a few milliseconds, so one extra
// thread per pass (no pool) costs little beside it.
#include <cmath>
#include <cstddef>
#include <exception>
#include <future>
#include <system_error>
#include <vector>

#include <Eigen/Core>

namespace foldkit::folding::detail {

// Points (or velocities) as two coordinate arrays, for the all-pairs loops the compiler vectorises.
struct Coordinates {
  explicit Coordinates(const std::vector<Eigen::Vector2d>& p) : x(p.size()), y(p.size()) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      x[i] = p[i].x();
      y[i] = p[i].y();
    }
  }
  std::vector<double> x, y;
};

// change[b] = |to_b − to_a|² − |from_b − from_a|² for b in [lo, hi]; returns how many are < 0.
// Counted, not or-ed: an integer sum keeps the loop vectorisable.
inline int squared_changes(const Coordinates& from, const Coordinates& to, int a, int lo, int hi, std::vector<double>& change) {
  const double* bx = from.x.data();
  const double* by = from.y.data();
  const double* ax = to.x.data();
  const double* ay = to.y.data();
  int shrinking = 0;
  for (int b = lo; b <= hi; ++b) {
    const double ex = bx[b] - bx[a], ey = by[b] - by[a], fx = ax[b] - ax[a], fy = ay[b] - ay[a];
    const double c = (fx * fx + fy * fy) - (ex * ex + ey * ey);
    change[b] = c;
    shrinking += c < 0.0;
  }
  return shrinking;
}

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
