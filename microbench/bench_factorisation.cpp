// The sparse factorisation behind two of issue 20's shortfalls, ours against CHOLMOD's
// supernodal Cholesky (SuiteSparse, through Eigen's CholmodSupport; its own choice of AMD or
// METIS ordering), to decide whether SuiteSparse should become a dependency of a library layer:
// - BM_FactorMiura_*: JᵀJ + εI of a folded Miura n × n, what geometry::LeastNormSolver factorises
//   at every step of projected folding (issue 20, item 2: 100×100 in ≤ 5 s);
// - BM_FactorPlate_*: the Jacobi-scaled stiffness tangent of the clamped plate of tiles, what
//   analysis::solve factorises at every Newton iteration (item 4: 10⁵ modules in ≤ 10 s).
// Ours is Eigen's SimplicialLDLT with AMD, as both libraries use it. Each entry times the
// numeric factorisation only (the symbolic one is done once, before timing, as in the solvers);
// `factor_nnz` counts the factor's entries.
#include <cmath>

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <benchmark/benchmark.h>

#include "bench_patterns.hpp"
#include "foldkit/geometry/closure.hpp"
#include "stiffness_problems.hpp"

namespace {

using namespace foldkit;
using Sparse = Eigen::SparseMatrix<double>;

Sparse miura_normal_matrix(int n) {
  const auto p = bench::pattern_for(-n);
  const geometry::ClosureSystem sys(p);
  const auto state = bench::closed_miura(p, sys, 0.3);
  Eigen::VectorXd r;
  Sparse j;
  sys.evaluate(state, r, j);
  Sparse a = Sparse(j.transpose()) * j;
  const double eps = 1e-10 * a.diagonal().maxCoeff();
  for (Eigen::Index i = 0; i < a.rows(); ++i) a.coeffRef(i, i) += eps;
  a.makeCompressed();
  return a;
}

Sparse plate_tangent(int modules) {
  const auto p = bench_stiffness::grid_problem(modules);
  const analysis::EquilibriumSystem sys(p);
  const Sparse h = sys.tangent(Eigen::VectorXd::Zero(sys.size()), 1.0, false);
  const Eigen::VectorXd s = h.diagonal().cwiseAbs().cwiseSqrt().cwiseInverse();
  Sparse scaled = s.asDiagonal() * h * s.asDiagonal();
  scaled.makeCompressed();
  return scaled;
}

Sparse make(const std::string& family, int size) { return family == "miura" ? miura_normal_matrix(size) : plate_tangent(size); }

using Ours = Eigen::SimplicialLDLT<Sparse, Eigen::Lower, Eigen::AMDOrdering<int>>;
using Cholmod = Eigen::CholmodSupernodalLLT<Sparse, Eigen::Lower>;

double factor_nnz(const Ours& f) { return static_cast<double>(f.matrixL().nestedExpression().nonZeros()); }
double factor_nnz(Cholmod& f) { return f.cholmod().lnz; }  // from its analysis

// The numeric factorisation of `family`'s matrix at the benchmark's size by Factor.
template <class Factor>
void factorise(benchmark::State& state, const std::string& family) {
  const Sparse a = make(family, static_cast<int>(state.range(0)));
  Factor f;
  f.analyzePattern(a);
  for (auto _ : state) {
    f.factorize(a);
    benchmark::DoNotOptimize(f.info());
  }
  if (f.info() != Eigen::Success) state.SkipWithError("the factorisation failed");
  state.counters["unknowns"] = static_cast<double>(a.rows());
  state.counters["factor_nnz"] = factor_nnz(f);
}

void BM_FactorMiura_Ours(benchmark::State& s) { factorise<Ours>(s, "miura"); }
void BM_FactorMiura_Cholmod(benchmark::State& s) { factorise<Cholmod>(s, "miura"); }
void BM_FactorPlate_Ours(benchmark::State& s) { factorise<Ours>(s, "plate"); }
void BM_FactorPlate_Cholmod(benchmark::State& s) { factorise<Cholmod>(s, "plate"); }

}  // namespace

BENCHMARK(BM_FactorMiura_Ours)->Arg(40)->Arg(70)->Arg(100)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FactorMiura_Cholmod)->Arg(40)->Arg(70)->Arg(100)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FactorPlate_Ours)->Arg(2000)->Arg(10000)->Arg(30000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FactorPlate_Cholmod)->Arg(2000)->Arg(10000)->Arg(30000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
