// Sparse Newton (analysis::solve, BM_Stiffness_Ours) against MINPACK's hybrd as ported in Eigen
// (HybridNonLinearSolver, the method behind MATLAB's fsolve; BM_Stiffness_Baseline) on the same
// equilibrium equations: a flat grid of rows × cols tiles, the first column fixed, a transverse corner load that turns
// the free edge by about 0.1 rad. Counters: modules, residual (scaled ∞-norm), iterations.
#include <cmath>

#include <benchmark/benchmark.h>
#include <unsupported/Eigen/NonLinearOptimization>

#include "stiffness_problems.hpp"

namespace {

using namespace foldkit;

using bench_stiffness::grid_problem;

struct Functor {
  const analysis::EquilibriumSystem& sys;
  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& r) const {
    r = sys.residual(x);
    return 0;
  }
};

void BM_Stiffness_Ours(benchmark::State& state) {
  const auto p = grid_problem(static_cast<int>(state.range(0)));
  analysis::SolveOptions o;
  o.estimate_condition = false;
  analysis::SolveResult r;
  for (auto _ : state) {
    r = analysis::solve(p, o);
    benchmark::DoNotOptimize(r.max_displacement);
  }
  state.counters["modules"] = static_cast<double>(p.structure.modules.size());
  state.counters["residual"] = r.residual_norm;
  state.counters["iterations"] = r.iterations;
  state.counters["converged"] = r.status.ok();
}

void BM_Stiffness_Baseline(benchmark::State& state) {
  const auto p = grid_problem(static_cast<int>(state.range(0)));
  const analysis::EquilibriumSystem sys(p);
  Eigen::VectorXd x;
  int evaluations = 0;
  for (auto _ : state) {
    Functor f{sys};
    Eigen::HybridNonLinearSolver<Functor> solver(f);
    solver.parameters.xtol = 1e-12;
    solver.parameters.maxfev = 200 * (sys.size() + 1);
    x = Eigen::VectorXd::Zero(sys.size());
    solver.solveNumericalDiff(x);
    evaluations = static_cast<int>(solver.nfev);
  }
  state.counters["modules"] = static_cast<double>(p.structure.modules.size());
  state.counters["residual"] = sys.residual(x).lpNorm<Eigen::Infinity>();
  state.counters["evaluations"] = evaluations;
}

}  // namespace

BENCHMARK(BM_Stiffness_Ours)->Arg(10)->Arg(50)->Arg(100)->Arg(200)->Arg(500)->Arg(1000)->Arg(2000)->Unit(benchmark::kMillisecond);
// hybrd is O(n³) per Jacobian with n = 6 × modules: capped at 500 modules (about a minute there).
BENCHMARK(BM_Stiffness_Baseline)->Arg(10)->Arg(50)->Arg(100)->Arg(200)->Arg(500)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_MAIN();
