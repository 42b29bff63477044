// Mobility (creases − rank of the closure Jacobian, `foldkit dof`) of Miura-ori sheets, side by
// side on the same Jacobian (issue 20, item 3):
//   BM_Mobility_Ours     — geometry::mobility: LeastNormSolver::decide_rank (dense SVD up to 400
//                          columns; above, SuiteSparse QR's count with its certificate, or inverse
//                          subspace iteration on JᵀJ + εI near the threshold);
//   BM_Mobility_InverseSubspace — decide_rank with SparseRankMethod::InverseSubspace, what `dof`
//                          used above 400 creases before issue 35;
//   BM_Mobility_SPQR     — SuiteSparse QR (Eigen's SPQRSupport), the rank-revealing sparse QR a
//                          user would pick, with the same absolute tolerance;
//   BM_Mobility_SparseQR — Eigen's SparseQR (COLAMD), what `foldkit dof` used before.
// Each includes evaluating J at the state. Counters: rank, and `agrees` = 1 when the rank equals
// ours (and, up to 400 columns, the dense JacobiSVD count). The state is the flat sheet, where
// the rank drops (what `foldkit dof` reports by default), or ("folded") a closed state at 0.3 rad.
#include <stdexcept>

#include <Eigen/SPQRSupport>
#include <Eigen/SVD>
#include <Eigen/SparseQR>
#include <benchmark/benchmark.h>

#include "bench_patterns.hpp"
#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/mobility.hpp"

namespace {

namespace geo = foldkit::geometry;
using Sparse = Eigen::SparseMatrix<double>;

struct Case {
  geo::CreasePattern pattern;
  geo::ClosureSystem system;
  geo::FoldState state;
  geo::Mobility ours;  // the reference count and tolerance
};

// range(0): Miura n × n; range(1): 0 flat, 1 folded (closed, every crease at least 0.3 rad).
Case make_case(const benchmark::State& st) {
  const int n = static_cast<int>(st.range(0));
  geo::CreasePattern p = foldkit::bench::pattern_for(-n);
  geo::ClosureSystem sys(p);
  geo::FoldState s = st.range(1) ? foldkit::bench::closed_miura(p, sys, 0.3) : geo::FoldState::flat(p);
  const geo::Mobility m = geo::mobility(sys, s);
  return {std::move(p), std::move(sys), std::move(s), m};
}

Sparse jacobian(const Case& c) {
  Eigen::VectorXd r;
  Sparse J;
  c.system.evaluate(c.state, r, J);
  J.makeCompressed();
  return J;
}

void report(benchmark::State& st, const Case& c, int rank) {
  st.counters["creases"] = c.ours.creases;
  st.counters["rank"] = rank;
  st.counters["dof"] = c.ours.creases - rank;
  st.counters["agrees"] = rank == c.ours.rank ? 1 : 0;
}

void BM_Mobility_Ours(benchmark::State& st) {
  const Case c = make_case(st);
  geo::Mobility m;
  for (auto _ : st) {
    m = geo::mobility(c.system, c.state);
    benchmark::DoNotOptimize(m.rank);
  }
  report(st, c, m.rank);
  st.counters["rank_gap"] = m.decision.gap();
  st.counters["sparse_qr"] = m.method == "sparse-qr" ? 1 : 0;  // 0: dense SVD, or near the threshold
  if (c.ours.creases <= 400) {
    // Dense oracle: singular values of J above the same absolute tolerance.
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Eigen::MatrixXd(jacobian(c)));
    int dense = 0;
    for (Eigen::Index i = 0; i < svd.singularValues().size(); ++i) dense += svd.singularValues()[i] > m.tolerance;
    st.counters["agrees"] = dense == m.rank ? 1 : 0;
  }
}

void BM_Mobility_InverseSubspace(benchmark::State& st) {
  const Case c = make_case(st);
  geo::RankDecision d;
  for (auto _ : st) {
    const Sparse J = jacobian(c);
    geo::LeastNormSolver solver;
    d = solver.decide_rank(J, geo::kMobilityTolerance, 400, 1.0, geo::SparseRankMethod::InverseSubspace);
    benchmark::DoNotOptimize(d.rank);
  }
  report(st, c, d.rank);
  st.counters["rank_gap"] = d.gap();
}

void BM_Mobility_SPQR(benchmark::State& st) {
  const Case c = make_case(st);
  long rank = 0;
  for (auto _ : st) {
    const Sparse J = jacobian(c);
    Eigen::SPQR<Sparse> qr;
    qr.setPivotThreshold(c.ours.tolerance);
    qr.compute(J);
    if (qr.info() != Eigen::Success) throw std::runtime_error("SPQR failed");
    rank = qr.rank();
    benchmark::DoNotOptimize(rank);
  }
  report(st, c, static_cast<int>(rank));
}

void BM_Mobility_SparseQR(benchmark::State& st) {
  const Case c = make_case(st);
  long rank = 0;
  for (auto _ : st) {
    const Sparse J = jacobian(c);
    Eigen::SparseQR<Sparse, Eigen::COLAMDOrdering<int>> qr;
    qr.setPivotThreshold(c.ours.tolerance);
    qr.compute(J);
    if (qr.info() != Eigen::Success) throw std::runtime_error("SparseQR failed");
    rank = qr.rank();
    benchmark::DoNotOptimize(rank);
  }
  report(st, c, static_cast<int>(rank));
}

void sizes(benchmark::internal::Benchmark* b, int largest) {
  for (int n : {10, 20, 40, 70, 100})
    if (n <= largest) b->Args({n, 0});
  for (int n : {10, 20, 40})
    if (n <= largest) b->Args({n, 1});
  b->Unit(benchmark::kMillisecond)->Iterations(1)->Repetitions(3)->ReportAggregatesOnly(true);
}

}  // namespace

BENCHMARK(BM_Mobility_Ours)->Apply([](auto* b) { sizes(b, 100); });
BENCHMARK(BM_Mobility_InverseSubspace)->Apply([](auto* b) { sizes(b, 100); });
BENCHMARK(BM_Mobility_SPQR)->Apply([](auto* b) { sizes(b, 100); });
// SparseQR fills in: 8 s and 220 MB at 40 × 40 (issue 20), so it stops there.
BENCHMARK(BM_Mobility_SparseQR)->Apply([](auto* b) { sizes(b, 40); });

BENCHMARK_MAIN();
