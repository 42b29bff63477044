// geometry::LeastNormSolver against dense SVD (Eigen's JacobiSVD): the least-norm step is −J⁺r,
// the projected velocity is (I − J⁺J)w, and the sparsity analysis is redone only when the
// pattern changes.
#include <random>

#include <Eigen/SVD>
#include <gtest/gtest.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/null_space.hpp"

namespace {

using foldkit::geometry::LeastNormSolver;
using foldkit::geometry::SparseRankMethod;
using Sparse = Eigen::SparseMatrix<double>;

// A random sparse m × n matrix (about 3 entries a row) whose rows r0 … m−1 repeat earlier rows
// with other weights, so its rank is r0.
Sparse random_jacobian(int m, int n, int r0, std::mt19937& rng) {
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  std::uniform_int_distribution<int> column(0, n - 1);
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(m, n);
  for (int i = 0; i < r0; ++i)
    for (int k = 0; k < 3; ++k) d(i, column(rng)) = value(rng);
  for (int i = r0; i < m; ++i) d.row(i) = 0.5 * d.row(i - r0) - 2.0 * d.row((i + 1) % r0);
  return d.sparseView();
}

// The regularised solve is accurate in J's range; along directions of tiny singular value it is
// off by up to about cond(JᵀJ + εI)·u ≈ 1e-4 relative (measured: ≤ 6e-5 over these trials), which
// a Newton corrector does not notice. The rank is not checked: counted from LDLᵀ pivots (not rank
// revealing) it came out 1–3 above the SVD rank on these matrices, full row rank included.
TEST(LeastNormSolver, StepAndNullSpaceMatchTheDensePseudoInverse) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 30, m = 24, r0 = trial % 2 ? 18 : 24;
    const Sparse j = random_jacobian(m, n, r0, rng);
    const Eigen::MatrixXd dense(j);
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(dense, Eigen::ComputeThinU | Eigen::ComputeThinV);
    svd.setThreshold(1e-9);
    // A residual the step can cancel (in J's range), as a closure residual near the manifold is.
    const Eigen::VectorXd r = dense * Eigen::VectorXd::Random(n), w = Eigen::VectorXd::Random(n);

    LeastNormSolver solver(1e-8);
    Eigen::VectorXd step;
    ASSERT_TRUE(solver.min_norm_step(j, r, step));
    const Eigen::VectorXd expected = -svd.solve(r);
    EXPECT_LT((dense * step + r).norm(), 1e-8 * r.norm()) << "trial " << trial;
    EXPECT_LT((step - expected).norm(), 1e-4 * expected.norm()) << "trial " << trial;

    const auto t = solver.project_onto_null_space(j, w);
    const Eigen::VectorXd null_part = w - svd.solve(dense * w);
    EXPECT_LT((t.velocity - null_part).norm(), 1e-4 * w.norm()) << "trial " << trial;
    EXPECT_LT((dense * t.velocity).norm(), 1e-6 * w.norm()) << "trial " << trial;
  }
}

TEST(LeastNormSolver, AnalysesOncePerSparsityPattern) {
  const auto p = foldkit::geometry::build_or_throw(foldkit::geometry::generators::miura(4, 4));
  const foldkit::geometry::ClosureSystem system(p);
  LeastNormSolver solver;
  Eigen::VectorXd r, step;
  Sparse j;
  foldkit::geometry::FoldState s = foldkit::geometry::FoldState::flat(p);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(-1.0, 1.0);
  for (int k = 0; k < 5; ++k) {
    for (Eigen::Index c = 0; c < s.angles.size(); ++c) s.angles[c] = angle(rng);
    system.evaluate(s, r, j);
    ASSERT_TRUE(solver.min_norm_step(j, r, step));
    // The one-off form factors afresh and agrees to rounding.
    Eigen::VectorXd fresh;
    ASSERT_TRUE(foldkit::geometry::min_norm_step(j, r, 1e-8, fresh));
    EXPECT_LT((fresh - step).norm(), 1e-12 * (1.0 + step.norm()));
  }
  EXPECT_EQ(solver.analyses(), 1);
  // Same size and number of non-zeros, other pattern (the columns reversed): a new analysis, and
  // the answer of a fresh solver.
  const Eigen::Index n = j.cols();
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic> reverse(n);
  for (Eigen::Index c = 0; c < n; ++c) reverse.indices()[c] = static_cast<int>(n - 1 - c);
  const Sparse permuted = j * reverse;
  ASSERT_EQ(permuted.nonZeros(), j.nonZeros());
  ASSERT_TRUE(solver.min_norm_step(permuted, r, step));
  EXPECT_EQ(solver.analyses(), 2);
  Eigen::VectorXd fresh;
  ASSERT_TRUE(foldkit::geometry::min_norm_step(permuted, r, 1e-8, fresh));
  EXPECT_LT((fresh - step).norm(), 1e-12 * (1.0 + step.norm()));
  // Back to the first pattern: analysed again, not served from a stale analysis.
  ASSERT_TRUE(solver.min_norm_step(j, r, step));
  EXPECT_EQ(solver.analyses(), 3);
  ASSERT_TRUE(foldkit::geometry::min_norm_step(j, r, 1e-8, fresh));
  EXPECT_LT((fresh - step).norm(), 1e-12 * (1.0 + step.norm()));
}

}  // namespace

namespace {

// decide_rank against Eigen's JacobiSVD (the oracle: a different SVD algorithm), on every path:
// dense SVD (the default limit), sparse QR and subspace iteration (limit 0). Random matrices of
// known rank r0 (rows beyond r0 repeat earlier ones), wider than the dense limit would pass; the
// rank and the singular values on both sides of the tolerance agree. The sparse QR's are bounds:
// the dropped norm is at least σ_{r+1}, and the kept estimate (σ_min of R's live triangle, less
// the dropped norm) at most σ_r to its 1e-2.
struct Path {
  Eigen::Index limit;
  SparseRankMethod sparse;
  const char* method;
};
const Path kPaths[] = {{1000, SparseRankMethod::QrCertified, "dense-svd"},
                       {0, SparseRankMethod::QrCertified, "sparse-qr"},
                       {0, SparseRankMethod::InverseSubspace, "inverse-subspace"}};

TEST(LeastNormSolver, DecideRankMatchesJacobiSvd) {
  std::mt19937 rng(17);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 60, m = 48, r0 = trial % 2 ? 36 : 48;
    const Sparse j = random_jacobian(m, n, r0, rng);
    Eigen::JacobiSVD<Eigen::MatrixXd> svd{Eigen::MatrixXd(j)};
    const Eigen::VectorXd s = svd.singularValues();
    const double tol = 1e-8 * s[0];
    int rank = 0;
    for (Eigen::Index i = 0; i < s.size(); ++i) rank += s[i] > tol;
    LeastNormSolver solver;
    for (const Path& path : kPaths) {
      const foldkit::geometry::RankDecision d = solver.decide_rank(j, 1e-8, path.limit, 0.0, path.sparse);
      EXPECT_EQ(d.method, path.method);
      EXPECT_EQ(d.rank, rank) << trial << " " << d.method;
      EXPECT_EQ(d.nullity, n - rank) << trial << " " << d.method;
      EXPECT_NEAR(d.sigma_max, s[0], 1e-4 * s[0]);  // by power iteration on the sparse paths
      EXPECT_LE(d.largest_zero, tol);
      EXPECT_GT(d.gap(), 1e4) << trial << " " << d.method;
      if (d.method == std::string("sparse-qr")) {
        EXPECT_LE(d.smallest_kept, 1.02 * s[rank - 1]) << trial;
        EXPECT_GT(d.smallest_kept, 10.0 * tol) << trial;
        if (rank < s.size()) {
          EXPECT_GE(d.largest_zero + 1e-14 * s[0], s[rank]) << trial;
        }
      } else {
        EXPECT_NEAR(d.smallest_kept, s[rank - 1], 1e-4 * s[rank - 1]) << trial << " " << d.method;
      }
    }
  }
}

// A matrix the sparse QR misjudges: upper bidiagonal with 1 on the diagonal and −2 above it has
// σ_min ≈ 2⁻ⁿ (its null vector grows geometrically) though no column is small, so Heath's column
// threshold keeps every column. Its live triangle's σ_min is tiny, the certificate refuses the
// count, and the subspace iteration finds the rank the dense SVD does.
TEST(LeastNormSolver, DecideRankDoesNotTakeAMisjudgingQrAtItsWord) {
  const int n = 60;
  Eigen::MatrixXd b = Eigen::MatrixXd::Identity(n, n);
  for (int i = 0; i + 1 < n; ++i) b(i, i + 1) = -2.0;
  const Eigen::VectorXd s = Eigen::JacobiSVD<Eigen::MatrixXd>(b).singularValues();
  int rank = 0;
  for (Eigen::Index i = 0; i < s.size(); ++i) rank += s[i] > 1e-8 * s[0];
  ASSERT_EQ(rank, n - 1);
  LeastNormSolver solver;
  const foldkit::geometry::RankDecision d = solver.decide_rank(Sparse(b.sparseView()), 1e-8, 0);
  EXPECT_EQ(d.method, "inverse-subspace");
  EXPECT_EQ(d.rank, rank);
}

// Near the tolerance the count is left to the singular values: a singular value 3× above the
// tolerance is inside the QR's margin of 10, so the subspace iteration decides, and keeps it.
TEST(LeastNormSolver, DecideRankNearTheThresholdUsesTheSingularValues) {
  std::mt19937 rng(5);
  const Eigen::MatrixXd j(random_jacobian(48, 60, 48, rng));
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(j, Eigen::ComputeThinU | Eigen::ComputeThinV);
  Eigen::VectorXd s = svd.singularValues();
  s[s.size() - 1] = 3.0 * 1e-8 * s[0];
  const Eigen::MatrixXd near = svd.matrixU() * s.asDiagonal() * svd.matrixV().transpose();
  LeastNormSolver solver;
  const foldkit::geometry::RankDecision d = solver.decide_rank(Sparse(near.sparseView(0.0)), 1e-8, 0);
  EXPECT_EQ(d.method, "inverse-subspace");
  EXPECT_EQ(d.rank, 48);
  EXPECT_NEAR(d.smallest_kept, s[s.size() - 1], 1e-3 * s[s.size() - 1]);
}

// Relative by default: the same matrix scaled by 1e-9 keeps its rank. With a scale floor, a
// matrix that is zero to rounding has rank 0 (as a closure Jacobian of a straight crease does).
TEST(LeastNormSolver, DecideRankScaleFloor) {
  std::mt19937 rng(3);
  const Sparse j = random_jacobian(24, 30, 18, rng);
  LeastNormSolver solver;
  for (const Path& path : kPaths) {
    EXPECT_EQ(solver.decide_rank(Sparse(1e-9 * j), 1e-8, path.limit, 0.0, path.sparse).rank, 18) << path.method;
    EXPECT_EQ(solver.decide_rank(Sparse(1e-17 * j), 1e-8, path.limit, 1.0, path.sparse).rank, 0) << path.method;
    EXPECT_EQ(solver.decide_rank(Sparse(1e-17 * j), 1e-8, path.limit, 1.0, path.sparse).nullity, 30) << path.method;
  }
}

}  // namespace
