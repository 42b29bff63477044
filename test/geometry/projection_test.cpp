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


TEST(Projection, ThousandRandomPerturbations) {
  // A closed folded state of a degree-6 vertex, perturbed 1,000 times by up to 0.2 rad per crease.
  std::mt19937 rng(6);
  const CreasePattern p = build_or_throw(gen::single_vertex(random_sectors(6, rng, 0.3)));
  const ClosureSystem sys(p);
  FoldState start = FoldState::flat(p);
  start.angles << 0.6, -0.5, 0.7, -0.4, 0.5, -0.6;
  const ProjectionResult base = project(sys, start, {1e-12, 200, false, {}});
  ASSERT_TRUE(base.status.ok()) << base.status.message;
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  int ok = 0;
  double worst = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    FoldState s = base.state;
    for (Eigen::Index i = 0; i < s.angles.size(); ++i) s.angles[i] += u(rng);
    const ProjectionResult r = project(sys, s, {1e-10, 100, false, {}});
    ok += r.status.ok();
    if (r.status.ok()) worst = std::max(worst, r.error);
    EXPECT_TRUE(r.state.angles.allFinite());
  }
  EXPECT_GE(ok, 995) << "success rate " << ok / 10.0 << "%";
  EXPECT_LE(worst, 1e-10);
}

TEST(Projection, MultiVertexPerturbations) {
  const CreasePattern p = build_or_throw(gen::miura(3, 3));
  const ClosureSystem sys(p);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.15, 0.15);
  int ok = 0;
  for (int trial = 0; trial < 200; ++trial) {
    FoldState s = FoldState::flat(p);
    for (std::size_t j = 0; j < p.joints().size(); ++j) {
      const double sign = p.joints()[j].assignment == Assignment::Mountain ? 1.0 : -1.0;
      s.angles[static_cast<Eigen::Index>(j)] = sign * 0.6 + u(rng);
    }
    ok += project(sys, s).status.ok();
  }
  EXPECT_GE(ok, 198);
}

TEST(Projection, NearFlatKeepsTheAssignedSigns) {
  // At the flat state every vertex loses rank; small angles along the Miura assignment must
  // project onto the folded branch with every mountain still a mountain.
  const CreasePattern p = build_or_throw(gen::miura(4, 4));
  const ClosureSystem sys(p);
  FoldState s = FoldState::flat(p);
  for (std::size_t j = 0; j < p.joints().size(); ++j)
    s.angles[static_cast<Eigen::Index>(j)] = (p.joints()[j].assignment == Assignment::Mountain ? 1 : -1) * 1e-3;
  const ProjectionResult r = project(sys, s);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  for (Eigen::Index j = 0; j < s.angles.size(); ++j) EXPECT_GT(r.state.angles[j] * s.angles[j], 0.0) << j;
}

// Holding crease 0 of a degree-4 flat-foldable vertex at 0.8 rad: the other three move to a closed
// state on one of the two closed-form modes (NOTES.md), and crease 0 stays exactly where it was.
TEST(Projection, HeldCreasesStayPut) {
  const double alpha = 1.1, beta = 0.7, t = 0.8;
  const CreasePattern p = build_or_throw(gen::single_vertex({alpha, beta, M_PI - alpha, M_PI - beta}));
  const ClosureSystem sys(p);
  ProjectionOptions o;
  o.held = {true, false, false, false};
  for (const Eigen::Vector4d& rough : {Eigen::Vector4d(t, -0.3, 0.6, 0.3), Eigen::Vector4d(t, 1.2, -0.5, 1.1)}) {
    FoldState start = FoldState::flat(p);
    start.angles = rough;
    const ProjectionResult r = project(sys, start, o);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    EXPECT_EQ(r.state.angles[0], t);
    EXPECT_LT(sys.max_error(r.state), 1e-10);
    const double r1 = 2 * std::atan(-std::cos((alpha + beta) / 2) / std::cos((alpha - beta) / 2) * std::tan(t / 2));
    const double t2 = 2 * std::atan(std::tan(t / 2) * std::sin((alpha + beta) / 2) / std::sin((alpha - beta) / 2));
    const Eigen::Vector4d mode1(t, r1, t, -r1), mode2(t, t2, -t, t2);
    const double off = std::min((r.state.angles - mode1).norm(), (r.state.angles - mode2).norm());
    EXPECT_LT(off, 1e-8) << r.state.angles.transpose();
  }
  o.held = {true, false};
  EXPECT_THROW(project(sys, FoldState::flat(p), o), std::invalid_argument);
}

TEST(Projection, ReportsFailure) {
  const CreasePattern p = build_or_throw(gen::single_vertex({1.0, 1.0, 1.0, 2 * M_PI - 3.0}));
  const ClosureSystem sys(p);
  FoldState s = FoldState::flat(p);
  s.angles << 2.5, 2.5, 2.5, 2.5;
  const ProjectionResult r = project(sys, s, {1e-10, 3, true, {}});
  EXPECT_FALSE(r.status.ok());
  EXPECT_FALSE(r.status.message.empty());
  EXPECT_GT(r.error, 1e-10);
  s.angles[1] = std::nan("");
  const ProjectionResult bad = project(sys, s);
  EXPECT_FALSE(bad.status.ok());
  EXPECT_NE(bad.status.message.find("non-finite"), std::string::npos);
}

TEST(NumericalExtremes, SliverSectorsHighDegreeAndNearPi) {
  std::mt19937 rng(9);
  // Sector angles down to 1e-6 rad.
  std::vector<double> sliver = random_sectors(8, rng, 0.2);
  sliver[1] += sliver[0] - 1e-6;  // move all but 1e-6 rad of the first sector into the second
  sliver[0] = 1e-6;
  // Degree 256.
  const std::vector<double> many = random_sectors(256, rng, 1e-3);
  for (const auto& sectors : {sliver, many}) {
    const CreasePattern p = build_or_throw(gen::single_vertex(sectors));
    const ClosureSystem sys(p);
    EXPECT_EQ(mobility(sys, FoldState::flat(p)).dof, static_cast<int>(sectors.size()) - 2);
    std::uniform_real_distribution<double> u(-0.3, 0.3);
    FoldState s = FoldState::flat(p);
    for (Eigen::Index i = 0; i < s.angles.size(); ++i) s.angles[i] = u(rng);
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> J;
    sys.evaluate(s, r, J);
    EXPECT_TRUE(r.allFinite());
    EXPECT_TRUE(Eigen::MatrixXd(J).allFinite());
    const ProjectionResult pr = project(sys, s, {1e-10, 300, false, {}});
    EXPECT_TRUE(pr.state.angles.allFinite());
    EXPECT_TRUE(std::isfinite(pr.error));
    EXPECT_TRUE(pr.status.ok()) << sectors.size() << ": " << pr.status.message;
  }
  // Fold angles at and near ±180°: a degree-4 vertex folded flat.
  const CreasePattern p = build_or_throw(gen::single_vertex({M_PI / 2, M_PI / 2, M_PI / 2, M_PI / 2}));
  const ClosureSystem sys(p);
  for (double a : {M_PI, M_PI - 1e-12, -M_PI, M_PI - 1e-6}) {
    FoldState s = FoldState::flat(p);
    s.angles << a, 0, a, 0;  // one straight crease line folded flat: both halves alike
    Eigen::VectorXd r;
    Eigen::SparseMatrix<double> J;
    sys.evaluate(s, r, J);
    EXPECT_TRUE(r.allFinite()) << a;
    EXPECT_TRUE(Eigen::MatrixXd(J).allFinite()) << a;
    EXPECT_LT(sys.max_error(s), 1e-9) << a;
    FoldState broken = s;
    broken.angles[1] = 1.0;
    EXPECT_TRUE(std::isfinite(sys.max_error(broken)));
    EXPECT_GT(sys.max_error(broken), 0.1);
  }
}

}  // namespace
