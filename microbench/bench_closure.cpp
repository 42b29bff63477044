// Closure residual + Jacobian, side by side:
//   BM_Closure_Ours     — the analytic sparse Jacobian, refilled in place;
//   BM_Closure_Baseline — central differences of the residual into a dense matrix (what OMPL's
//                         Constraint::jacobian does by default).
#include <random>

#include <benchmark/benchmark.h>

#include "foldkit/geometry/closure.hpp"
#include "bench_patterns.hpp"

namespace {

using namespace foldkit::geometry;

using foldkit::bench::pattern_for;
using foldkit::bench::some_state;

void BM_Closure_Ours(benchmark::State& state) {
  const CreasePattern p = pattern_for(static_cast<int>(state.range(0)));
  const ClosureSystem sys(p);
  const FoldState s = some_state(p);
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> J;
  for (auto _ : state) {
    sys.evaluate(s, r, J);
    benchmark::DoNotOptimize(J.valuePtr());
  }
  state.counters["creases"] = static_cast<double>(p.joints().size());
}

void BM_Closure_Baseline(benchmark::State& state) {
  const CreasePattern p = pattern_for(static_cast<int>(state.range(0)));
  const ClosureSystem sys(p);
  FoldState s = some_state(p);
  Eigen::MatrixXd J(sys.rows(), sys.cols());
  const double h = 1e-6;
  for (auto _ : state) {
    const Eigen::VectorXd r = sys.residual(s);
    for (Eigen::Index j = 0; j < sys.cols(); ++j) {
      const double x = s.angles[j];
      s.angles[j] = x + h;
      const Eigen::VectorXd plus = sys.residual(s);
      s.angles[j] = x - h;
      J.col(j) = (plus - sys.residual(s)) / (2 * h);
      s.angles[j] = x;
    }
    benchmark::DoNotOptimize(r.data());
    benchmark::DoNotOptimize(J.data());
  }
  state.counters["creases"] = static_cast<double>(p.joints().size());
}

// Degree 8 and 64 single vertices; −10, −40: Miura-ori 10 × 10 and 40 × 40 (3,120 creases).
BENCHMARK(BM_Closure_Ours)->Arg(8)->Arg(64)->Arg(-10)->Arg(-40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Closure_Baseline)->Arg(8)->Arg(64)->Arg(-10)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Closure_Baseline)->Arg(-40)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
