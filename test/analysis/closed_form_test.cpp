// The solver against closed forms that share no code with it: rigid links on rotational springs.
#include <cmath>

#include <gtest/gtest.h>

#include "foldkit/analysis/solver.hpp"
#include "foldkit/geometry/generators.hpp"

namespace {

using namespace foldkit;
using analysis::ConnectionKind;
using Eigen::Vector3d;

// A flat strip of `tiles` unit squares along +x, the first fixed; the hinges are stiff in every
// direction but about their line, where they have stiffness k.
analysis::Problem strip_problem(int tiles, double k, double k_translation = 1e9) {
  const auto pattern = geometry::build_or_throw(geometry::generators::strip(tiles));
  analysis::Problem p;
  p.structure = analysis::build_structure(pattern, geometry::FoldState::flat(pattern));
  analysis::Matrix6 hinge = analysis::Matrix6::Zero();
  hinge.diagonal() << k_translation, k_translation, k_translation, 1e4, 1e4, k;
  p.stiffness[static_cast<int>(ConnectionKind::Hinged)] = hinge;
  p.fixed.assign(static_cast<std::size_t>(tiles), false);
  p.fixed[0] = true;
  return p;
}

// Displacement of a point of a module (given in the unloaded coordinates) from the solution.
Vector3d point_displacement(const analysis::Problem& p, const analysis::SolveResult& r, int module, const Vector3d& point) {
  const auto& m = r.modules[static_cast<std::size_t>(module)];
  const Vector3d arm = point - p.structure.modules[static_cast<std::size_t>(module)].centroid;
  const double angle = m.rotation.norm();
  const Eigen::Matrix3d rot =
      angle > 0 ? Eigen::AngleAxisd(angle, m.rotation / angle).toRotationMatrix() : Eigen::Matrix3d::Identity();
  return m.displacement + rot * arm - arm;
}

TEST(ClosedForm, StripTipLoadSmallDisplacement) {
  // δ = P Σ dᵢ²/k + (hinges)·P/k_t, dᵢ the distance from hinge i to the load.
  for (int tiles : {2, 5, 12}) {
    const double k = 3.0, kt = 1e6, load = 1e-4;
    auto p = strip_problem(tiles, k, kt);
    const Vector3d tip(tiles, 0.5, 0.0);
    p.loads.push_back({tiles - 1, Vector3d(0, 0, -load), tip});
    double sum = 0.0;
    for (int i = 1; i < tiles; ++i) sum += (tiles - i) * (tiles - i);
    const double expected = load * sum / k + (tiles - 1) * load / kt;
    for (bool linear : {true, false}) {
      analysis::SolveOptions o;
      o.linear = linear;
      const auto r = analysis::solve(p, o);
      ASSERT_TRUE(r.status.ok()) << r.status.message;
      const Vector3d d = point_displacement(p, r, tiles - 1, tip);
      EXPECT_NEAR(-d.z(), expected, expected * (linear ? 1e-7 : 1e-4)) << tiles << (linear ? " linear" : " nonlinear");
    }
  }
}

TEST(ClosedForm, SingleHingeLargeRotation) {
  // k·θ = P·L·cos θ for a dead load P perpendicular to the flat sheet at distance L.
  for (double pl_over_k : {0.5, 1.0, 3.0, 10.0}) {
    const double k = 2.0, length = 1.0;
    auto p = strip_problem(2, k);
    p.loads.push_back({1, Vector3d(0, 0, pl_over_k * k / length), Vector3d(1.0 + length, 0.5, 0.0)});
    const auto r = analysis::solve(p);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    const double theta = r.modules[1].rotation.norm();
    EXPECT_NEAR(k * theta, pl_over_k * k * std::cos(theta), 1e-6) << pl_over_k;
    EXPECT_NEAR(r.modules[1].rotation.y(), -theta, 1e-9);  // an upward load turns the free tile up: −y
  }
}

TEST(ClosedForm, DiscreteElastica) {
  // N links of length a on springs k = EI/a (the first at the wall), tip dead load with
  // α = PL²/EI = 1: δ/L = 0.38278 (N = 5), 0.34204 (N = 10) (NOTES.md, "Lumped 6-DOF springs").
  for (const auto& [n, expected] : {std::pair{5, 0.38278}, std::pair{10, 0.34204}}) {
    const double a = 1.0, k = 1.0, length = n * a;
    const double load = k * a / (length * length);  // P = EI/L², EI = k·a
    auto p = strip_problem(n + 1, k);
    const Vector3d tip((n + 1) * a, 0.5, 0.0);
    p.loads.push_back({n, Vector3d(0, 0, -load), tip});
    const auto r = analysis::solve(p);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    const Vector3d d = point_displacement(p, r, n, tip);
    EXPECT_NEAR(-d.z() / length, expected, 6e-6) << n;
    EXPECT_LE(r.residual_norm, std::max(1e-10, r.residual_floor));
    EXPECT_LT(r.residual_floor, 1e-3);
  }
}

TEST(ClosedForm, LinearAndNonlinearAgreeForSmallLoads) {
  auto p = strip_problem(6, 1.0, 1e6);
  p.loads.push_back({5, Vector3d(1e-7, 2e-7, -3e-7), Vector3d(6.0, 0.2, 0.0)});
  analysis::SolveOptions lin;
  lin.linear = true;
  const auto a = analysis::solve(p, lin), b = analysis::solve(p);
  ASSERT_TRUE(a.status.ok() && b.status.ok());
  for (std::size_t i = 0; i < a.modules.size(); ++i)
    EXPECT_LT((a.modules[i].displacement - b.modules[i].displacement).norm(), 1e-5 * a.max_displacement + 1e-15);
}

TEST(ClosedForm, TinyLoadOnStiffSpringsIsNotRoundedToZero) {
  // Translational springs 1e9 times stiffer than the hinges: the load is far below the round-off
  // floor of the spring forces at any displaced state, yet the hinges still turn by P·dᵢ/k. The
  // unloaded state is exact, so it must not pass for the solution.
  constexpr int kTiles = 11;
  for (double load : {1e-7, 1e-9}) {
    auto p = strip_problem(kTiles, 1.0, 1e9);
    const Vector3d tip(kTiles, 0.5, 0.0);
    p.loads.push_back({kTiles - 1, Vector3d(0, 0, -load), tip});
    double sum = 0.0;
    for (int i = 1; i < kTiles; ++i) sum += (kTiles - i) * (kTiles - i);
    const double expected = load * sum + (kTiles - 1) * load / 1e9;
    for (bool linear : {true, false}) {
      analysis::SolveOptions o;
      o.linear = linear;
      const auto r = analysis::solve(p, o);
      ASSERT_TRUE(r.status.ok()) << r.status.message << (linear ? " linear" : " nonlinear") << " load " << load;
      // Ill-conditioning (ratio 1e9) leaves about four digits.
      const auto& m = r.modules[kTiles - 1];
      const Vector3d arm = tip - p.structure.modules[kTiles - 1].centroid;
      const double d = linear ? -(m.displacement + m.rotation.cross(arm)).z() : -point_displacement(p, r, kTiles - 1, tip).z();
      EXPECT_NEAR(d, expected, 1e-4 * expected) << (linear ? "linear" : "nonlinear") << " load " << load;
    }
  }
}

TEST(ClosedForm, LinearSolveAcceptedAtLargeLoads) {
  // The linear model at a large load (α = 10 on the 10-link elastica): the solution's residual is
  // judged against the round-off floor at the solution, not at the unloaded state.
  auto p = strip_problem(11, 1.0, 1e6);
  const double load = 0.1;
  const Vector3d tip(11.0, 0.5, 0.0);
  p.loads.push_back({10, Vector3d(0, 0, -load), tip});
  analysis::SolveOptions o;
  o.linear = true;
  const auto r = analysis::solve(p, o);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  double sum = 0.0;
  for (int i = 1; i < 11; ++i) sum += (11 - i) * (11 - i);
  const double expected = load * sum + 10 * load / 1e6;
  const auto& m = r.modules[10];  // the linear model's small-rotation displacement of the tip
  const Vector3d arm = tip - p.structure.modules[10].centroid;
  EXPECT_NEAR(-(m.displacement + m.rotation.cross(arm)).z(), expected, 1e-6 * expected);
}

}  // namespace
