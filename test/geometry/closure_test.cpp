#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/mobility.hpp"
#include "foldkit/geometry/projection.hpp"
#include "spec_helpers.hpp"

namespace {

using namespace foldkit::geometry;
namespace gen = generators;
using foldkit::test::random_sectors;


// Central differences of the residual, column by column.
Eigen::MatrixXd numeric_jacobian(const ClosureSystem& sys, const FoldState& at, double h = 1e-6) {
  Eigen::MatrixXd J(sys.rows(), sys.cols());
  for (Eigen::Index j = 0; j < sys.cols(); ++j) {
    FoldState plus = at, minus = at;
    plus.angles[j] += h;
    minus.angles[j] -= h;
    J.col(j) = (sys.residual(plus) - sys.residual(minus)) / (2 * h);
  }
  return J;
}

Eigen::MatrixXd analytic_jacobian(const ClosureSystem& sys, const FoldState& at) {
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  sys.evaluate(at, r, J);
  return Eigen::MatrixXd(J);
}

FoldState random_state(const CreasePattern& p, std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> u(-scale, scale);
  FoldState s = FoldState::flat(p);
  for (Eigen::Index i = 0; i < s.angles.size(); ++i) s.angles[i] = u(rng);
  return s;
}

TEST(Closure, FlatIsClosed) {
  std::mt19937 rng(1);
  for (int n : {4, 5, 8, 17, 64}) {
    const CreasePattern p = build_or_throw(gen::single_vertex(random_sectors(n, rng)));
    const ClosureSystem sys(p);
    EXPECT_EQ(sys.vertex_loops(), 1u);
    EXPECT_EQ(sys.rows(), 3);
    EXPECT_EQ(sys.max_error(FoldState::flat(p)), 0.0);
  }
}

TEST(Closure, JacobianMatchesCentralDifferences) {
  std::mt19937 rng(2);
  for (int n : {3, 4, 8, 16, 64}) {
    const CreasePattern p = build_or_throw(gen::single_vertex(random_sectors(n, rng)));
    const ClosureSystem sys(p);
    for (int trial = 0; trial < 5; ++trial) {
      const FoldState s = random_state(p, rng, 1.0 / std::sqrt(n));
      const double err = (analytic_jacobian(sys, s) - numeric_jacobian(sys, s)).cwiseAbs().maxCoeff();
      EXPECT_LT(err, 1e-7) << "degree " << n;
    }
  }
  const CreasePattern miura = build_or_throw(gen::miura(3, 4));
  const ClosureSystem sys(miura);
  const FoldState s = random_state(miura, rng, 0.8);
  EXPECT_LT((analytic_jacobian(sys, s) - numeric_jacobian(sys, s)).cwiseAbs().maxCoeff(), 1e-7);
}

// Degree-4 flat-foldable vertex with sectors (α, β, π−α, π−β); ρk between sectors k−1 and k.
TEST(Closure, DegreeFourModesMatchClosedForms) {
  const double alpha = 1.1, beta = 0.7;
  const CreasePattern p = build_or_throw(gen::single_vertex({alpha, beta, M_PI - alpha, M_PI - beta}));
  const ClosureSystem sys(p);
  // Joint k+1 is crease k (at the cumulative sector angle); sector k lies after crease k.
  for (double t : {0.1, 0.8, 1.5, 2.5, -1.2}) {
    FoldState one = FoldState::flat(p);
    const double r1 = 2 * std::atan(-std::cos((alpha + beta) / 2) / std::cos((alpha - beta) / 2) * std::tan(t / 2));
    one.angles << t, r1, t, -r1;  // mode I: ρ0 = ρ2, ρ3 = −ρ1
    EXPECT_LT(sys.max_error(one), 1e-12) << "mode I at " << t;
    FoldState two = FoldState::flat(p);
    const double r0 = 2 * std::atan(std::sin((alpha - beta) / 2) / std::sin((alpha + beta) / 2) * std::tan(t / 2));
    two.angles << r0, t, -r0, t;  // mode II: ρ1 = ρ3, ρ2 = −ρ0
    EXPECT_LT(sys.max_error(two), 1e-12) << "mode II at " << t;
    // Maekawa: mountains and valleys differ by two in both modes.
    for (const FoldState* m : {&one, &two}) {
      int mountains = 0, valleys = 0;
      for (Eigen::Index k = 0; k < 4; ++k) (m->angles[k] > 0 ? mountains : valleys) += 1;
      EXPECT_EQ(std::abs(mountains - valleys), 2) << t;
    }
    // Driving one crease alone breaks closure.
    FoldState lone = FoldState::flat(p);
    lone.angles[0] = t;
    EXPECT_GT(sys.max_error(lone), 1e-3);
  }
}

TEST(Mobility, SingleVertexFlatAndFolded) {
  std::mt19937 rng(3);
  for (int n : {4, 5, 8, 12, 32, 64}) {
    const CreasePattern p = build_or_throw(gen::single_vertex(random_sectors(n, rng)));
    const ClosureSystem sys(p);
    const Mobility flat = mobility(sys, FoldState::flat(p));
    EXPECT_EQ(flat.rank, 2) << n;
    EXPECT_EQ(flat.dof, n - 2) << n;
    // A folded closed state: project a random non-flat state.
    const ProjectionResult folded = project(sys, random_state(p, rng, 0.6), {1e-12, 200, false, {}});
    ASSERT_TRUE(folded.status.ok()) << n << ": " << folded.status.message;
    const Mobility m = mobility(sys, folded.state);
    EXPECT_EQ(m.rank, 3) << n;
    EXPECT_EQ(m.dof, n - 3) << n;
  }
}

TEST(Mobility, PaperFigure2DegreeEight) {
  const CreasePattern p = build_or_throw(gen::single_vertex(std::vector<double>(8, M_PI / 4)));
  const ClosureSystem sys(p);
  EXPECT_EQ(mobility(sys, FoldState::flat(p)).dof, 6);
  std::mt19937 rng(8);
  const ProjectionResult folded = project(sys, random_state(p, rng, 0.7), {1e-12, 200, false, {}});
  ASSERT_TRUE(folded.status.ok()) << folded.status.message;
  EXPECT_EQ(mobility(sys, folded.state).dof, 5);
}

// Fold a pattern along its mountain/valley assignment: start small with the assigned signs and
// project; rigid-foldable patterns keep the signs.
FoldState fold_along_assignment(const ClosureSystem& sys, const CreasePattern& p, double magnitude) {
  FoldState s = FoldState::flat(p);
  for (std::size_t j = 0; j < p.joints().size(); ++j) {
    const Assignment a = p.joints()[j].assignment;
    s.angles[static_cast<Eigen::Index>(j)] = a == Assignment::Mountain ? magnitude : a == Assignment::Valley ? -magnitude : 0.0;
  }
  const ProjectionResult r = project(sys, s, {1e-12, 500, true, {}});
  EXPECT_TRUE(r.status.ok()) << r.status.message;
  return r.state;
}

TEST(Mobility, FoldedMiuraHasOneDof) {
  const CreasePattern p = build_or_throw(gen::miura(4, 4));
  const ClosureSystem sys(p);
  EXPECT_EQ(sys.vertex_loops(), 9u);
  EXPECT_EQ(p.joints().size(), 24u);
  EXPECT_GT(mobility(sys, FoldState::flat(p)).dof, 1);
  const FoldState folded = fold_along_assignment(sys, p, 0.5);
  const Mobility m = mobility(sys, folded);
  EXPECT_EQ(m.rank, 23);
  EXPECT_EQ(m.dof, 1);
  for (std::size_t j = 0; j < p.joints().size(); ++j)
    EXPECT_NE(folded.angles[static_cast<Eigen::Index>(j)], 0.0) << "joint " << p.joints()[j].id;
}

// Above the dense limit the count is SuiteSparse QR's, with bounds on both sides: the norm it
// dropped is at least the largest singular value counted zero, and its kept estimate (σ_min of
// R's live triangle less that norm) at most the smallest one kept, to its 1e-2.
TEST(Mobility, LargeMiuraBySparseQr) {
  const CreasePattern p = build_or_throw(gen::miura(12, 12));
  const ClosureSystem sys(p);
  const FoldState folded = fold_along_assignment(sys, p, 0.4);
  const Mobility dense = mobility(sys, folded);
  const Mobility sparse = mobility(sys, folded, 1e-8, 0);
  EXPECT_EQ(dense.method, "dense-svd");
  EXPECT_EQ(sparse.method, "sparse-qr");
  EXPECT_EQ(dense.dof, 1);
  EXPECT_EQ(sparse.dof, 1);
  EXPECT_GT(sparse.decision.gap(), 1e3);
  EXPECT_GE(sparse.decision.largest_zero + 1e-14 * dense.decision.sigma_max, dense.decision.largest_zero);
  EXPECT_LE(sparse.decision.smallest_kept, 1.02 * dense.decision.smallest_kept);
  EXPECT_GT(sparse.decision.smallest_kept, 10.0 * sparse.tolerance);
}

// A 3 × 3 grid without its centre cell: no interior vertex, one hole; closure lives in the
// fundamental cycle around the hole.
PatternSpec frame() {
  PatternSpec s = gen::grid(3, 3);
  const int centre = 5;
  s.actors.erase(s.actors.begin() + (centre - 1));
  std::vector<JointSpec> kept;
  for (const JointSpec& j : s.joints)
    if (j.actor_ids[0] != centre && j.actor_ids[1] != centre) kept.push_back(j);
  s.joints = kept;
  return s;
}

TEST(Closure, HoleCyclesCloseTheFrame) {
  const CreasePattern p = build_or_throw(frame());
  EXPECT_EQ(hole_count(p), 1);
  const ClosureSystem sys(p);
  EXPECT_EQ(sys.vertex_loops(), 0u);
  EXPECT_EQ(sys.hole_cycles(), 1u);
  // Folding the line x = 1 on both sides of the hole keeps the frame closed; one side alone not.
  std::vector<int> line;
  for (std::size_t j = 0; j < p.joints().size(); ++j) {
    const auto& J = p.joints()[j];
    if (p.vertices()[J.v[0]].x() == 1.0 && p.vertices()[J.v[1]].x() == 1.0) line.push_back(static_cast<int>(j));
  }
  ASSERT_EQ(line.size(), 2u);
  FoldState both = FoldState::flat(p), one = FoldState::flat(p);
  both.angles[line[0]] = both.angles[line[1]] = 0.9;
  one.angles[line[0]] = 0.9;
  EXPECT_LT(sys.max_error(both), 1e-12);
  EXPECT_GT(sys.max_error(one), 0.1);
  std::mt19937 rng(4);
  for (int trial = 0; trial < 5; ++trial) {
    const FoldState s = random_state(p, rng, 0.7);
    EXPECT_LT((analytic_jacobian(sys, s) - numeric_jacobian(sys, s)).cwiseAbs().maxCoeff(), 1e-7);
  }
}

TEST(Closure, GridWithoutHoleNeedsNoCycles) {
  const CreasePattern p = build_or_throw(gen::grid(3, 3));
  EXPECT_EQ(hole_count(p), 0);
  EXPECT_EQ(ClosureSystem(p).hole_cycles(), 0u);
}

}  // namespace

namespace {

// The boat (paper Fig. 3): folded along its keel it is a one-DOF mechanism; at the bow vertex
// A (sectors π−β, β, β, π−β, β = atan(half_width / bow)) keel and diagonals follow the
// flat-foldable closed form tan(ρ_keel/2) = cos β · tan(ρ_diagonal/2).
TEST(Mobility, BoatFoldsWithOneDof) {
  const double length = 4, half_width = 1, bow = 1.5;
  const CreasePattern p = build_or_throw(gen::boat(length, half_width, bow));
  const ClosureSystem sys(p);
  EXPECT_EQ(sys.vertex_loops(), 3u);
  EXPECT_EQ(mobility(sys, FoldState::flat(p)).dof, 4);
  const double beta = std::atan(half_width / bow);
  for (double t : {0.3, 0.8, 1.5}) {
    FoldState s = FoldState::flat(p);
    // Joints (docs/GENERATORS.md): 1–4 keel bow to stern, 5–6 bow diagonals, 7–8 transverse,
    // 9–10 stern diagonals.
    s.angles << t, -t, -t, t, -t, -t, 0, 0, -t, -t;
    const ProjectionResult r = project(sys, s, {1e-12, 300, false, {}});
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    const Mobility m = mobility(sys, r.state);
    EXPECT_EQ(m.dof, 1) << t;
    const auto& a = r.state.angles;
    EXPECT_NEAR(std::tan(std::abs(a[1]) / 2), std::cos(beta) * std::tan(std::abs(a[4]) / 2), 1e-10);
    EXPECT_NEAR(a[0], -a[1], 1e-10);  // the bow's keel turns against the middle keel
    EXPECT_NEAR(a[6], 0.0, 1e-10);    // the middle vertex folds along its keel only
  }
}

}  // namespace

namespace {

// A crease that runs straight through a vertex (one joint over two collinear edges): its two
// halves enter that vertex's loop as d and −d, which cancel at any angle.
TEST(Closure, StraightCreaseThroughAVertex) {
  const CreasePattern p = build_or_throw(foldkit::test::straight_crease_through_vertex());
  const ClosureSystem sys(p);
  ASSERT_EQ(sys.vertex_loops(), 1u);
  for (double a : {0.4, -2.0, M_PI}) {
    FoldState st = FoldState::flat(p);
    st.angles[0] = a;
    EXPECT_LT(sys.max_error(st), 1e-15);
    EXPECT_LT(analytic_jacobian(sys, st).cwiseAbs().maxCoeff(), 1e-15);
    EXPECT_EQ(mobility(sys, st).dof, 1);
  }
}

}  // namespace
