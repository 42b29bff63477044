// Our stiffness solver (analysis::solve: Newton, sparse LDLᵀ, load stepping) against Ceres, the
// sparse nonlinear least-squares solver a user would pick (issue 20, item 4), on the same
// equilibrium equations and to the same residual.
//
// Fair by construction: Ceres gets our residual and our analytic tangent (through an
// EvaluationCallback that evaluates them once per point, and one 6-row residual block per free
// module), our retraction as its manifold, SPARSE_NORMAL_CHOLESKY on SuiteSparse, one thread
// (ours has one), and it stops as soon as the scaled residual (∞-norm) is at most what ours
// reached. What differs is the solver: Levenberg–Marquardt on JᵀJ against Newton on J's symmetric part.
//
// Structures: the cube beam of issue 20 (BM_StiffnessBeam_*, 48 to 10,000 modules) and the clamped
// plate of bench_stiffness (BM_StiffnessPlate_*). Baseline: Ceres's default Levenberg–Marquardt;
// CeresGaussNewton: a huge initial trust region and non-monotonic steps, nearly Gauss–Newton.
// Counters: modules, unknowns, residual (scaled ∞-norm reached), iterations; ours also the
// condition estimate of the tangent (the normal equations' is its square), Ceres's `reached`
// (0: it stopped, after 500 iterations or without progress, above our residual).
//
// Not in scripts/microbench.sh: it is built only where Ceres is installed, and its baselines
// take minutes (they run out their 500 iterations from 1,000 modules on).
//
//   bench_stiffness_ceres                      the side-by-side table
//   bench_stiffness_ceres --error-vs-time=F    residual against time for both, CSV to F
//   FOLDKIT_CERES_REPORT=1 bench_stiffness_ceres …   also prints Ceres's full report per solve
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <ceres/ceres.h>

#include "stiffness_problems.hpp"

namespace {

using namespace foldkit;
using Clock = std::chrono::steady_clock;
using RowSparse = Eigen::SparseMatrix<double, Eigen::RowMajor>;

// The residual and tangent at Ceres's current point, computed once per point for every block.
class SharedEvaluation : public ceres::EvaluationCallback {
 public:
  SharedEvaluation(const analysis::EquilibriumSystem& sys, const Eigen::VectorXd& x) : sys_(sys), x_(x) {}
  void PrepareForEvaluation(bool jacobians, bool new_point) override {
    if (new_point || !have_residual_) {
      r_ = sys_.residual(x_);
      have_residual_ = true;
      have_tangent_ = false;
    }
    if (jacobians && !have_tangent_) {
      h_ = sys_.tangent(x_);
      have_tangent_ = true;
    }
  }
  const Eigen::VectorXd& residual() const { return r_; }
  const RowSparse& tangent() const { return h_; }

 private:
  const analysis::EquilibriumSystem& sys_;
  const Eigen::VectorXd& x_;  // Ceres's parameter blocks live here
  Eigen::VectorXd r_;
  RowSparse h_;
  bool have_residual_ = false, have_tangent_ = false;
};

// Module k's six equations; its parameter blocks are k and every free module a spring ties to it.
class ModuleEquations : public ceres::CostFunction {
 public:
  ModuleEquations(const SharedEvaluation& eval, int k, std::vector<int> blocks) : eval_(eval), k_(k), blocks_(std::move(blocks)) {
    set_num_residuals(6);
    for (std::size_t i = 0; i < blocks_.size(); ++i) mutable_parameter_block_sizes()->push_back(6);
  }
  bool Evaluate(double const* const*, double* residuals, double** jacobians) const override {
    Eigen::Map<Eigen::Matrix<double, 6, 1>> r(residuals);
    r = eval_.residual().segment<6>(6 * k_);
    if (!jacobians) return true;
    for (std::size_t b = 0; b < blocks_.size(); ++b)
      if (jacobians[b]) std::fill(jacobians[b], jacobians[b] + 36, 0.0);
    const RowSparse& h = eval_.tangent();
    for (int i = 0; i < 6; ++i)
      for (RowSparse::InnerIterator it(h, 6 * k_ + i); it; ++it) {
        const int module = static_cast<int>(it.col()) / 6;
        const auto pos = std::find(blocks_.begin(), blocks_.end(), module) - blocks_.begin();
        if (jacobians[pos]) jacobians[pos][6 * i + it.col() % 6] = it.value();
      }
    return true;
  }

 private:
  const SharedEvaluation& eval_;
  int k_;
  std::vector<int> blocks_;  // free-module indices, in parameter-block order
};

// Our retraction (a left perturbation applied as a screw motion). The cost functions already
// return ∂r/∂(left perturbation), so the Jacobian of Plus at δ = 0 is declared the identity:
// Ceres only ever uses their product, which is then our tangent.
class ModulePose : public ceres::Manifold {
 public:
  explicit ModulePose(const analysis::EquilibriumSystem& sys) : sys_(sys) {}
  int AmbientSize() const override { return 6; }
  int TangentSize() const override { return 6; }
  bool Plus(const double* x, const double* delta, double* out) const override {
    using V6 = Eigen::Matrix<double, 6, 1>;
    const Eigen::VectorXd y = sys_.retract(Eigen::Map<const V6>(x), Eigen::Map<const V6>(delta));
    Eigen::Map<V6> o(out);
    o = y;
    return true;
  }
  bool PlusJacobian(const double*, double* j) const override { return identity(j); }
  // Only Ceres's checks call Minus; a first-order inverse of Plus is enough there.
  bool Minus(const double* y, const double* x, double* out) const override {
    for (int i = 0; i < 6; ++i) out[i] = y[i] - x[i];
    return true;
  }
  bool MinusJacobian(const double*, double* j) const override { return identity(j); }

 private:
  static bool identity(double* j) {
    Eigen::Map<Eigen::Matrix<double, 6, 6, Eigen::RowMajor>>(j).setIdentity();
    return true;
  }
  const analysis::EquilibriumSystem& sys_;
};

// Stops Ceres once the scaled residual is at `target`, and records it against time.
class StopAtResidual : public ceres::IterationCallback {
 public:
  StopAtResidual(const analysis::EquilibriumSystem& sys, const Eigen::VectorXd& x, double target, Clock::time_point start)
      : sys_(sys), x_(x), target_(target), start_(start) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override {
    reached = sys_.residual(x_).lpNorm<Eigen::Infinity>();
    trace.push_back({std::chrono::duration<double>(Clock::now() - start_).count(), reached});
    return reached <= target_ ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }
  double reached = -1.0;
  std::vector<std::pair<double, double>> trace;  // (seconds, residual)

 private:
  const analysis::EquilibriumSystem& sys_;
  const Eigen::VectorXd& x_;
  double target_;
  Clock::time_point start_;
};

struct CeresRun {
  double residual = -1.0;
  int iterations = 0;
  std::vector<std::pair<double, double>> trace;
};

// Ceres from the unloaded state to `target`; everything built inside is part of what it costs.
enum class Strategy { LevenbergMarquardt, NearlyGaussNewton };

CeresRun solve_with_ceres(const analysis::Problem& p, const analysis::EquilibriumSystem& sys, double target,
                          Strategy strategy = Strategy::LevenbergMarquardt) {
  const auto start = Clock::now();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(sys.size());
  SharedEvaluation eval(sys, x);
  ceres::Problem::Options po;
  po.evaluation_callback = &eval;
  po.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  po.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(po);
  ModulePose pose(sys);
  const int n = static_cast<int>(sys.free_modules().size());
  std::vector<std::vector<int>> neighbours(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) neighbours[static_cast<std::size_t>(k)].push_back(k);
  for (const auto& c : p.structure.connections) {
    const int a = sys.index_of(c.a), b = sys.index_of(c.b);
    if (a < 0 || b < 0 || a == b) continue;
    neighbours[static_cast<std::size_t>(a)].push_back(b);
    neighbours[static_cast<std::size_t>(b)].push_back(a);
  }
  for (int k = 0; k < n; ++k) problem.AddParameterBlock(x.data() + 6 * k, 6, &pose);
  for (int k = 0; k < n; ++k) {
    auto& nb = neighbours[static_cast<std::size_t>(k)];
    std::sort(nb.begin(), nb.end());
    nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
    std::vector<double*> blocks;
    for (int m : nb) blocks.push_back(x.data() + 6 * m);
    problem.AddResidualBlock(new ModuleEquations(eval, k, nb), nullptr, blocks);
  }
  StopAtResidual stop(sys, x, target, start);
  ceres::Solver::Options o;
  o.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  o.num_threads = 1;
  o.max_num_iterations = 500;
  o.function_tolerance = o.gradient_tolerance = o.parameter_tolerance = 0.0;
  o.update_state_every_iteration = true;
  o.callbacks.push_back(&stop);
  o.logging_type = ceres::SILENT;
  if (strategy == Strategy::NearlyGaussNewton) {
    o.initial_trust_region_radius = 1e12;
    o.max_trust_region_radius = 1e16;
    o.use_nonmonotonic_steps = true;
  }
  ceres::Solver::Summary summary;
  ceres::Solve(o, &problem, &summary);
  if (std::getenv("FOLDKIT_CERES_REPORT")) std::fprintf(stderr, "%s\n", summary.FullReport().c_str());
  return {sys.residual(x).lpNorm<Eigen::Infinity>(), static_cast<int>(summary.iterations.size()) - 1, std::move(stop.trace)};
}

analysis::SolveOptions our_options() {
  analysis::SolveOptions o;
  o.estimate_condition = false;
  return o;
}

analysis::Problem make(const std::string& shape, int modules) {
  return shape == "beam" ? bench_stiffness::beam_problem(modules) : bench_stiffness::grid_problem(modules);
}

void counters(benchmark::State& state, const analysis::Problem& p, double residual, int iterations) {
  state.counters["modules"] = static_cast<double>(p.structure.modules.size());
  state.counters["unknowns"] = 6.0 * static_cast<double>(std::count(p.fixed.begin(), p.fixed.end(), false));
  state.counters["residual"] = residual;
  state.counters["iterations"] = iterations;
}

void ours(benchmark::State& state, const std::string& shape) {
  const auto p = make(shape, static_cast<int>(state.range(0)));
  analysis::SolveResult r;
  for (auto _ : state) {
    r = analysis::solve(p, our_options());
    benchmark::DoNotOptimize(r.max_displacement);
  }
  if (!r.status.ok()) state.SkipWithError(("ours did not converge: " + r.status.message).c_str());
  counters(state, p, r.residual_norm, r.iterations);
  // Why the normal equations struggle: their condition number is this one squared.
  auto with_condition = our_options();
  with_condition.estimate_condition = true;
  state.counters["condition"] = analysis::solve(p, with_condition).condition_estimate;
}

// The target is what ours reaches on the same problem (computed before timing).
void baseline(benchmark::State& state, const std::string& shape, Strategy strategy = Strategy::LevenbergMarquardt) {
  const auto p = make(shape, static_cast<int>(state.range(0)));
  const auto reference = analysis::solve(p, our_options());
  const analysis::EquilibriumSystem sys(p);
  CeresRun run;
  for (auto _ : state) {
    run = solve_with_ceres(p, sys, reference.residual_norm, strategy);
    benchmark::DoNotOptimize(run.residual);
  }
  counters(state, p, run.residual, run.iterations);
  // 0: Ceres stopped (500 iterations, or no progress) above ours; the time is then to that stop.
  state.counters["reached"] = run.residual <= reference.residual_norm;
}

void BM_StiffnessBeam_Ours(benchmark::State& s) { ours(s, "beam"); }
void BM_StiffnessBeam_Baseline(benchmark::State& s) { baseline(s, "beam"); }
void BM_StiffnessBeam_CeresGaussNewton(benchmark::State& s) { baseline(s, "beam", Strategy::NearlyGaussNewton); }
void BM_StiffnessPlate_Ours(benchmark::State& s) { ours(s, "plate"); }
void BM_StiffnessPlate_Baseline(benchmark::State& s) { baseline(s, "plate"); }

// Residual against time: ours at tolerances 1e-1 … 1e-12 (one run each), Ceres iteration by
// iteration down to ours at 1e-12. Columns: structure, modules, method, seconds, residual.
int error_vs_time(const std::string& path) {
  std::ofstream out(path);
  out << "structure,modules,method,seconds,residual\n";
  for (const std::string shape : {"beam", "plate"})
    for (int modules : {300, 1000}) {
      const auto p = make(shape, modules);
      const analysis::EquilibriumSystem sys(p);
      double finest = 0.0;
      for (int e = 1; e <= 12; ++e) {
        auto o = our_options();
        o.tolerance = std::pow(10.0, -e);
        const auto start = Clock::now();
        const auto r = analysis::solve(p, o);
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        out << shape << ',' << p.structure.modules.size() << ",ours," << seconds << ',' << r.residual_norm << '\n';
        finest = r.residual_norm;
      }
      for (const auto& [seconds, residual] : solve_with_ceres(p, sys, finest).trace)
        out << shape << ',' << p.structure.modules.size() << ",ceres," << seconds << ',' << residual << '\n';
      std::fprintf(stderr, "%s %zu modules done\n", shape.c_str(), p.structure.modules.size());
    }
  return out ? 0 : 1;
}

}  // namespace

BENCHMARK(BM_StiffnessBeam_Ours)->Arg(48)->Arg(300)->Arg(1000)->Arg(3000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StiffnessBeam_Baseline)->Arg(48)->Arg(300)->Arg(1000)->Arg(3000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StiffnessBeam_CeresGaussNewton)->Arg(48)->Arg(300)->Arg(1000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StiffnessPlate_Ours)->Arg(50)->Arg(200)->Arg(1000)->Arg(2000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StiffnessPlate_Baseline)->Arg(50)->Arg(200)->Arg(1000)->Arg(2000)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strncmp(argv[i], "--error-vs-time=", 16) == 0) return error_vs_time(argv[i] + 16);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
