// foldkit simulate: replay a CMML on a pattern and say whether it is physically possible.
#include <cmath>
#include <filesystem>
#include <map>
#include <iostream>
#include <sstream>
#include <vector>

#include "cli_common.hpp"
#include "progress_line.hpp"
#include "foldkit/dynamics/dynamic_simulate.hpp"
#include "foldkit/geometry/closure.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/parse_error.hpp"
#include "simulation_report.hpp"

namespace foldkit::apps {
namespace {

struct SimulateOptions {
  std::string pattern, sequence, model = simulation::to_string(simulation::SimulationOptions{}.model), frames, svg;
  simulation::SimulationOptions sim;
  dynamics::DynamicOptions dyn;
  std::string gravity, drive = dynamics::to_string(dynamics::DynamicOptions{}.drive), series, fixed, start, joint_torque;
  std::string solver = dynamics::to_string(dynamics::DynamicOptions{}.solver);
  double ground = 0.0, thickness = 0.0, friction = dynamics::kDefaultFriction, density = dynamics::kDefaultDensity;
  bool no_collision = false;
  std::size_t max_frames = 1000;
  // The options of one model only, as declared: given to the other model they are refused.
  std::vector<CLI::Option*> dynamic_only, kinematic_only;
  bool json = false;
};

// "X,Y,Z": three finite numbers (m/s²).
Eigen::Vector3d parse_gravity(const std::string& text) {
  std::istringstream in(text);
  Eigen::Vector3d g;
  char comma1 = 0, comma2 = 0;
  if (!(in >> g.x() >> comma1 >> g.y() >> comma2 >> g.z()) || comma1 != ',' || comma2 != ',' || !(in >> std::ws).eof() ||
      !g.allFinite())
    throw UsageError("--gravity needs three finite numbers X,Y,Z (m/s²), not '" + text + "'");
  return g;
}

// "ID:N·m,…": torque limits of some joints, each a joint of the pattern, positive and finite.
std::map<int, double> parse_joint_torques(const std::string& text, const geometry::CreasePattern& pattern) {
  std::map<int, double> out;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    std::istringstream one(item);
    int id = 0;
    double torque = 0.0;
    char colon = 0;
    if (!(one >> id >> colon >> torque) || colon != ':' || !(one >> std::ws).eof() || !(torque > 0.0) || !std::isfinite(torque))
      throw UsageError("--joint-torque needs ID:N·m,… with positive finite torques, not '" + item + "'");
    if (!pattern.joint_index(id)) throw UsageError("--joint-torque: the pattern has no joint " + std::to_string(id));
    out[id] = torque;
  }
  return out;
}

// The end state of --start's CMML, closed within the tolerance (else FILE:LINE, exit 1).
Eigen::VectorXd start_state(const std::string& cmml, const geometry::CreasePattern& pattern, int root, double tolerance) {
  const geometry::FoldSequence seq = load_sequence(pattern, cmml);
  const geometry::FoldState state = geometry::end_state(pattern, seq);
  int line = 0;
  if (!seq.events.empty())
    for (const auto& f : seq.events.back().folds) line = std::max(line, f.line);
  const double error = geometry::ClosureSystem(pattern, root).max_error(state);
  if (error > tolerance)
    throw io::ParseError(cmml, line, "its end state does not close (loop error " + std::to_string(error) +
                                         " rad, above the closure tolerance): the sheet cannot start there");
  return state.angles;
}

// The physical model's options (foldkit::dynamics): the kinematic options that also apply to it
// carry over when given; density, gravity and the fixed actor given here override the pattern's
// (PMML extensions), which simulate_dynamic() takes where these leave them empty; its own
// defaults otherwise.
dynamics::DynamicOptions dynamic_options(const CLI::App& app, const SimulateOptions& opt,
                                         const geometry::CreasePattern& pattern) {
  dynamics::DynamicOptions o = opt.dyn;
  if (app.count("--time-step")) o.time_step = opt.sim.time_step;
  if (app.count("--closure-tolerance")) o.closure_tolerance = opt.sim.closure_tolerance;
  if (app.count("--max-event-time")) o.max_event_time = opt.sim.max_event_time;
  if (app.count("--density")) o.density = opt.density;
  if (!opt.gravity.empty()) o.gravity = parse_gravity(opt.gravity);
  if (opt.fixed == "none") {
    o.hold_fixed = false;
  } else if (app.count("--fixed")) {
    int id = 0;
    std::istringstream in(opt.fixed);
    if (!(in >> id) || !(in >> std::ws).eof() || !pattern.actor_index(id))
      throw UsageError("--fixed: the pattern has no actor '" + opt.fixed + "' (an actor ID, or none)");
    o.fixed_actor = id;
  }
  if (app.count("--ground")) o.ground = opt.ground;
  if (app.count("--thickness")) o.thickness = opt.thickness;
  // Given without --contacts or --ground, simulate_dynamic() refuses them (std::invalid_argument: usage).
  if (app.count("--friction")) o.friction = opt.friction;
  if (!opt.joint_torque.empty()) o.joint_max_torque = parse_joint_torques(opt.joint_torque, pattern);
  o.drive = dynamics::parse_drive(opt.drive);
  o.solver = dynamics::parse_solver(opt.solver);
  if (!opt.start.empty()) {
    const dynamics::DynamicOptions run = dynamics::resolve_options(pattern, o);  // the held actor: the file's too
    const int root = run.hold_fixed && run.fixed_actor ? *pattern.actor_index(*run.fixed_actor) : 0;
    o.start = start_state(opt.start, pattern, root, o.closure_tolerance);
  }
  return o;
}

// The physical model (foldkit::dynamics).
int run_dynamic(const CLI::App& app, const SimulateOptions& opt, const geometry::CreasePattern& pattern,
                const geometry::FoldSequence& seq) {
  dynamics::DynamicOptions o = dynamic_options(app, opt, pattern);
  o.record_frames = !opt.frames.empty() || !opt.series.empty();
  dynamics::DynamicReport report;
  try {
    ProgressLine progress("simulate");
    o.progress = progress.callback();
    report = dynamics::simulate_dynamic(pattern, seq, o);
  } catch (const simulation::SequenceError& e) {
    throw io::ParseError(opt.sequence, e.line, e.what());
  }
  print_dynamic_summary(opt.sequence, report);
  if (!opt.series.empty()) {
    io::write_file_atomic(opt.series, dynamic_series(pattern, report, opt.series));
    std::cerr << "wrote " << opt.series << '\n';
  }
  const simulation::SimulationReport view = frames_view(report);
  if (!opt.frames.empty()) {
    io::write_file_atomic(opt.frames, trajectory_fold(pattern, view, opt.max_frames));
    std::cerr << "wrote " << opt.frames << '\n';
  }
  if (!opt.svg.empty()) {
    const auto files = write_snapshots(pattern, view, opt.svg);
    std::cerr << "wrote " << files.size() << " snapshots to " << opt.svg << '\n';
  }
  if (opt.json) print_json(dynamic_report_json(pattern, report, o));
  return report.status.ok() ? kOk : kInvalidSequence;
}

int run_kinematic(const SimulateOptions& opt, const geometry::CreasePattern& pattern, const geometry::FoldSequence& seq) {
  simulation::SimulationOptions sim = opt.sim;
  sim.model = simulation::parse_actuation(opt.model);
  sim.collisions = !opt.no_collision;
  sim.record_frames = !opt.frames.empty();
  simulation::SimulationReport report;
  try {
    ProgressLine progress("simulate");
    sim.progress = progress.callback();
    report = simulation::simulate(pattern, seq, sim);
  } catch (const simulation::SequenceError& e) {
    throw io::ParseError(opt.sequence, e.line, e.what());
  }
  print_summary(opt.sequence, report);
  if (!opt.frames.empty()) {
    io::write_file_atomic(opt.frames, trajectory_fold(pattern, report, opt.max_frames));
    std::cerr << "wrote " << opt.frames << '\n';
  }
  if (!opt.svg.empty()) {
    const auto files = write_snapshots(pattern, report, opt.svg);
    std::cerr << "wrote " << files.size() << " snapshots to " << opt.svg << '\n';
  }
  if (opt.json) print_json(report_json(pattern, report));
  return report.status.ok() ? kOk : kInvalidSequence;
}

// The physical model's options (docs/SIMULATION.md, "Dynamic simulation"); their defaults are
// dynamics::DynamicOptions'.
void add_dynamic_options(CLI::App* app, SimulateOptions& opt) {
  opt.dynamic_only = {
      app->add_option("--gravity", opt.gravity,
                      "Dynamic model: gravity X,Y,Z in m/s² (default: the pattern's <Gravity>, else none)"),
      app->add_option("--density", opt.density,
                      "Dynamic model: areal density of the sheet, kg/m² (default: the pattern's <Density>, else 1)")
          ->check(CLI::PositiveNumber),
      positive(app->add_option("--max-torque", opt.dyn.max_torque,
                               "Dynamic model: torque limit of every motor without its own (PMML <MaxTorque>), N·m")),
      app->add_option("--fixed", opt.fixed,
                      "Dynamic model: ID of the actor held in place (default: the pattern's <FixedActor>, else the "
                      "first actor), or none (the whole sheet moves: on --ground, say)"),
      positive(app->add_option("--scale", opt.dyn.scale, "Dynamic model: metres per pattern unit")),
      app->add_option("--drive", opt.drive,
                      "Dynamic model: what drives an event's joints: motor (CMML speed, --max-torque) or "
                      "spring (PMML SpringConst, DampConst)")
          ->check(CLI::IsMember({dynamics::to_string(dynamics::Drive::Motor), dynamics::to_string(dynamics::Drive::Spring)}))
          ->capture_default_str(),
      app->add_option("--ground", opt.ground,
                      "Dynamic model: a ground plane at height Z (metres, normal +z; tilt --gravity for an incline) "
                      "with contacts and friction"),
      app->add_flag("--contacts", opt.dyn.contacts,
                    "Dynamic model: facet-facet contacts with friction (facets not joined by a crease push each "
                    "other apart; a motor they block is a collision)"),
      app->add_option("--friction", opt.friction, "Dynamic model: Coulomb friction coefficient of every contact")
          ->check(CLI::NonNegativeNumber)
          ->capture_default_str(),
      app->add_option("--thickness", opt.thickness,
                      "Dynamic model: sheet thickness for contacts, metres (default: 1/1000 of the sheet's diagonal "
                      "times --scale)")
          ->check(CLI::PositiveNumber),
      app->add_option("--joint-torque", opt.joint_torque,
                      "Dynamic model: torque limits of some motors as ID:N·m,… (the others: --max-torque)"),
      app->add_option("--solver", opt.solver,
                      "Dynamic model: how the engine solves the hinges each step: direct (ODE's dWorldStep: exact, "
                      "cubic in the joints) or iterative (dWorldQuickStep: --iterations sweeps; with "
                      "--projection-interval for closed loops)")
          ->check(CLI::IsMember(
              {dynamics::to_string(dynamics::Solver::Direct), dynamics::to_string(dynamics::Solver::Iterative)}))
          ->capture_default_str(),
      positive(app->add_option("--iterations", opt.dyn.iterations,
                               "Dynamic model: Gauss-Seidel sweeps per step of --solver iterative")
                   ->capture_default_str()),
      app->add_option("--projection-interval", opt.dyn.projection_interval,
                      "Dynamic model: seconds between post-stabilisations (the engine's poses and velocities "
                      "projected onto the closed loops, the motors' joints held); 0: none")
          ->check(CLI::NonNegativeNumber)
          ->capture_default_str(),
      reads(app->add_option("--start", opt.start,
                            "Dynamic model: CMML whose end state the sheet starts from, at rest (default: flat, where "
                            "one motor does not choose the branch)"))};
  writes(app->add_option("--series", opt.series,
                         "Dynamic model: write each joint's angle (degrees) and torque (N·m) every 0.01 s as CSV (.csv) "
                         "or JSON (.json)"));
}

// An option of one model given to the other is a usage error, not ignored: `--gravity 0,0,-9.81
// --max-torque 0.01` without `--model dynamic` would otherwise say "valid" for a kinematic replay.
void check_model_options(const SimulateOptions& opt) {
  const bool dynamic = opt.model == dynamics::kModelName;
  for (const CLI::Option* o : opt.dynamic_only)
    if (!dynamic && o->count() > 0) throw UsageError(o->get_name() + " is an option of --model dynamic");
  for (const CLI::Option* o : opt.kinematic_only)
    if (dynamic && o->count() > 0)
      throw UsageError(o->get_name() + " is not an option of --model dynamic (its contacts are --contacts and --ground)");
}

}  // namespace

Command add_simulate(CLI::App& root) {
  auto opt = std::make_shared<SimulateOptions>();
  CLI::App* app = root.add_subcommand("simulate", "Replay a CMML fold sequence: closure error and self-collision at every step");
  add_pattern(app, opt->pattern);
  reads(app->add_option("sequence", opt->sequence, "Fold sequence (.cmml)"))->required();
  app->add_option("--model", opt->model,
                  "Actuation: motor (CMML speeds), spring (PMML constants), sync (joints arrive together), dynamic "
                  "(a physics engine: masses, torque-limited motors, gravity, contacts)")
      ->check(CLI::IsMember(dynamics::model_names()))
      ->capture_default_str();
  positive(app->add_option("--time-step", opt->sim.time_step, "Seconds per step (dynamic model: default 0.001)"));
  positive(app->add_option("--closure-tolerance", opt->sim.closure_tolerance, "Largest loop error accepted, radians"));
  opt->kinematic_only = {
      app->add_option("--collision-tolerance", opt->sim.collision.tolerance,
                      "Touching distance, relative to the sheet's bounding-box diagonal")
          ->check(CLI::NonNegativeNumber)
          ->capture_default_str(),
      app->add_flag("--no-collision", opt->no_collision, "Check closure only (no collision world is built)")};
  positive(app->add_option("--max-event-time", opt->sim.max_event_time,
                           "Spring model: seconds an event may take to settle (dynamic model: any event; default 60)"));
  add_dynamic_options(app, *opt);
  writes(app->add_option("--frames", opt->frames, "Write the trajectory as FOLD file_frames (.fold)"));
  positive(app->add_option("--max-frames", opt->max_frames, "Frames kept in --frames, evenly thinned"));
  writes_into(app->add_option("--svg", opt->svg, "Folder for SVG snapshots: each event's end and the first collisions"));
  add_json(app, opt->json);
  return {app, [opt, app] {
            if (!opt->frames.empty() && !is_kind(opt->frames, FileKind::Fold))
              throw UsageError("--frames needs a .fold file name, not '" + opt->frames + "'");
            if (!opt->series.empty() && (opt->model != dynamics::kModelName || !is_series_file(opt->series)))
              throw UsageError("--series needs --model dynamic and a .csv or .json file name, not '" + opt->series + "'");
            check_model_options(*opt);
            const geometry::CreasePattern pattern = load_pattern(opt->pattern).pattern;
            const geometry::FoldSequence seq = load_sequence(pattern, opt->sequence);
            if (opt->model == dynamics::kModelName) return run_dynamic(*app, *opt, pattern, seq);
            return run_kinematic(*opt, pattern, seq);
          }};
}

}  // namespace foldkit::apps
