// geometry::closure_path: paths of closed states, checked by invariants (closure of every state,
// step bounds, held angles, rank reached) on a Miura-ori and a strip.
#include <cmath>

#include <gtest/gtest.h>

#include "foldkit/geometry/closure_path.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/mobility.hpp"
#include "foldkit/geometry/projection.hpp"

namespace {

using namespace foldkit::geometry;

FoldState along_assignment(const CreasePattern& p, double magnitude) {
  FoldState s = FoldState::flat(p);
  for (std::size_t j = 0; j < p.joints().size(); ++j)
    s.angles[static_cast<Eigen::Index>(j)] = (p.joints()[j].assignment == Assignment::Mountain ? 1.0 : -1.0) * magnitude;
  return s;
}

TEST(ClosurePath, LeadInLeavesFlatAtFullRankAndDensifyKeepsSteps) {
  const CreasePattern p = build_or_throw(generators::miura(4, 4));
  const ClosureSystem sys(p);
  const FoldState goal = project(sys, along_assignment(p, 0.8)).state;
  ASSERT_LT(sys.max_error(goal), 1e-9);
  const Eigen::Index rank = mobility(sys, goal).rank;
  const std::vector<FoldState> in = lead_in(sys, FoldState::flat(p), goal, rank, 0.02);
  ASSERT_GE(in.size(), 2u);
  EXPECT_EQ(in.front().angles.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(mobility(sys, in.back()).rank, rank);
  for (std::size_t i = 0; i < in.size(); ++i) {
    EXPECT_LT(sys.max_error(in[i]), 1e-9) << i;
    if (i > 0) {
      EXPECT_LE((in[i].angles - in[i - 1].angles).cwiseAbs().maxCoeff(), 0.04 + 1e-12) << i;
    }
  }
  const auto dense = densify(sys, {in.back(), goal}, 0.02);
  ASSERT_TRUE(dense);
  EXPECT_EQ((dense->back().angles - goal.angles).cwiseAbs().maxCoeff(), 0.0);
  for (std::size_t i = 1; i < dense->size(); ++i) {
    EXPECT_LT(sys.max_error((*dense)[i]), 1e-9) << i;
    EXPECT_LE(((*dense)[i].angles - (*dense)[i - 1].angles).cwiseAbs().maxCoeff(), 0.04 + 1e-12) << i;
  }
  EXPECT_EQ(projected_line(sys, in.back(), goal, 0.02).size(), dense->size());
}

// Without a loop the projected line is the straight line, ends included.
TEST(ClosurePath, ProjectedLineOfAStripIsStraight) {
  const CreasePattern p = build_or_throw(generators::strip(4));
  const ClosureSystem sys(p);
  const FoldState a = FoldState::flat(p), b = along_assignment(p, 1.0);
  const std::vector<FoldState> line = projected_line(sys, a, b, 0.1);
  ASSERT_EQ(line.size(), 11u);
  EXPECT_EQ(line.back().angles, b.angles);
  EXPECT_NEAR((line[3].angles - 0.3 * b.angles).cwiseAbs().maxCoeff(), 0.0, 1e-15);
}

// The named creases keep their angles exactly; the state closes; an impossible request says why.
TEST(ClosurePath, GoalFromAnglesHoldsTheNamedCreases) {
  const CreasePattern p = build_or_throw(generators::single_vertex({M_PI / 4, M_PI / 4, M_PI / 4, M_PI / 4, M_PI / 4,
                                                                     M_PI / 4, M_PI / 4, M_PI / 4}));
  const ClosureSystem sys(p);
  std::string why;
  const auto g = goal_from_angles(sys, {{0, 0.7}, {2, -0.4}}, why);
  ASSERT_TRUE(g) << why;
  EXPECT_EQ(g->angles[0], 0.7);
  EXPECT_EQ(g->angles[2], -0.4);
  EXPECT_LT(sys.max_error(*g), 1e-9);
}

}  // namespace
