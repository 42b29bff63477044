// The tangent against central differences, stiff problems, and bad problems.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "foldkit/analysis/solver.hpp"
#include "foldkit/geometry/generators.hpp"

namespace {

using namespace foldkit;
using analysis::ConnectionKind;
using Eigen::Vector3d;

analysis::Problem cube_problem(double translational, double rotational) {
  const auto p = geometry::build_or_throw(geometry::generators::cube_sheet(1, 0.01));
  geometry::FoldState s = geometry::FoldState::flat(p);
  for (int j = 0; j < 5; ++j) s.angles[j] = -M_PI / 2;
  analysis::Problem pr;
  pr.structure = analysis::build_structure(p, s);
  for (auto kind : {ConnectionKind::Face, ConnectionKind::Edge}) {
    analysis::Matrix6 k = analysis::Matrix6::Zero();
    k.diagonal() << translational, translational, translational, rotational, rotational, rotational;
    pr.stiffness[static_cast<int>(kind)] = k;
  }
  pr.fixed.assign(6, false);
  pr.fixed[0] = true;  // the base: actor 1, the root, lies flat and the cube rises above it
  pr.loads.push_back({2, Vector3d(3.0, -1.0, -40.0), pr.structure.modules[2].centroid + Vector3d(0.004, 0.003, 0.0)});
  return pr;
}

TEST(Solver, TangentMatchesCentralDifferences) {
  auto p = cube_problem(1e3, 5.0);
  p.stiffness[0](0, 4) = p.stiffness[0](4, 0) = 3.0;  // coupling terms too
  p.stiffness[0](2, 3) = p.stiffness[0](3, 2) = -2.0;
  const analysis::EquilibriumSystem sys(p);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  Eigen::VectorXd x(sys.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) x[i] = u(rng);
  const Eigen::MatrixXd analytic = Eigen::MatrixXd(sys.tangent(x, 0.7));
  const double h = 1e-6;
  double worst = 0.0;
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    Eigen::VectorXd e = Eigen::VectorXd::Zero(x.size());
    e[j] = h;
    const Eigen::VectorXd fd = (sys.residual(sys.retract(x, e), 0.7) - sys.residual(sys.retract(x, -e), 0.7)) / (2 * h);
    worst = std::max(worst, (fd - analytic.col(j)).lpNorm<Eigen::Infinity>() / (1.0 + analytic.col(j).lpNorm<Eigen::Infinity>()));
  }
  EXPECT_LT(worst, 1e-6);
}

TEST(Solver, StiffnessRatiosOf1e6And1e12Converge) {
  // Hinges keep K66 = 1 N·m/rad; faces and edges 1e6 (Eq. 6) and then 1e12 N/m.
  for (double stiff : {1e6, 1e12}) {
    const auto p = cube_problem(stiff, stiff * 1e-5);
    const auto r = analysis::solve(p);
    ASSERT_TRUE(r.status.ok()) << stiff << ": " << r.status.message;
    EXPECT_LE(r.residual_norm, std::max(1e-10, r.residual_floor)) << stiff;
    EXPECT_LT(r.residual_floor, 1e-3) << stiff;
    EXPECT_GT(r.condition_estimate, 1.0);
    EXPECT_TRUE(std::isfinite(r.condition_estimate));
    analysis::SolveOptions lin;
    lin.linear = true;
    const auto l = analysis::solve(p, lin);
    ASSERT_TRUE(l.status.ok()) << l.status.message;
    EXPECT_GT(r.max_displacement, 0.0);
    // Stiff structure, small motion: the linear answer is close.
    EXPECT_NEAR(l.max_displacement, r.max_displacement, 0.05 * r.max_displacement) << stiff;
  }
}

TEST(Solver, UnrestrainedModuleIsRefused) {
  auto p = cube_problem(1e6, 10);
  p.fixed.assign(6, false);
  EXPECT_EQ(analysis::unrestrained_module(p), 0);
  EXPECT_THROW(analysis::solve(p), std::invalid_argument);
}

TEST(Solver, NoLoadNoMotion) {
  auto p = cube_problem(1e6, 10);
  p.loads.clear();
  const auto r = analysis::solve(p);
  EXPECT_TRUE(r.status.ok());
  EXPECT_EQ(r.max_displacement, 0.0);
  EXPECT_EQ(r.iterations, 0);
}

}  // namespace
