// The dynamic-simulation spike (issue 33): a Miura-ori n×n folded from flat by one motor, gravity
// off, in ODE through foldkit::dynamics; prints closure drift (geometry::ClosureSystem on the
// engine's poses), the largest difference from the kinematic fold (folding::fold_projected) at
// the same driving angle, and the real-time factor. The sheet starts 0.2 rad into the kinematic path.
// `measure_dynamics pendulum`: instead, the period error of a free unit-square flap released
// 0.4 rad below the horizontal (against 4√(I/mgd)·K(sin(θ₀/2))) for time steps 1e-2 … 1e-4 s.
// `contacts` as the seventh argument: facet–facet contacts on (DynamicOptions::contacts), to
// measure what they cost on a fold that touches nothing.
// Trailing KEY=VALUE arguments set more options: projection=S (DynamicOptions::projection_interval,
// post-stabilisation every S seconds), erp=E, cfm=C. RTF is printed from wall and from CPU time
// (the process's, the machine being shared).
// Usage: measure_dynamics [n=10] [solver=iterative|direct] [iterations=100] [time_step=1e-3] [speed=0.5] [driving joint index|-1] [contacts|-] [KEY=VALUE …]
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "foldkit/dynamics/dynamic_simulate.hpp"
#include "foldkit/geometry/generators.hpp"
#include "one_motor_miura.hpp"

using namespace foldkit;

namespace {

int pendulum() {
  geometry::PatternSpec spec;
  spec.actors.push_back({1, {{{{{-1, 0}, {0, 0}, {0, 1}}}}, {{{{-1, 0}, {0, 1}, {-1, 1}}}}}});
  spec.actors.push_back({2, {{{{{0, 0}, {1, 0}, {1, 1}}}}, {{{{0, 0}, {1, 1}, {0, 1}}}}}});
  spec.actors.push_back({3, {{{{{-1, 0}, {-1, 1}, {-1.2, 0.5}}}}}});  // its motor keeps the clock running
  spec.joints.push_back({1, {{{0, 0}, {0, 1}}}, {1, 2}, 0.0, 0.0});
  spec.joints.push_back({2, {{{-1, 0}, {-1, 1}}}, {1, 3}, 0.0, 0.0});
  const geometry::CreasePattern p = geometry::build_or_throw(spec);
  geometry::FoldSequence seq;
  seq.events.push_back({1, {{2, -1.5, 0.25, 0}}});  // 6 s
  const double amplitude = M_PI / 2 - 0.4, I = 1.0 / 3.0, mgd = 9.81 * 0.5;
  const double period = 4.0 * std::sqrt(I / mgd) * std::comp_ellint_1(std::sin(amplitude / 2));
  for (double dt : {1e-2, 3e-3, 1e-3, 3e-4, 1e-4}) {
    dynamics::DynamicOptions o;
    o.gravity = Eigen::Vector3d(0, 0, -9.81);
    o.time_step = dt;
    o.check_interval = dt;
    o.record_frames = true;
    o.start = Eigen::Vector2d(0.4, 0.0);
    const auto r = dynamics::simulate_dynamic(p, seq, o);
    std::vector<double> up;
    for (std::size_t k = 1; k < r.frames.size(); ++k) {
      const double a = r.frames[k - 1].state.angles[0] - M_PI / 2, b = r.frames[k].state.angles[0] - M_PI / 2;
      if (a < 0 && b >= 0) up.push_back(r.frames[k - 1].time + (r.frames[k].time - r.frames[k - 1].time) * a / (a - b));
    }
    const double measured = up.size() > 1 ? (up.back() - up.front()) / static_cast<double>(up.size() - 1) : 0.0;
    std::printf("pendulum dt %g: period %.6f s (closed form %.6f s), error %.3g %%, RTF %.3g\n", dt, measured, period,
                100.0 * (measured - period) / period, r.duration / r.seconds);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "pendulum") return pendulum();
  const int n = argc > 1 ? std::atoi(argv[1]) : 10;
  dynamics::DynamicOptions o;
  o.solver = argc > 2 && std::string(argv[2]) == "direct" ? dynamics::Solver::Direct : dynamics::Solver::Iterative;
  if (argc > 3) o.iterations = std::atoi(argv[3]);
  if (argc > 4) o.time_step = std::atof(argv[4]);
  const double speed = argc > 5 ? std::atof(argv[5]) : 0.5;
  o.max_torque = 1e6;  // the spike measures the engine, not the motor
  o.contacts = argc > 7 && std::string(argv[7]) == "contacts";
  for (int a = 8; a < argc; ++a) {
    const std::string arg = argv[a];
    const auto eq = arg.find('=');
    const std::string key = arg.substr(0, eq);
    const double value = eq == std::string::npos ? 0.0 : std::atof(arg.c_str() + eq + 1);
    if (key == "projection") o.projection_interval = value;
    else if (key == "erp") o.erp = value;
    else if (key == "cfm") o.cfm = value;
    else return std::fprintf(stderr, "unknown option %s (projection=, erp=, cfm=)\n", arg.c_str()), 1;
  }
  const microbench::OneMotorMiura scene = microbench::one_motor_miura(n, speed, argc > 6 ? std::atoi(argv[6]) : -1);
  const geometry::CreasePattern& p = scene.pattern;
  const geometry::FoldState& K = scene.kinematic.states.back();
  const int drive = scene.drive;
  o.start = scene.start;
  const geometry::FoldSequence& seq = scene.sequence;
  // DYN_TRACE: the closure error at every check, to see where in the fold the drift arises.
  if (std::getenv("DYN_TRACE"))
    o.progress = [k = 0](const geometry::Progress& pr) mutable { std::printf("check %d closure %.3g rad\n", ++k, pr.closure_error); };
  const std::clock_t cpu0 = std::clock();
  const auto r = dynamics::simulate_dynamic(p, seq, o);
  const double cpu = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  const double diff = (r.final_state.angles - K.angles).cwiseAbs().maxCoeff();
  std::printf("miura %dx%d joints %zu solver %s iterations %d dt %g projection %g erp %g%s: status %s, %g s simulated in %g s "
              "(RTF %.3g, CPU RTF %.3g), closure drift %.3g rad (before corrections %.3g rad), max |angle - kinematic| %.3g rad, driving angle %.4f rad, "
              "%zu contacts\n",
              n, n, p.joints().size(), o.solver == dynamics::Solver::Direct ? "direct" : "iterative", o.iterations, o.time_step,
              o.projection_interval, o.erp, o.contacts ? " contacts" : "", geometry::to_string(r.status.code), r.duration,
              r.seconds, r.duration / r.seconds, r.duration / cpu, r.max_closure_error, r.max_corrected_error, diff, K.angles[drive], r.contacts.size());
  if (!r.status.ok()) std::printf("  %s\n", r.status.message.c_str());
  if (std::getenv("DYN_VERBOSE"))
    for (int j = 0; j < static_cast<int>(p.joints().size()); ++j)
      std::printf("  joint %d actors %d %d kin %.4f dyn %.4f\n", p.joints()[j].id, p.joints()[j].actors[0], p.joints()[j].actors[1], K.angles[j], r.final_state.angles[j]);
  return 0;
}
