// The driving space's continuation on the Resch tessellation (bench/data): a goal whose plan went
// wrong when a continuation's first tangent came from the previous correction's factorisation
// (made up to a step away) instead of a fresh one at its start. The continuation then crossed to
// another branch within its jump limit and every plan ended in "the planned path jumps
// (interpolation left the manifold)" (scripts/experience-queries.py, goal 5 of seed 1); the
// fresh factorisation plans it with every seed.
#include <string>

#include <gtest/gtest.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/fold_format.hpp"
#include "foldkit/planners/plan.hpp"
#include "resch_states.hpp"

namespace {

using foldkit::geometry::CreasePattern;
using foldkit::geometry::FoldState;

TEST(DrivingContinuation, ReschGoalIsPlannedWithoutLeavingItsBranch) {
  const CreasePattern p = foldkit::io::read_fold(foldkit::test::resch_path()).pattern;
  const FoldState goal =
      foldkit::geometry::end_state(p, foldkit::io::read_cmml(std::string(FOLDKIT_TEST_DATA) + "/good/resch-goal-branch.cmml"));
  ASSERT_LE(foldkit::geometry::ClosureSystem(p).max_error(goal), 1e-9);
  for (unsigned seed : {1u, 2u, 6u}) {
    SCOPED_TRACE(seed);
    foldkit::planners::PlanOptions o;
    o.seed = seed;
    o.time = 10.0;
    const foldkit::planners::PlanResult r = foldkit::planners::plan(p, goal, o);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    EXPECT_EQ(r.space, "driving");
    ASSERT_TRUE(r.replay && r.replay->status.ok());
    EXPECT_LT((r.waypoints.back().angles - goal.angles).cwiseAbs().maxCoeff(), 1e-6);
  }
}

}  // namespace
