// statespaces::FoldValidity under concurrent calls, as OMPL's parallel planners (PRM, PRM*) make
// them: every thread gets the verdict a single thread gets, and no more collision worlds are
// built than threads checked at once. Run under ThreadSanitizer by scripts/test-tsan.sh.
#include <atomic>
#include <cmath>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "foldkit/geometry/generators.hpp"
#include "foldkit/statespaces/validity.hpp"

namespace {

using namespace foldkit;

// A 30-panel strip: curled the same way at every crease it runs into itself (100° a crease);
// as an accordion (±170°) it does not.
geometry::FoldState strip_state(const geometry::CreasePattern& p, bool curled, double scale) {
  geometry::FoldState s = geometry::FoldState::flat(p);
  for (Eigen::Index j = 0; j < s.angles.size(); ++j)
    s.angles[j] = curled ? scale * 100.0 * M_PI / 180.0 : (j % 2 ? 1.0 : -1.0) * scale * 170.0 * M_PI / 180.0;
  return s;
}

TEST(FoldValidity, ConcurrentChecksAgreeWithOneThread) {
  const geometry::CreasePattern p = geometry::build_or_throw(geometry::generators::strip(30));
  const statespaces::FoldValidity validity(p, statespaces::AngleBounds::of(p, false), true);
  std::vector<geometry::FoldState> states;
  std::vector<bool> expected;
  for (int k = 0; k < 16; ++k) {
    states.push_back(strip_state(p, k % 2 == 0, 0.9 + 0.01 * k + (k % 2 == 0 ? 0.1 : 0.0)));
    expected.push_back(validity.valid(states.back()));
  }
  EXPECT_FALSE(expected[0]);
  EXPECT_TRUE(expected[1]);
  const unsigned threads = 8;
  std::atomic<int> wrong{0};
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t)
    pool.emplace_back([&, t] {
      for (int round = 0; round < 20; ++round)
        for (std::size_t k = 0; k < states.size(); ++k) {
          const std::size_t i = (k + t) % states.size();
          if (validity.valid(states[i]) != expected[i]) ++wrong;
          statespaces::FoldValidity::Motion motion(validity);
          if (motion.valid_first(states[i]) != expected[i] || motion.valid_next(states[i]) != expected[i]) ++wrong;
        }
    });
  for (auto& th : pool) th.join();
  EXPECT_EQ(wrong.load(), 0);
  EXPECT_GE(validity.worlds_built(), 1u);
  EXPECT_LE(validity.worlds_built(), threads);
}

// No collision world at all when collisions are not checked.
TEST(FoldValidity, NoWorldWithoutCollisions) {
  const geometry::CreasePattern p = geometry::build_or_throw(geometry::generators::strip(5));
  const statespaces::FoldValidity validity(p, statespaces::AngleBounds::of(p, false), false);
  EXPECT_TRUE(validity.valid(strip_state(p, true, 1.0)));  // crossing, but not checked
  EXPECT_EQ(validity.worlds_built(), 0u);
}

}  // namespace
