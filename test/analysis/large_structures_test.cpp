// The stiffness solver on the cube beam of issue 20 and the clamped plate (bench_stiffness_ceres's
// structures) at the sizes the benchmark runs, against invariants that do not share its code:
// Maxwell–Betti reciprocity, the cantilever's L³ law, the linear limit of the nonlinear solve,
// and mirror symmetry.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "foldkit/analysis/solver.hpp"
#include "stiffness_problems.hpp"

namespace {

using foldkit::analysis::Problem;
using foldkit::analysis::solve;
using foldkit::analysis::SolveOptions;
using foldkit::analysis::SolveResult;

SolveOptions linear() {
  SolveOptions o;
  o.linear = true;
  return o;
}

// The linear displacement of module `at` along `direction` under a unit load at module `on`
// along the same direction (at the centroids).
double influence(Problem p, int on, int at, const Eigen::Vector3d& direction) {
  p.loads = {{on, direction, p.structure.modules[static_cast<std::size_t>(on)].centroid}};
  const SolveResult r = solve(p, linear());
  EXPECT_TRUE(r.status.ok()) << r.status.message;
  return r.modules[static_cast<std::size_t>(at)].displacement.dot(direction);
}

double tip_deflection(int modules) {
  const Problem p = foldkit::bench_stiffness::beam_problem(modules);
  const SolveResult r = solve(p, linear());
  EXPECT_TRUE(r.status.ok()) << r.status.message;
  return r.modules.back().displacement.norm() / p.loads.front().force.norm();  // per newton
}

// A 500-cube beam (3,000 modules, condition ≈ 9e11): the residual of one LU solve used to sit
// a few times above the old round-off floor, and --linear called the system singular.
TEST(CubeBeam, LongBeamIsSolvedLinearAndNonlinear) {
  const Problem p = foldkit::bench_stiffness::beam_problem(3000);
  const SolveResult lin = solve(p, linear());
  ASSERT_TRUE(lin.status.ok()) << lin.status.message;
  EXPECT_LE(lin.residual_norm, std::max(lin.residual_floor, 1e-8));
  SolveOptions newton;
  newton.estimate_condition = false;
  const SolveResult r = solve(p, newton);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  EXPECT_LE(r.iterations, 12);
  // The load turns the beam by about 0.1 rad (beam_problem's scaling): the nonlinear answer is
  // close to the linear one, but not equal.
  const double tip = r.modules.back().displacement.norm(), tip_linear = lin.modules.back().displacement.norm();
  EXPECT_NEAR(tip / tip_linear, 1.0, 0.05);
  EXPECT_GT(std::abs(tip / tip_linear - 1.0), 1e-6);
}

// Betti: the displacement at B from a load at A equals the displacement at A from the same load
// at B. It holds only if the assembled stiffness is symmetric and the solve is accurate.
TEST(CubeBeam, DisplacementsAreReciprocal) {
  const Problem p = foldkit::bench_stiffness::beam_problem(1200);
  const Eigen::Vector3d across = p.loads.front().force.normalized();
  const int tip = static_cast<int>(p.structure.modules.size()) - 1, middle = tip / 2;
  const double ab = influence(p, middle, tip, across), ba = influence(p, tip, middle, across);
  EXPECT_GT(std::abs(ab), 0.0);
  EXPECT_NEAR(ab / ba, 1.0, 1e-6);
}

// A slender cantilever's tip deflection under an end load grows as L³ (Euler–Bernoulli; shear
// adds a term in L that fades with length). The free length is the beam less its clamped cube:
// 149 and 299 cubes, so the ratio is (299/149)³ ≈ 8.08, to within 1 %.
TEST(CubeBeam, TipDeflectionGrowsAsLengthCubed) {
  const double ratio = tip_deflection(1800) / tip_deflection(900);
  EXPECT_NEAR(ratio, std::pow(299.0 / 149.0, 3), 0.08);
}

// A 2,000-tile plate clamped along one edge, its two free corners loaded alike: the nonlinear
// answer is mirror-symmetric about the plate's mid-line (displacements reflect; rotation vectors,
// being axial, reflect with the opposite sign), to round-off, although nothing in the solver
// knows the symmetry.
TEST(Plate, SymmetricLoadsGiveMirroredDisplacements) {
  Problem p = foldkit::bench_stiffness::grid_problem(2000);
  const auto& m = p.structure.modules;
  double lo = m.front().centroid.y(), hi = lo;
  for (const auto& module : m) lo = std::min(lo, module.centroid.y()), hi = std::max(hi, module.centroid.y());
  std::map<std::pair<long, long>, std::size_t> at;  // centroid (x, y) in units of 1e-9 → module
  const auto key = [](double x, double y) { return std::make_pair(std::lround(x * 1e9), std::lround(y * 1e9)); };
  for (std::size_t i = 0; i < m.size(); ++i) at[key(m[i].centroid.x(), m[i].centroid.y())] = i;
  const int corner = p.loads.front().module;
  const auto mirror_of = [&](std::size_t i) { return at.at(key(m[i].centroid.x(), lo + hi - m[i].centroid.y())); };
  const std::size_t other = mirror_of(static_cast<std::size_t>(corner));
  ASSERT_NE(other, static_cast<std::size_t>(corner));
  p.loads.push_back({static_cast<int>(other), p.loads.front().force, m[other].centroid});
  SolveOptions o;
  o.estimate_condition = false;
  const SolveResult r = solve(p, o);
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_GT(r.max_displacement, 0.0);
  const Eigen::Vector3d reflect(1.0, -1.0, 1.0);
  double worst = 0.0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    const std::size_t j = mirror_of(i);
    worst = std::max(worst, (r.modules[i].displacement - reflect.cwiseProduct(r.modules[j].displacement)).norm());
    worst = std::max(worst, p.structure.tile * (r.modules[i].rotation + reflect.cwiseProduct(r.modules[j].rotation)).norm());
  }
  EXPECT_LE(worst, 1e-8 * r.max_displacement);
}

}  // namespace
