// statespaces::ClosureConstraint::project: disturbed Miura-ori states come back to the closure
// manifold (every loop of geometry::ClosureSystem closed, not only the rows the constraint keeps),
// to nearly the point the dense least-norm Newton iteration reaches from the same start (Eigen's
// complete orthogonal decomposition of the constraint's dense Jacobian, the previous method), and
// non-finite input is refused.
#include <cmath>
#include <limits>
#include <random>

#include <Eigen/QR>
#include <gtest/gtest.h>

#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/statespaces/closure_constraint.hpp"

namespace {

using namespace foldkit;

// A Miura-ori folded along its mode by continuation, every crease at least `m_end` on its side.
geometry::FoldState closed_miura(const geometry::CreasePattern& p, double m_end) {
  const geometry::ClosureSystem sys(p);
  geometry::FoldState s = geometry::FoldState::flat(p);
  for (double m = 0.1; m <= m_end + 1e-9; m += 0.1) {
    for (std::size_t j = 0; j < p.joints().size(); ++j) {
      const auto i = static_cast<Eigen::Index>(j);
      s.angles[i] = (p.joints()[j].assignment == geometry::Assignment::Mountain ? 1 : -1) * std::max(m, std::abs(s.angles[i]));
    }
    const auto r = geometry::project(sys, s);
    EXPECT_TRUE(r.status.ok()) << r.status.message;
    s = r.state;
  }
  return s;
}

// The dense least-norm Newton iteration on the same constraint (function, analytic Jacobian).
bool dense_project(const statespaces::ClosureConstraint& c, Eigen::VectorXd& x) {
  Eigen::VectorXd f(c.getCoDimension());
  Eigen::MatrixXd j(c.getCoDimension(), x.size());
  c.function(x, f);
  for (unsigned int iteration = 0; f.norm() > c.getTolerance(); ++iteration) {
    if (iteration >= c.getMaxIterations()) return false;
    c.jacobian(x, j);
    x -= j.completeOrthogonalDecomposition().solve(f);
    c.function(x, f);
  }
  return true;
}

TEST(ClosureConstraint, SparseProjectionClosesEveryLoopAndAgreesWithTheDenseOne) {
  for (int n : {4, 6}) {
    const auto p = geometry::build_or_throw(geometry::generators::miura(n, n));
    const geometry::FoldState reference = closed_miura(p, 1.0);
    const statespaces::ClosureConstraint c(p, reference);
    const geometry::ClosureSystem all(p);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> noise(-0.02, 0.02);
    double largest_gap = 0.0;
    for (int trial = 0; trial < 20; ++trial) {
      Eigen::VectorXd start = reference.angles;
      for (Eigen::Index i = 0; i < start.size(); ++i) start[i] += noise(rng);
      ASSERT_GT(all.max_error(geometry::FoldState{start}), 1e-3);
      Eigen::VectorXd sparse = start, dense = start;
      ASSERT_TRUE(c.project(sparse)) << n << " trial " << trial;
      ASSERT_TRUE(dense_project(c, dense)) << n << " trial " << trial;
      EXPECT_LT(all.max_error(geometry::FoldState{sparse}), 1e-7) << n << " trial " << trial;
      largest_gap = std::max(largest_gap, (sparse - dense).cwiseAbs().maxCoeff());
    }
    // Both take least-norm steps from the same start; the sparse one is regularised (ε ≈ 1e-12
    // of JᵀJ's scale), so the end points agree closely but not to rounding.
    EXPECT_LT(largest_gap, 1e-5) << n;
  }
}

TEST(ClosureConstraint, NonFiniteStatesAreRefused) {
  const auto p = geometry::build_or_throw(geometry::generators::miura(4, 4));
  const statespaces::ClosureConstraint c(p, closed_miura(p, 1.0));
  Eigen::VectorXd x = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(p.joints().size()), 0.3);
  x[2] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(c.project(x));
  x[2] = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(c.project(x));
}

}  // namespace
