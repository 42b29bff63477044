// Error reached versus cost for the numerical parameters of the closure projection
// (geometry::project: tolerance, iteration limit, keep_signs; beside a generic Gauss–Newton with a
// JacobiSVD pseudo-inverse at step lengths 1, ½, ¼) and of the stiffness solver
// (analysis::solve: tolerance, linear vs nonlinear as the load grows, stiffness ratios to 1e14).
//
//   measure_error_cost [--out DIR] [--quick]
//
// Writes DIR/error_cost_projection.csv and DIR/error_cost_stiffness.csv (default DIR: .), one row
// per run: study, problem, method, parameter, value, iterations, load_steps, error, residual,
// time_s (CPU seconds per run, the mean over repeats), converged. Projection: error = residual =
// the largest loop error (rad). Stiffness: error = relative error of the tip deflection against an
// oracle that shares no code with the solver (closed form or an independent N-link chain solve;
// for the plate, the solution at tolerance 1e-14, marked in `problem`), residual = scaled ∞-norm
// of the nonlinear equilibrium equations at the returned displacements. scripts/plot_error_cost.py
// draws them.
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "foldkit/analysis/solver.hpp"
#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/io/atomic_write.hpp"

#include "bench_patterns.hpp"

namespace {

using namespace foldkit;
using Eigen::Vector3d;
using geometry::CreasePattern;
using geometry::FoldState;

bool g_quick = false;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// Mean CPU time of `run` over enough repeats to measure it (at least 0.2 s in all, 0.02 s quick).
double timed(const std::function<void()>& run) {
  const double budget = g_quick ? 0.02 : 0.2;
  int n = 0;
  const double t0 = cpu_seconds();
  double t = t0;
  do {
    run();
    ++n;
    t = cpu_seconds();
  } while (t - t0 < budget && n < 2000);
  return (t - t0) / n;
}

struct Row {
  std::string study, problem, method, parameter;
  double value = 0;
  int iterations = 0, load_steps = 0;
  double error = kNaN, residual = kNaN, time_s = 0;
  bool converged = false;
};

std::string csv(const std::vector<Row>& rows) {
  std::ostringstream o;
  o.precision(6);
  o << "study,problem,method,parameter,value,iterations,load_steps,error,residual,time_s,converged\n";
  auto num = [&](double v) {
    if (std::isnan(v)) return std::string();
    std::ostringstream s;
    s.precision(6);
    s << v;
    return s.str();
  };
  for (const auto& r : rows)
    o << r.study << ',' << r.problem << ',' << r.method << ',' << r.parameter << ',' << num(r.value) << ',' << r.iterations
      << ',' << r.load_steps << ',' << num(r.error) << ',' << num(r.residual) << ',' << num(r.time_s) << ','
      << (r.converged ? 1 : 0) << '\n';
  return o.str();
}

// ---------------------------------------------------------------------------------------------
// Projection

struct ProjectionCase {
  std::string name;
  CreasePattern pattern;
  FoldState start;
};

FoldState random_state(const CreasePattern& p, double amplitude, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  FoldState s = FoldState::flat(p);
  for (Eigen::Index i = 0; i < s.angles.size(); ++i) s.angles[i] = u(rng);
  return s;
}

std::vector<ProjectionCase> projection_cases() {
  std::vector<ProjectionCase> out;
  const int n = g_quick ? 6 : 10;
  const std::string miura = "miura" + std::to_string(n) + "x" + std::to_string(n);
  {
    CreasePattern p = geometry::build_or_throw(geometry::generators::miura(n, n));
    FoldState s = foldkit::bench::closed_miura(p, geometry::ClosureSystem(p), 1.0);
    const FoldState noise = random_state(p, 0.02, 11);
    s.angles += noise.angles;
    out.push_back({miura + "_disturbed", std::move(p), s});
  }
  {
    // The flat state is singular (the Jacobian drops rank there): start 1e-3 rad away from it.
    CreasePattern p = geometry::build_or_throw(geometry::generators::miura(n, n));
    const FoldState s = random_state(p, 1e-3, 12);
    out.push_back({miura + "_near_flat", std::move(p), s});
  }
  for (int degree : {64, 256}) {
    CreasePattern p = geometry::build_or_throw(
        geometry::generators::single_vertex(std::vector<double>(static_cast<std::size_t>(degree), 2 * M_PI / degree)));
    const FoldState s = random_state(p, 0.5, 13);
    out.push_back({"vertex_degree" + std::to_string(degree), std::move(p), s});
  }
  {
    // Two sliver sectors of 1e-3 rad among six wide ones.
    std::vector<double> sectors = {1e-3, (2 * M_PI - 2e-3) / 6, 1e-3};
    for (int k = 0; k < 5; ++k) sectors.push_back((2 * M_PI - 2e-3) / 6);
    CreasePattern p = geometry::build_or_throw(geometry::generators::single_vertex(sectors));
    const FoldState s = random_state(p, 0.5, 14);
    out.push_back({"vertex_sliver_sectors", std::move(p), s});
  }
  return out;
}

Row projection_row(const ProjectionCase& c, const std::string& method, const std::string& parameter, double value) {
  Row r;
  r.study = "projection";
  r.problem = c.name;
  r.method = method;
  r.parameter = parameter;
  r.value = value;
  return r;
}

// Ours, stopped after k iterations: the error trajectory, each point costed as a whole run.
void iteration_limit_rows(const geometry::ClosureSystem& sys, const ProjectionCase& c, std::vector<Row>& rows) {
  for (int k = 1; k <= 60; ++k) {
    geometry::ProjectionOptions o;
    o.tolerance = 1e-15;
    o.max_iterations = k;
    geometry::ProjectionResult res;
    Row r = projection_row(c, "ours_iteration_limit", "max_iterations", k);
    r.time_s = timed([&] { res = geometry::project(sys, c.start, o); });
    r.iterations = res.iterations;
    r.error = r.residual = res.error;
    r.converged = res.status.ok();
    rows.push_back(r);
    if (res.iterations < k) break;  // converged or stuck: later limits change nothing
  }
}

void tolerance_rows(const geometry::ClosureSystem& sys, const ProjectionCase& c, bool keep, std::vector<Row>& rows) {
  for (int e = 2; e <= 14; ++e) {
    geometry::ProjectionOptions o;
    o.tolerance = std::pow(10.0, -e);
    o.keep_signs = keep;
    geometry::ProjectionResult res;
    Row r = projection_row(c, keep ? "ours_tolerance" : "ours_tolerance_free_signs", "tolerance", o.tolerance);
    r.time_s = timed([&] { res = geometry::project(sys, c.start, o); });
    r.iterations = res.iterations;
    r.error = r.residual = res.error;
    r.converged = res.status.ok();
    rows.push_back(r);
  }
}

// The error after each Gauss–Newton iteration, and the CPU time spent up to it.
struct Trajectory {
  std::vector<double> errors, spent;
};

// The trajectory is run a few times and each point keeps its least cumulative time.
Trajectory gauss_newton(const geometry::ClosureSystem& sys, const FoldState& start, double alpha) {
  const int limit = g_quick ? 25 : 40;
  Trajectory out;
  for (int repeat = 0; repeat < 5; ++repeat) {
    FoldState s = start;
    Eigen::VectorXd res;
    Eigen::SparseMatrix<double> J;
    double total = 0;
    for (int k = 1; k <= limit; ++k) {
      const double t0 = cpu_seconds();
      sys.evaluate(s, res, J);
      const Eigen::MatrixXd dense(J);
      const Eigen::JacobiSVD<Eigen::MatrixXd> svd(dense, Eigen::ComputeThinU | Eigen::ComputeThinV);
      s.angles = (s.angles - alpha * svd.solve(res)).cwiseMax(-M_PI).cwiseMin(M_PI);
      const double error = sys.max_error(s);
      total += cpu_seconds() - t0;
      if (repeat == 0) {
        out.errors.push_back(error);
        out.spent.push_back(total);
      } else {
        out.spent[static_cast<std::size_t>(k - 1)] = std::min(out.spent[static_cast<std::size_t>(k - 1)], total);
      }
      if (error <= 1e-14 || !std::isfinite(error)) break;
    }
    if (total > (g_quick ? 0.2 : 2.0)) break;  // slow enough to be measured once
  }
  return out;
}

// The generic way: Gauss–Newton through the dense pseudo-inverse, x ← x − α J⁺ r, its error
// after each iteration against the CPU time spent so far.
void gauss_newton_rows(const geometry::ClosureSystem& sys, const ProjectionCase& c, double alpha, std::vector<Row>& rows) {
  const Trajectory t = gauss_newton(sys, c.start, alpha);
  for (std::size_t k = 0; k < t.errors.size(); ++k) {
    Row r = projection_row(c, "gn_svd_step_" + std::string(alpha == 1.0 ? "1" : alpha == 0.5 ? "0.5" : "0.25"), "step", alpha);
    r.iterations = static_cast<int>(k + 1);
    r.time_s = t.spent[k];
    r.error = r.residual = t.errors[k];
    r.converged = t.errors[k] <= 1e-10;
    rows.push_back(r);
  }
}

void projection_rows(const ProjectionCase& c, std::vector<Row>& rows) {
  const geometry::ClosureSystem sys(c.pattern);
  {
    Row r = projection_row(c, "start", "none", 0);
    r.error = r.residual = sys.max_error(c.start);
    rows.push_back(r);
  }
  iteration_limit_rows(sys, c, rows);
  for (bool keep : {true, false}) tolerance_rows(sys, c, keep, rows);
  for (double alpha : {1.0, 0.5, 0.25}) gauss_newton_rows(sys, c, alpha, rows);
}

// ---------------------------------------------------------------------------------------------
// Stiffness

// A flat strip of `tiles` unit squares along +x, tile 0 fixed, hinges of stiffness k about their
// line and `k_translation` along every axis (1e4 about the other two).
analysis::Problem strip_problem(int tiles, double k, double k_translation) {
  const auto pattern = geometry::build_or_throw(geometry::generators::strip(tiles));
  analysis::Problem p;
  p.structure = analysis::build_structure(pattern, FoldState::flat(pattern));
  analysis::Matrix6 hinge = analysis::Matrix6::Zero();
  hinge.diagonal() << k_translation, k_translation, k_translation, 1e4, 1e4, k;
  p.stiffness[static_cast<int>(analysis::ConnectionKind::Hinged)] = hinge;
  p.fixed.assign(static_cast<std::size_t>(tiles), false);
  p.fixed[0] = true;
  return p;
}

// The grid of bench_stiffness: rows × cols tiles of 10 mm, first column fixed, a corner load.
analysis::Problem plate_problem(int modules) {
  const int rows = std::max(1, static_cast<int>(std::lround(std::sqrt(modules / 2.0))));
  const int cols = std::max(2, modules / rows);
  const auto pattern = geometry::build_or_throw(geometry::generators::grid(rows, cols, 0.01));
  analysis::Problem p;
  p.structure = analysis::build_structure(pattern, FoldState::flat(pattern));
  p.fixed.assign(p.structure.modules.size(), false);
  for (int j = 0; j < rows; ++j) p.fixed[static_cast<std::size_t>(j * cols)] = true;
  const int corner = rows * cols - 1;
  p.loads.push_back({corner, Vector3d(0, 0, -10.0 / cols), p.structure.modules[static_cast<std::size_t>(corner)].centroid});
  return p;
}

// The independent oracle: N rigid links of length 1 on rotational springs k (the first at the
// wall), a dead load P at the tip, perpendicular to the unloaded chain. Link m turns by φ_m;
// moments about joint i: k (φ_i − φ_{i−1}) = P Σ_{m≥i} cos φ_m. Newton on the N angles with load
// continuation; returns the tip's deflection Σ sin φ_m.
double chain_tip_deflection(int n, double k, double load) {
  Eigen::VectorXd phi = Eigen::VectorXd::Zero(n);
  const int increments = 50;
  for (int step = 1; step <= increments; ++step) {
    const double P = load * step / increments;
    for (int it = 0; it < 100; ++it) {
      Eigen::VectorXd F(n);
      Eigen::MatrixXd Jac = Eigen::MatrixXd::Zero(n, n);
      for (int i = 0; i < n; ++i) {
        double tail = 0;
        for (int m = i; m < n; ++m) {
          tail += std::cos(phi[m]);
          Jac(i, m) += P * std::sin(phi[m]);
        }
        F[i] = k * (phi[i] - (i > 0 ? phi[i - 1] : 0.0)) - P * tail;
        Jac(i, i) += k;
        if (i > 0) Jac(i, i - 1) -= k;
      }
      const Eigen::VectorXd d = Jac.partialPivLu().solve(-F);
      phi += d;
      if (d.lpNorm<Eigen::Infinity>() < 1e-15) break;
    }
  }
  double tip = 0;
  for (int m = 0; m < n; ++m) tip += std::sin(phi[m]);
  return tip;
}

// Downward deflection of a point of a module (given unloaded) in a solution; a linear solution
// moves the point by u + φ × arm, as its model does (the exact rotation would add O(φ³)).
double deflection(const analysis::Problem& p, const analysis::SolveResult& r, int module, const Vector3d& point, bool linear) {
  const auto& m = r.modules[static_cast<std::size_t>(module)];
  const Vector3d arm = point - p.structure.modules[static_cast<std::size_t>(module)].centroid;
  if (linear) return -(m.displacement + m.rotation.cross(arm)).z();
  const double angle = m.rotation.norm();
  const Eigen::Matrix3d rot = angle > 0 ? Eigen::AngleAxisd(angle, m.rotation / angle).toRotationMatrix() : Eigen::Matrix3d::Identity();
  return -(m.displacement + rot * arm - arm).z();
}

// The scaled ∞-norm of the nonlinear equations at the displacements a solve returned.
double nonlinear_residual(const analysis::Problem& p, const analysis::SolveResult& r) {
  const analysis::EquilibriumSystem sys(p);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(sys.size());
  for (std::size_t i = 0; i < r.modules.size(); ++i) {
    const int k = sys.index_of(static_cast<int>(i));
    if (k < 0) continue;
    x.segment<3>(6 * k) = r.modules[i].displacement / sys.length_unit();
    x.segment<3>(6 * k + 3) = r.modules[i].rotation;
  }
  return sys.residual(x).lpNorm<Eigen::Infinity>();
}

Row solve_row(const std::string& problem, const std::string& method, const std::string& parameter, double value,
              const analysis::Problem& p, const analysis::SolveOptions& o, const std::function<double(const analysis::SolveResult&)>& error) {
  analysis::SolveResult res;
  Row r;
  r.study = "stiffness";
  r.problem = problem;
  r.method = method;
  r.parameter = parameter;
  r.value = value;
  r.time_s = timed([&] { res = analysis::solve(p, o); });
  r.iterations = res.iterations;
  r.load_steps = res.load_steps;
  r.converged = res.status.ok();
  r.residual = nonlinear_residual(p, res);
  r.error = error(res);
  return r;
}

// The discrete elastica: N = 10 links on hinges of stiffness k = 1 about their line and k_t
// along every axis, a tip load P = α k / N. Oracle: the rigid chain (chain_tip_deflection) plus
// the slip of the N hinges' translational springs, N P / k_t (isotropic springs under a vertical
// force slip vertically, leaving every lever arm unchanged). The linear solver is held to the
// linear model's closed form δ = P Σ dᵢ² / k + N P / k_t instead (dᵢ = hinge to load).
constexpr int kLinks = 10;
const Vector3d kTip(kLinks + 1, 0.5, 0.0);

analysis::Problem elastica(double load, double kt) {
  analysis::Problem p = strip_problem(kLinks + 1, 1.0, kt);
  p.loads.push_back({kLinks, Vector3d(0, 0, -load), kTip});
  return p;
}

double oracle(double load, double kt, bool linear_model) {
  double bending = 0;
  if (linear_model)
    for (int i = 1; i <= kLinks; ++i) bending += load * (kLinks + 1 - i) * (kLinks + 1 - i);
  else
    bending = chain_tip_deflection(kLinks, 1.0, load);
  return bending + kLinks * load / kt;
}

// The relative error of the tip deflection against `expected` (p must outlive the function).
std::function<double(const analysis::SolveResult&)> relative_to(const analysis::Problem& p, double expected, bool lin) {
  const Vector3d tip = kTip;
  return [&p, expected, tip, lin](const analysis::SolveResult& res) {
    if (!res.status.ok()) return kNaN;
    return std::abs(deflection(p, res, kLinks, tip, lin) - expected) / std::abs(expected);
  };
}

struct Solvers {
  analysis::SolveOptions base, linear;
};

// Linear against nonlinear as the load grows (ratio k_t / k = 1e6, the default springs' ratio):
// the nonlinear error is against the large-deflection oracle, the linear one against it too (the
// error a user makes by choosing --linear).
constexpr double kDefaultRatio = 1e6;

void elastica_load_sweep_rows(const Solvers& s, std::vector<Row>& rows) {
  for (double alpha : {0.01, 0.03, 0.1, 0.3, 1.0, 2.0, 5.0, 10.0}) {
    const double load = alpha / (kLinks * kLinks);
    const analysis::Problem p = elastica(load, kDefaultRatio);
    const double expected = oracle(load, kDefaultRatio, false);
    rows.push_back(solve_row("elastica_load_sweep", "newton", "alpha", alpha, p, s.base, relative_to(p, expected, false)));
    rows.push_back(solve_row("elastica_load_sweep", "linear", "alpha", alpha, p, s.linear, relative_to(p, expected, true)));
  }
}

// Tolerance and iteration limit against cost at α = 1.
void elastica_alpha1_rows(const Solvers& s, std::vector<Row>& rows) {
  const double load = 0.01;
  const analysis::Problem p = elastica(load, kDefaultRatio);
  const double expected = oracle(load, kDefaultRatio, false);
  for (int e = 2; e <= 14; ++e) {
    analysis::SolveOptions o = s.base;
    o.tolerance = std::pow(10.0, -e);
    rows.push_back(solve_row("elastica_alpha1", "newton_tolerance", "tolerance", o.tolerance, p, o, relative_to(p, expected, false)));
  }
  for (int m = 1; m <= 8; ++m) {
    analysis::SolveOptions o = s.base;
    o.max_iterations = m;
    rows.push_back(solve_row("elastica_alpha1", "newton_iteration_limit", "max_iterations", m, p, o, relative_to(p, expected, false)));
  }
}

// Stiffness ratio k_t / k from 1e2 to 1e14 at α = 1 (nonlinear) and α = 0.01 (linear, against
// the linear closed form): how many digits the ill-conditioning leaves.
void elastica_stiffness_ratio_rows(const Solvers& s, std::vector<Row>& rows) {
  for (int e = 2; e <= 14; ++e) {
    const double kt = std::pow(10.0, e);
    {
      const analysis::Problem p = elastica(0.01, kt);
      rows.push_back(solve_row("elastica_stiffness_ratio", "newton", "ratio", kt, p, s.base, relative_to(p, oracle(0.01, kt, false), false)));
    }
    {
      const analysis::Problem p = elastica(1e-4, kt);
      rows.push_back(solve_row("elastica_stiffness_ratio", "linear", "ratio", kt, p, s.linear, relative_to(p, oracle(1e-4, kt, true), true)));
    }
  }
}

// Small loads on stiff springs: the stiffness in units of the load, k_t L / P, grows as P
// shrinks, and with it the round-off floor the solver raises its tolerance to.
void elastica_small_load_rows(const Solvers& s, std::vector<Row>& rows) {
  for (int e = 1; e <= 9; ++e) {
    const double load = std::pow(10.0, -e), kt = 1e9;
    const analysis::Problem p = elastica(load, kt);
    rows.push_back(solve_row("elastica_small_load", "newton", "load", load, p, s.base, relative_to(p, oracle(load, kt, false), false)));
    rows.push_back(solve_row("elastica_small_load", "linear", "load", load, p, s.linear, relative_to(p, oracle(load, kt, true), true)));
  }
}

// A plate of ≈ 200 tiles (the benchmark's grid): tolerance against cost, error relative to the
// solution at tolerance 1e-14 (self-convergence: no independent oracle here).
void plate_rows(const Solvers& s, std::vector<Row>& rows) {
  const analysis::Problem p = plate_problem(g_quick ? 50 : 200);
  analysis::SolveOptions tight = s.base;
  tight.tolerance = 1e-14;
  const auto ref = analysis::solve(p, tight);
  const std::string name = g_quick ? "plate50_vs_tol1e-14" : "plate200_vs_tol1e-14";
  auto err = [&p, &ref](const analysis::SolveResult& res) {
    if (!res.status.ok() || !ref.status.ok()) return kNaN;
    double worst = 0, scale = 0;
    for (std::size_t i = 0; i < res.modules.size(); ++i) {
      worst = std::max(worst, (res.modules[i].displacement - ref.modules[i].displacement).norm());
      scale = std::max(scale, ref.modules[i].displacement.norm());
    }
    (void)p;
    return worst / scale;
  };
  for (int e = 2; e <= 14; ++e) {
    analysis::SolveOptions o = s.base;
    o.tolerance = std::pow(10.0, -e);
    rows.push_back(solve_row(name, "newton_tolerance", "tolerance", o.tolerance, p, o, err));
  }
  rows.push_back(solve_row(name, "linear", "tolerance", 0, p, s.linear, err));
}

void stiffness_rows(std::vector<Row>& rows) {
  Solvers s;
  s.base.estimate_condition = false;
  s.linear = s.base;
  s.linear.linear = true;
  std::cerr << "elastica N=10, alpha=1: oracle tip deflection / L = " << chain_tip_deflection(kLinks, 1.0, 0.01) / kLinks
            << " (NOTES.md: 0.34204)\n";
  elastica_load_sweep_rows(s, rows);
  elastica_alpha1_rows(s, rows);
  elastica_stiffness_ratio_rows(s, rows);
  elastica_small_load_rows(s, rows);
  plate_rows(s, rows);
}

}  // namespace

int main(int argc, char** argv) {
  std::string out = ".";
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--out" && i + 1 < argc) out = argv[++i];
    else if (a == "--quick") g_quick = true;
    else if (a == "--help" || a == "-h") {
      std::cout << "usage: measure_error_cost [--out DIR] [--quick]\n"
                   "Writes DIR/error_cost_projection.csv and DIR/error_cost_stiffness.csv.\n";
      return 0;
    } else {
      std::cerr << "measure_error_cost: unknown argument '" << a << "' (see --help)\n";
      return 2;
    }
  }
  try {
    std::vector<Row> projection;
    for (const auto& c : projection_cases()) {
      std::cerr << "projection: " << c.name << " (" << c.pattern.joints().size() << " creases)\n";
      projection_rows(c, projection);
    }
    io::write_file_atomic(out + "/error_cost_projection.csv", csv(projection));
    std::vector<Row> stiffness;
    std::cerr << "stiffness\n";
    stiffness_rows(stiffness);
    io::write_file_atomic(out + "/error_cost_stiffness.csv", csv(stiffness));
    std::cerr << "wrote " << out << "/error_cost_projection.csv (" << projection.size() << " rows) and " << out
              << "/error_cost_stiffness.csv (" << stiffness.size() << " rows)\n";
  } catch (const std::exception& e) {
    std::cerr << "measure_error_cost: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
