// Driving charts: the passive creases solved from the driving ones are closed (ClosureSystem),
// agree with the Levenberg–Marquardt projection holding the driving creases (geometry::project,
// another solver), and continuation is a function of the driving angles (there and back again).
#include <random>

#include <gtest/gtest.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/driving_chart.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/mobility.hpp"
#include "foldkit/geometry/projection.hpp"
#include "folded_state.hpp"
#include "spec_helpers.hpp"

namespace {

namespace gen = foldkit::geometry::generators;
using namespace foldkit::geometry;

using foldkit::test::folded_along_assignment;

TEST(DrivingChart, MiuraHasOneDrivingCreaseAndItsPassivesFollow) {
  for (int n : {2, 5, 12}) {
    SCOPED_TRACE("Miura " + std::to_string(n));
    const CreasePattern p = build_or_throw(gen::miura(n, n));
    const ClosureSystem sys(p);
    const FoldState goal = folded_along_assignment(p, 0.7);
    const Mobility m = mobility(sys, goal);
    ASSERT_EQ(m.dof, 1);
    const DrivingChart chart = choose_driving_chart(sys, goal, m.dof);
    ASSERT_EQ(chart.driving.size(), 1u);
    EXPECT_EQ(chart.driving.size() + chart.passive.size(), p.joints().size());
    EXPECT_GT(chart.conditioning, 0.0);
    PassiveSolver solver(sys, chart);

    // Perturbed passives come back to the same state (the passives are a function of the driving).
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u(-0.01, 0.01);
    FoldState x = goal;
    for (int j : chart.passive) x.angles[j] += u(rng);
    ASSERT_TRUE(solver.correct(x).ok());
    EXPECT_LE(sys.max_error(x), 1e-12);
    EXPECT_LT((x.angles - goal.angles).cwiseAbs().maxCoeff(), 1e-9);

    // Down to a third of the way and back: the same state, every point closed.
    const Eigen::VectorXd d = solver.driving_of(goal);
    FoldState mid, back;
    std::vector<FoldState> path;
    ASSERT_TRUE(solver.follow(goal, d / 3.0, mid, &path).ok());
    EXPECT_NEAR(mid.angles[chart.driving[0]], d[0] / 3.0, 1e-15);
    for (const FoldState& s : path) EXPECT_LE(sys.max_error(s), 1e-12);
    for (std::size_t i = 1; i < path.size(); ++i)
      EXPECT_LE((path[i].angles - path[i - 1].angles).cwiseAbs().maxCoeff(), 2 * solver.options().max_step);
    ASSERT_TRUE(solver.follow(mid, d, back).ok());
    EXPECT_LT((back.angles - goal.angles).cwiseAbs().maxCoeff(), 1e-9);

    // Another solver agrees: Levenberg–Marquardt holding the driving crease from a rough guess.
    ProjectionOptions po;
    po.tolerance = 1e-12;
    po.held.assign(p.joints().size(), false);
    po.held[static_cast<std::size_t>(chart.driving[0])] = true;
    FoldState guess = mid;
    for (int j : chart.passive) guess.angles[j] *= 1.02;
    const auto lm = project(sys, guess, po);
    ASSERT_TRUE(lm.status.ok()) << lm.status.message;
    EXPECT_LT((lm.state.angles - mid.angles).cwiseAbs().maxCoeff(), 1e-8);
  }
}

// Several degrees of freedom: a degree-8 vertex of random sectors (5 DOF) and the waterbomb.
TEST(DrivingChart, SeveralDrivingCreases) {
  std::mt19937 rng(7);
  for (const PatternSpec& spec : {gen::single_vertex(gen::random_sectors(8, rng, 0.3)), gen::waterbomb(2, 2)}) {
    const CreasePattern p = build_or_throw(spec);
    const ClosureSystem sys(p);
    FoldState goal = p.interior_vertices().size() == 1 ? FoldState::flat(p) : folded_along_assignment(p, 0.4);
    if (p.interior_vertices().size() == 1) {  // no assignment: alternate the signs
      Eigen::VectorXd g(static_cast<Eigen::Index>(p.joints().size()));
      for (Eigen::Index j = 0; j < g.size(); ++j) g[j] = (j % 2 ? -0.3 : 0.4) + 0.02 * static_cast<double>(j);
      ProjectionOptions po;
      po.tolerance = 1e-12;
      const auto r = project(sys, FoldState{g}, po);
      ASSERT_TRUE(r.status.ok());
      goal = r.state;
    }
    const Mobility m = mobility(sys, goal);
    ASSERT_GT(m.dof, 1);
    const DrivingChart chart = choose_driving_chart(sys, goal, m.dof);
    ASSERT_EQ(static_cast<int>(chart.driving.size()), m.dof);
    PassiveSolver solver(sys, chart);
    const Eigen::VectorXd d = solver.driving_of(goal);
    FoldState out;
    ASSERT_TRUE(solver.follow(goal, 0.6 * d, out).ok());
    EXPECT_LE(sys.max_error(out), 1e-12);
    EXPECT_LT((solver.driving_of(out) - 0.6 * d).cwiseAbs().maxCoeff(), 1e-15);
  }
}

TEST(DrivingChart, RefusesAWrongDof) {
  const CreasePattern p = build_or_throw(gen::miura(3, 3));
  const ClosureSystem sys(p);
  const FoldState goal = folded_along_assignment(p, 0.5);
  EXPECT_THROW(choose_driving_chart(sys, goal, 3), std::invalid_argument);  // the null space has 1 dimension
  EXPECT_THROW(choose_driving_chart(sys, goal, -1), std::invalid_argument);
  EXPECT_TRUE(choose_driving_chart(sys, goal, 0).driving.empty());
}

}  // namespace
