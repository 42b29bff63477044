// Real-time factor of the dynamic simulator (foldkit::dynamics, ODE) on a Miura-ori n × n folded
// by one motor, gravity off, beside the kinematic simulator replaying the same fold:
//   BM_Dynamic_Direct/n     — ODE's direct solver (the default), 10 ms steps;
//   BM_Dynamic_Iterative/n  — ODE's QuickStep, 20 sweeps, 10 ms steps (drifts more: see the
//                             closure counter);
//   BM_Kinematic/n          — simulation::simulate (motor model, no collisions) of the CMML
//                             fold_projected wrote for the same fold, every crease driven.
// Counters: rtf = simulated seconds per wall second; drift = closure drift of the engine's poses.
#include <map>
#include <memory>

#include <benchmark/benchmark.h>

#include "foldkit/dynamics/dynamic_simulate.hpp"
#include "foldkit/folding/projected_folding.hpp"
#include "foldkit/geometry/generators.hpp"

namespace {

using namespace foldkit;

// The sheet, the kinematic fold to half way and the one-motor sequence toward its end, per size.
struct Scene {
  geometry::CreasePattern pattern;
  folding::ProjectedFoldingResult kinematic;
  geometry::FoldSequence one_motor;
  Eigen::VectorXd start;
};

const Scene& scene(int n) {
  static std::map<int, std::unique_ptr<Scene>> cache;
  auto& slot = cache[n];
  if (slot) return *slot;
  geometry::CreasePattern p = geometry::build_or_throw(geometry::generators::miura(n, n));
  folding::ProjectedFoldingOptions fo;
  fo.target_fraction = 0.5;
  fo.replay = false;
  fo.collisions = false;
  fo.speed = 0.5;
  auto kin = folding::fold_projected(p, fo);
  const geometry::FoldState& goal = kin.states.back();
  int drive = -1;
  for (int j = 0; j < static_cast<int>(p.joints().size()); ++j) {
    const auto& a = p.joints()[j].actors;
    if ((a[0] == 0 || a[1] == 0) && (drive < 0 || std::abs(goal.angles[j]) > std::abs(goal.angles[drive]))) drive = j;
  }
  geometry::FoldSequence seq;
  seq.events.push_back({1, {{p.joints()[drive].id, goal.angles[drive], 0.5, 0}}});
  Eigen::VectorXd start;
  for (const auto& s : kin.states)
    if (s.angles.cwiseAbs().maxCoeff() >= 0.2) {
      start = s.angles;
      break;
    }
  slot = std::make_unique<Scene>(Scene{std::move(p), std::move(kin), std::move(seq), std::move(start)});
  return *slot;
}

void run_dynamic(benchmark::State& st, dynamics::Solver solver) {
  const Scene& sc = scene(static_cast<int>(st.range(0)));
  dynamics::DynamicOptions o;
  o.solver = solver;
  o.iterations = 20;
  o.time_step = 1e-2;
  o.max_torque = 1e6;
  o.start = sc.start;
  double simulated = 0.0, wall = 0.0, drift = 0.0;
  for (auto _ : st) {
    const auto r = dynamics::simulate_dynamic(sc.pattern, sc.one_motor, o);
    simulated += r.duration;
    wall += r.seconds;
    drift = r.max_closure_error;
  }
  st.counters["rtf"] = simulated / wall;
  st.counters["drift"] = drift;
  st.counters["facets"] = static_cast<double>(sc.pattern.actors().size());
}

void BM_Dynamic_Direct(benchmark::State& st) { run_dynamic(st, dynamics::Solver::Direct); }
void BM_Dynamic_Iterative(benchmark::State& st) { run_dynamic(st, dynamics::Solver::Iterative); }

void BM_Kinematic(benchmark::State& st) {
  const Scene& sc = scene(static_cast<int>(st.range(0)));
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
BENCHMARK(BM_Kinematic)->Arg(4)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond)->UseRealTime();  // rtf per wall second, as above
BENCHMARK_MAIN();
