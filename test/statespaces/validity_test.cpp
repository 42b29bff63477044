// statespaces::FoldValidity under concurrent calls, as OMPL's parallel planners (PRM, PRM*) make
// them: every thread gets the verdict a single thread gets, and no more collision worlds are
// built than threads checked at once. Run under ThreadSanitizer by scripts/test-tsan.sh.
#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "foldkit/geometry/generators.hpp"
#include "foldkit/statespaces/validity.hpp"

#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>

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

// A time limit makes OMPL's checks on the validity fail once it has passed (so that planner loops
// that never consult their termination condition end), leaves valid() alone, and nests: the
// limit it replaced comes back with it.
TEST(FoldValidity, TimeLimitExpiresOmplChecksAndNests) {
  namespace ob = ompl::base;
  using Clock = std::chrono::steady_clock;
  const geometry::CreasePattern p = geometry::build_or_throw(geometry::generators::strip(5));
  const auto validity = std::make_shared<const statespaces::FoldValidity>(p, statespaces::AngleBounds::of(p, false), false);
  const auto joints = static_cast<unsigned>(p.joints().size());
  auto space = std::make_shared<ob::RealVectorStateSpace>(joints);
  space->setBounds(-M_PI, M_PI);
  auto si = std::make_shared<ob::SpaceInformation>(space);
  const statespaces::StateReader reader = [joints](const ob::State* s, geometry::FoldState& f) {
    f.angles.resize(joints);
    for (unsigned j = 0; j < joints; ++j) f.angles[j] = s->as<ob::RealVectorStateSpace::StateType>()->values[j];
    return true;
  };
  const statespaces::FoldValidityChecker checker(si, validity, reader);
  const statespaces::FoldMotionValidator motion(si, validity, reader);
  ob::ScopedState<ob::RealVectorStateSpace> flat(space);
  for (unsigned j = 0; j < joints; ++j) flat[j] = 0.0;
  EXPECT_FALSE(validity->expired());
  EXPECT_TRUE(checker.isValid(flat.get()));
  {
    const statespaces::FoldValidity::TimeLimit later(*validity, Clock::now() + std::chrono::hours(1));
    EXPECT_FALSE(validity->expired());
    EXPECT_TRUE(motion.checkMotion(flat.get(), flat.get()));
    {
      const statespaces::FoldValidity::TimeLimit past(*validity, Clock::now() - std::chrono::seconds(1));
      EXPECT_TRUE(validity->expired());
      EXPECT_TRUE(checker.isValid(flat.get()));  // a state keeps its verdict (SPARStwo asserts it)
      EXPECT_FALSE(motion.checkMotion(flat.get(), flat.get()));
      EXPECT_TRUE(validity->valid(geometry::FoldState::flat(p)));
    }
    EXPECT_FALSE(validity->expired());
    EXPECT_TRUE(checker.isValid(flat.get()));
  }
  EXPECT_FALSE(validity->expired());
}

}  // namespace
