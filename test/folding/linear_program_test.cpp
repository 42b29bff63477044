// The Clp wrapper against LPs solved by hand (vertex enumeration on paper).
#include "../../folding/src/linear_program.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

namespace {

using foldkit::folding::detail::IncrementalLp;
using foldkit::folding::detail::LinearProgram;
using foldkit::folding::detail::LpSolution;
using foldkit::folding::detail::solve;

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(LinearProgram, TextbookMaximumAtAVertex) {
  // max 3x + 2y  s.t.  x + y <= 4,  x + 3y <= 6,  0 <= x <= 3,  y >= 0.
  // Vertices and objective: (0,0) 0, (3,0) 9, (3,1) 11 (x = 3, x + y = 4 and x + 3y = 6 all
  // meet there), (0,2) 4. Optimum 11 at (3,1).
  LinearProgram lp;
  const int x = lp.add_column(0.0, 3.0, -3.0);
  const int y = lp.add_column(0.0, kInf, -2.0);
  lp.add_row({{x, 1.0}, {y, 1.0}}, -kInf, 4.0);
  lp.add_row({{x, 1.0}, {y, 3.0}}, -kInf, 6.0);
  const LpSolution s = solve(lp);
  ASSERT_EQ(s.status, LpSolution::Status::Optimal);
  ASSERT_EQ(s.x.size(), 2u);
  EXPECT_NEAR(s.x[0], 3.0, 1e-9);
  EXPECT_NEAR(s.x[1], 1.0, 1e-9);
  EXPECT_NEAR(s.objective, -11.0, 1e-9);
}

TEST(LinearProgram, FreeVariablesEqualityRowAndSummedDuplicates) {
  // min t  s.t.  u - v = 1 (written as 0.5u + 0.5u - v), t >= u, t >= -u, t >= v, t >= -v, all free.
  // |u|, |v| <= t with u = v + 1: best is u = 1/2, v = -1/2, t = 1/2.
  LinearProgram lp;
  const int u = lp.add_column(-kInf, kInf, 0.0);
  const int v = lp.add_column(-kInf, kInf, 0.0);
  const int t = lp.add_column(-kInf, kInf, 1.0);
  lp.add_row({{u, 0.5}, {u, 0.5}, {v, -1.0}}, 1.0, 1.0);
  lp.add_row({{t, 1.0}, {u, -1.0}}, 0.0, kInf);
  lp.add_row({{t, 1.0}, {u, 1.0}}, 0.0, kInf);
  lp.add_row({{t, 1.0}, {v, -1.0}}, 0.0, kInf);
  lp.add_row({{t, 1.0}, {v, 1.0}}, 0.0, kInf);
  const LpSolution s = solve(lp);
  ASSERT_EQ(s.status, LpSolution::Status::Optimal);
  EXPECT_NEAR(s.x[0], 0.5, 1e-9);
  EXPECT_NEAR(s.x[1], -0.5, 1e-9);
  EXPECT_NEAR(s.objective, 0.5, 1e-9);
}

TEST(LinearProgram, InfeasibleAndUnboundedAreReported) {
  LinearProgram infeasible;
  const int x = infeasible.add_column(0.0, 1.0, 1.0);
  infeasible.add_row({{x, 1.0}}, 2.0, kInf);
  EXPECT_EQ(solve(infeasible).status, LpSolution::Status::Infeasible);

  LinearProgram unbounded;
  const int a = unbounded.add_column(0.0, kInf, -1.0);
  const int b = unbounded.add_column(0.0, kInf, 0.0);
  unbounded.add_row({{a, 1.0}, {b, -1.0}}, -kInf, 1.0);
  EXPECT_EQ(solve(unbounded).status, LpSolution::Status::Unbounded);
}

TEST(LinearProgram, MalformedInputIsRejected) {
  LinearProgram lp;
  lp.add_column(0.0, 1.0, 1.0);
  lp.add_row({{3, 1.0}}, 0.0, 1.0);
  EXPECT_THROW(solve(lp), std::invalid_argument);
}

TEST(LinearProgram, RowsAddedAfterASolveAreHonouredFromTheWarmBasis) {
  // The textbook LP above, optimum (3,1); then x + y <= 3 cuts it off: the vertices left are
  // (0,0) 0, (3,0) 9, (1.5,1.5) 7.5, (0,2) 4, so the optimum moves to (3,0) with 9. Then
  // y >= 1 (written 0.25y + 0.25y >= 0.5, summed): (3,0) is cut off, and of (2,1) 8, (1.5,1.5)
  // 7.5 and (0,2) 4 the first is best.
  LinearProgram lp;
  const int x = lp.add_column(0.0, 3.0, -3.0);
  const int y = lp.add_column(0.0, kInf, -2.0);
  lp.add_row({{x, 1.0}, {y, 1.0}}, -kInf, 4.0);
  lp.add_row({{x, 1.0}, {y, 3.0}}, -kInf, 6.0);
  IncrementalLp incremental(lp);
  LpSolution s = incremental.solve();
  ASSERT_EQ(s.status, LpSolution::Status::Optimal);
  EXPECT_NEAR(s.objective, -11.0, 1e-9);
  EXPECT_EQ(incremental.add_row({{x, 1.0}, {y, 1.0}}, -kInf, 3.0), 2);
  s = incremental.solve();
  ASSERT_EQ(s.status, LpSolution::Status::Optimal);
  EXPECT_NEAR(s.x[0], 3.0, 1e-9);
  EXPECT_NEAR(s.x[1], 0.0, 1e-9);
  EXPECT_NEAR(s.objective, -9.0, 1e-9);
  incremental.add_row({{y, 0.25}, {y, 0.25}}, 0.5, kInf);
  s = incremental.solve(IncrementalLp::Method::Primal);
  ASSERT_EQ(s.status, LpSolution::Status::Optimal);
  EXPECT_NEAR(s.x[0], 2.0, 1e-9);
  EXPECT_NEAR(s.x[1], 1.0, 1e-9);
  EXPECT_EQ(incremental.rows(), 4);

  // The optimal basis, handed to a fresh model of the same LP, is optimal there at once.
  const IncrementalLp::Basis basis = incremental.basis();
  lp.add_row({{x, 1.0}, {y, 1.0}}, -kInf, 3.0);
  lp.add_row({{y, 0.5}}, 0.5, kInf);
  IncrementalLp restarted(lp);
  restarted.set_basis(basis);
  s = restarted.solve();
  ASSERT_EQ(s.status, LpSolution::Status::Optimal);
  EXPECT_NEAR(s.objective, -8.0, 1e-9);

  IncrementalLp other(lp);
  EXPECT_THROW(other.set_basis(IncrementalLp::Basis{{1}, {1, 1}}), std::invalid_argument);
  EXPECT_THROW(other.add_row({{5, 1.0}}, 0.0, 1.0), std::invalid_argument);
}

}  // namespace
