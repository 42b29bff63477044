// Real-time factor of the dynamic simulator (foldkit::dynamics, ODE) on a Miura-ori n × n folded
// by one motor, gravity off, beside the kinematic simulator replaying the same fold:
//   BM_Dynamic_Direct/n     — ODE's direct solver (the default), 10 ms steps;
//   BM_Dynamic_Iterative/n  — ODE's QuickStep, 20 sweeps, 10 ms steps (drifts more: see the
//                             closure counter);
//   BM_Dynamic_Stabilised/n — QuickStep, 20 sweeps, 10 ms steps, post-stabilised every step
//                             (DynamicOptions::projection_interval): the configuration that meets
//                             the targets with the loops closed;
//   BM_Dynamic_Contacts/n   — the iterative run with facet–facet contacts on (the fold touches
//                             nothing: what the collision space alone costs);
//   BM_Kinematic/n          — simulation::simulate (motor model, no collisions) of the CMML
//                             fold_projected wrote for the same fold, every crease driven.
// Counters: rtf = simulated seconds per wall second; drift = closure drift of the engine's poses;
// corrected = the drift the steps left before the post-stabilisations removed it (0 without).
#include <map>
#include <memory>

#include <benchmark/benchmark.h>

#include "foldkit/dynamics/dynamic_simulate.hpp"
#include "one_motor_miura.hpp"

namespace {

using namespace foldkit;

// The scene per size (one_motor_miura.hpp), made once.
const microbench::OneMotorMiura& scene(int n) {
  static std::map<int, std::unique_ptr<microbench::OneMotorMiura>> cache;
  auto& slot = cache[n];
  if (!slot) slot = std::make_unique<microbench::OneMotorMiura>(microbench::one_motor_miura(n));
  return *slot;
}

void run_dynamic(benchmark::State& st, dynamics::Solver solver, bool contacts = false, double projection_interval = 0.0) {
  const microbench::OneMotorMiura& sc = scene(static_cast<int>(st.range(0)));
  dynamics::DynamicOptions o;
  o.solver = solver;
  o.iterations = 20;
  o.time_step = 1e-2;
  o.max_torque = 1e6;
  o.start = sc.start;
  o.contacts = contacts;
  o.projection_interval = projection_interval;
  double simulated = 0.0, wall = 0.0, drift = 0.0, corrected = 0.0;
  for (auto _ : st) {
    const auto r = dynamics::simulate_dynamic(sc.pattern, sc.sequence, o);
    simulated += r.duration;
    wall += r.seconds;
    drift = r.max_closure_error;
    corrected = r.max_corrected_error;
  }
  st.counters["rtf"] = simulated / wall;
  st.counters["drift"] = drift;
  st.counters["corrected"] = corrected;
  st.counters["facets"] = static_cast<double>(sc.pattern.actors().size());
}

void BM_Dynamic_Direct(benchmark::State& st) { run_dynamic(st, dynamics::Solver::Direct); }
void BM_Dynamic_Iterative(benchmark::State& st) { run_dynamic(st, dynamics::Solver::Iterative); }
void BM_Dynamic_Contacts(benchmark::State& st) { run_dynamic(st, dynamics::Solver::Iterative, true); }
void BM_Dynamic_Stabilised(benchmark::State& st) { run_dynamic(st, dynamics::Solver::Iterative, false, 1e-2); }

void BM_Kinematic(benchmark::State& st) {
  const microbench::OneMotorMiura& sc = scene(static_cast<int>(st.range(0)));
  simulation::SimulationOptions o;
  o.collisions = false;
  double simulated = 0.0;
  for (auto _ : st) simulated += simulation::simulate(sc.pattern, sc.kinematic.sequence, o).duration;
  st.counters["rtf"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
  st.counters["facets"] = static_cast<double>(sc.pattern.actors().size());
}

}  // namespace

BENCHMARK(BM_Dynamic_Direct)->Arg(4)->Arg(10)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Dynamic_Iterative)->Arg(4)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Dynamic_Stabilised)->Arg(4)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Dynamic_Contacts)->Arg(4)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_Kinematic)->Arg(4)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond)->UseRealTime();  // rtf per wall second, as above
BENCHMARK_MAIN();
