// The constrained planning space's projection (statespaces::ClosureConstraint::project, what
// OMPL's ProjectedStateSpace calls for every sample and every step of a geodesic), side by side:
//   BM_ConstraintProjection_Ours     — least-norm Newton steps from a sparse LDLᵀ of JᵀJ + εI,
//                                       its ordering kept between steps (geometry::LeastNormSolver);
//   BM_ConstraintProjection_Baseline — the same Newton iteration with the dense Jacobian and
//                                       Eigen's complete orthogonal decomposition per step (what
//                                       ClosureConstraint::project did before; OMPL's own
//                                       Constraint::project uses a dense JacobiSVD).
// Start: a Miura-ori of n × n facets folded to a closed state by continuation (the constraint's
// reference), then disturbed by ±0.02 rad. Same constraint, tolerance 1e-8 and iteration cap.
// Counters: error (residual norm reached), converged, creases, rows (co-dimension).
#include <map>
#include <memory>
#include <random>

#include <Eigen/QR>
#include <benchmark/benchmark.h>

#include "foldkit/statespaces/closure_constraint.hpp"

#include "bench_patterns.hpp"

namespace {

using namespace foldkit;

struct Problem {
  geometry::CreasePattern pattern;
  std::unique_ptr<statespaces::ClosureConstraint> constraint;
  Eigen::VectorXd start;
};

const Problem& problem(int n) {
  static std::map<int, std::unique_ptr<Problem>> cache;
  auto& slot = cache[n];
  if (slot) return *slot;
  slot = std::make_unique<Problem>(Problem{geometry::build_or_throw(geometry::generators::miura(n, n)), nullptr, {}});
  const geometry::CreasePattern& p = slot->pattern;
  const geometry::FoldState s = bench::closed_miura(p, geometry::ClosureSystem(p), 1.0);
  slot->constraint = std::make_unique<statespaces::ClosureConstraint>(p, s);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.02, 0.02);
  slot->start = s.angles;
  for (Eigen::Index i = 0; i < slot->start.size(); ++i) slot->start[i] += u(rng);
  return *slot;
}

void report(benchmark::State& st, const Problem& pr, const Eigen::VectorXd& x, bool converged) {
  Eigen::VectorXd f(pr.constraint->getCoDimension());
  pr.constraint->function(x, f);
  st.counters["creases"] = static_cast<double>(pr.pattern.joints().size());
  st.counters["rows"] = static_cast<double>(pr.constraint->getCoDimension());
  st.counters["error"] = f.norm();
  st.counters["converged"] = converged;
}

void BM_ConstraintProjection_Ours(benchmark::State& st) {
  const Problem& pr = problem(static_cast<int>(st.range(0)));
  Eigen::VectorXd x;
  bool converged = false;
  for (auto _ : st) {
    x = pr.start;
    converged = pr.constraint->project(x);
    benchmark::DoNotOptimize(x.data());
  }
  report(st, pr, x, converged);
}

void BM_ConstraintProjection_Baseline(benchmark::State& st) {
  const Problem& pr = problem(static_cast<int>(st.range(0)));
  const statespaces::ClosureConstraint& c = *pr.constraint;
  const double tolerance2 = c.getTolerance() * c.getTolerance();
  Eigen::VectorXd x, f(c.getCoDimension());
  Eigen::MatrixXd j(c.getCoDimension(), pr.start.size());
  bool converged = false;
  for (auto _ : st) {
    x = pr.start;
    c.function(x, f);
    converged = true;
    for (unsigned int iteration = 0; !(f.squaredNorm() <= tolerance2); ++iteration) {
      if (iteration >= c.getMaxIterations()) {
        converged = false;
        break;
      }
      c.jacobian(x, j);
      x -= j.completeOrthogonalDecomposition().solve(f);
      c.function(x, f);
    }
    benchmark::DoNotOptimize(x.data());
  }
  report(st, pr, x, converged);
}

}  // namespace

BENCHMARK(BM_ConstraintProjection_Ours)->Arg(4)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ConstraintProjection_Baseline)->Arg(4)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
