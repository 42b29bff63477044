#include <filesystem>
#include <functional>
#include <iostream>

#include "cli_common.hpp"
#include "simulation_report.hpp"
#include "foldkit/analysis/load_case.hpp"
#include "foldkit/analysis/solver.hpp"
#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/mobility.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/fold_format.hpp"
#include "foldkit/io/pmml.hpp"
#include "foldkit/simulation/simulate.hpp"

namespace foldkit::apps {
namespace {

namespace gen = geometry::generators;
namespace fs = std::filesystem;

// A zig-zag for a strip: alternate mountain and valley creases, one event per crease, so the
// CMML exercises event order and angle carry-through.
geometry::FoldSequence zigzag(const geometry::CreasePattern& strip, double degrees) {
  geometry::FoldSequence seq{"zig-zag", {}};
  int event = 1;
  for (const auto& j : strip.joints()) {
    const double sign = (event % 2) ? 1.0 : -1.0;
    seq.events.push_back({event++, {{j.id, sign * degrees * M_PI / 180.0, 45.0 * M_PI / 180.0, 0}}});
  }
  return seq;
}

// Replays a sequence (as read back from its file) and writes the trajectory (FOLD frames), the
// report (JSON) and snapshots (SVG) beside it.
nlohmann::json simulation_stage(const geometry::CreasePattern& pattern, const geometry::FoldSequence& seq,
                                const std::string& base, simulation::Actuation model) {
  simulation::SimulationOptions o;
  o.model = model;
  o.record_frames = true;
  const simulation::SimulationReport report = simulation::simulate(pattern, seq, o);
  io::write_file_atomic(base + ".fold", trajectory_fold(pattern, report, 200));
  const nlohmann::json j = report_json(pattern, report);
  io::write_file_atomic(base + "-simulation.json", j.dump(2) + "\n");
  write_snapshots(pattern, report, base + "-snapshots");
  std::cerr << "[demo] " << fs::path(base).filename().string() << ": simulated (" << simulation::to_string(model) << "), "
            << (report.status.ok() ? "valid" : "INVALID") << ", max closure error " << report.max_closure_error << " rad, "
            << report.collision_count << " collisions -> " << base << "{.fold,-simulation.json,-snapshots/}\n";
  return {{"ok", report.status.ok()},  // deprecated: status
          {"status", geometry::to_string(report.status.code)},
          {"max_closure_error", report.max_closure_error},
          {"collisions", report.collision_count},
          {"duration", report.duration},
          {"checks", report.checks}};
}

// Folds a pattern along a path of closed states (each waypoint a fraction of the rough start,
// projected onto closure from the previous one), writes it as CMML (one event per waypoint, the
// joints of each arriving together) and reports mobility before and after.
nlohmann::json fold_stage(const geometry::CreasePattern& pattern, const geometry::FoldState& rough, const std::string& base) {
  const geometry::ClosureSystem system(pattern);
  const int waypoints = 24;
  std::vector<geometry::FoldState> path;
  geometry::FoldState at = geometry::FoldState::flat(pattern);
  geometry::ProjectionResult r;
  for (int k = 1; k <= waypoints; ++k) {
    // The last closed state, moved on by one step of the rough path.
    const geometry::FoldState target{at.angles + rough.angles / waypoints};
    r = geometry::project(system, target);
    if (!r.status.ok()) throw std::runtime_error(base + ": projection failed at waypoint " + std::to_string(k) + ": " + r.status.message);
    at = r.state;
    path.push_back(at);
  }
  const geometry::FoldSequence seq = geometry::path_sequence(pattern, path, 30.0 * M_PI / 180.0, pattern.title() + " folded");
  io::write_file_atomic(base + "-folded.cmml", io::write_cmml(seq));
  nlohmann::json out = {{"dof_flat", geometry::mobility(system, geometry::FoldState::flat(pattern)).dof},
                        {"dof_folded", geometry::mobility(system, r.state).dof},
                        {"closure_error", r.error},
                        {"waypoints", waypoints}};
  return out;
}

// One cube net (10 mm tiles) folded shut, its base fixed, 40 N on its top: the strength analysis
// of the paper's Sec. 5 on the smallest structure it applies to.
nlohmann::json stiffness_stage(const std::string& dir, nlohmann::json& simulations) {
  const geometry::CreasePattern net = geometry::build_or_throw(gen::cube_sheet(1, 0.01));
  const std::string base = (fs::path(dir) / "cube-1").string();
  save_pattern(base + ".pmml", net);
  geometry::FoldState closed = geometry::FoldState::flat(net);
  closed.angles.setConstant(-M_PI / 2);  // every crease of the net is a valley (docs/GENERATORS.md)
  io::write_file_atomic(base + "-folded.cmml", io::write_cmml(geometry::sequence_to(net, closed, M_PI / 6, "cube net folded")));
  io::write_file_atomic(base + "-top-load.loadcase",
                        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<LoadCase>\n  <Title>cube under a top load</Title>\n"
                        "  <Fixed>1</Fixed>\n  <Load><ActorID>3</ActorID><Force>0 0 -40</Force></Load>\n</LoadCase>\n");
  // Read back what was written, as `foldkit stiffness` would.
  const geometry::CreasePattern pattern = load_pattern(base + ".pmml").pattern;
  simulations["cube-1-folded"] =
      simulation_stage(pattern, load_sequence(pattern, base + "-folded.cmml"), base + "-folded", simulation::Actuation::Motor);
  const analysis::LoadCase lc = analysis::read_load_case(base + "-top-load.loadcase");
  const analysis::Problem problem =
      analysis::make_problem(analysis::build_structure(pattern, state_from(pattern, base + "-folded.cmml")), lc, base + "-top-load.loadcase");
  const analysis::SolveResult r = analysis::solve(problem);
  if (!r.status.ok()) throw std::runtime_error(base + ": the stiffness solve did not converge: " + r.status.message);
  int counts[3] = {0, 0, 0};
  for (const auto& c : problem.structure.connections) ++counts[static_cast<int>(c.kind)];
  std::cerr << "[demo] cube-1: folded cube, base fixed, 40 N on top: largest displacement " << r.max_displacement * 1e3
            << " mm (" << r.iterations << " Newton iterations, " << counts[0] << " hinged, " << counts[1] << " face, " << counts[2]
            << " edge connections) -> " << base << "{.pmml,-folded.cmml,-top-load.loadcase}\n";
  return {{"converged", r.status.ok()},  // deprecated: status
          {"status", geometry::to_string(r.status.code)},
          {"max_displacement", r.max_displacement},
          {"iterations", r.iterations},
          {"residual_norm", r.residual_norm},
          {"connections", {{"hinged", counts[0]}, {"face", counts[1]}, {"edge", counts[2]}}}};
}

using RoughStart = std::function<geometry::FoldState(const geometry::CreasePattern&)>;

// A start for the projection, away from the flat state on the side of the intended fold.
RoughStart alternating(double mountain, double valley) {
  return [=](const geometry::CreasePattern& p) {
    geometry::FoldState s = geometry::FoldState::flat(p);
    for (Eigen::Index j = 0; j < s.angles.size(); ++j) s.angles[j] = j % 2 ? valley : mountain;
    return s;
  };
}

RoughStart along_assignment(double magnitude) {
  return [=](const geometry::CreasePattern& p) {
    geometry::FoldState s = geometry::FoldState::flat(p);
    for (std::size_t j = 0; j < p.joints().size(); ++j)
      s.angles[static_cast<Eigen::Index>(j)] =
          p.joints()[j].assignment == geometry::Assignment::Mountain ? magnitude : -magnitude;
    return s;
  };
}

// The boat's keel folds up into a hull; bow and stern keels turn the other way (joint order in
// docs/GENERATORS.md).
geometry::FoldState boat_start(const geometry::CreasePattern& p) {
  geometry::FoldState s = geometry::FoldState::flat(p);
  s.angles << 0.8, -0.8, -0.8, 0.8, -0.8, -0.8, 0, 0, -0.8, -0.8;
  return s;
}

struct Example {
  std::string name;
  geometry::PatternSpec spec;
  RoughStart fold;  // empty: the example is not folded
};

int run_demo(const std::string& dir) {
  fs::create_directories(dir);
  const std::vector<Example> examples = {
      {"degree8-vertex", gen::single_vertex(std::vector<double>(8, M_PI / 4)), alternating(0.5, -0.45)},
      {"boat", gen::boat(), boat_start},
      {"miura-4x4", gen::miura(4, 4), along_assignment(0.6)},
      {"waterbomb-3x4", gen::waterbomb(3, 4), {}},
      {"cube-sheet-2", gen::cube_sheet(2), {}},
      {"strip-5", gen::strip(5), {}},
  };
  nlohmann::json report = {{"output", dir},
                           {"stages", {"generate", "validate", "convert", "kinematics", "simulation", "stiffness"}},
                           {"patterns", nlohmann::json::object()},
                           {"kinematics", nlohmann::json::object()},
                           {"simulation", nlohmann::json::object()}};
  for (const auto& [name, spec, fold] : examples) {
    const geometry::CreasePattern pattern = geometry::build_or_throw(spec);
    const std::string base = (fs::path(dir) / name).string();
    save_pattern(base + ".pmml", pattern);
    save_pattern(base + ".svg", pattern, std::nullopt, true);
    save_pattern(base + ".fold", pattern);
    // Read back what was written: the demo checks the round trip it shows.
    const geometry::CreasePattern again = load_pattern(base + ".pmml").pattern;
    if (io::write_pmml(again) != io::write_pmml(pattern)) throw std::runtime_error(base + ".pmml: round trip changed the pattern");
    report["patterns"][name] = pattern_summary(pattern);
    std::cerr << "[demo] " << name << ": " << pattern.actors().size() << " actors, " << pattern.joints().size()
              << " joints -> " << base << ".{pmml,svg,fold}\n";
    if (fold) {
      const nlohmann::json k = fold_stage(pattern, fold(pattern), base);
      report["kinematics"][name] = k;
      std::cerr << "[demo] " << name << ": DOF " << k["dof_flat"] << " flat, " << k["dof_folded"]
                << " folded (closure error " << k["closure_error"].get<double>() << " rad) -> " << base
                << "-folded.cmml\n";
      report["simulation"][name + "-folded"] = simulation_stage(pattern, io::read_cmml(base + "-folded.cmml"), base + "-folded",
                                                                simulation::Actuation::Motor);
    }
    if (name == "strip-5") {
      const geometry::FoldSequence seq = zigzag(pattern, 90.0);
      io::write_file_atomic(base + "-zigzag.cmml", io::write_cmml(seq));
      std::cerr << "[demo] " << name << ": zig-zag CMML, " << seq.events.size() << " events -> " << base << "-zigzag.cmml\n";
      report["simulation"][name + "-zigzag"] =
          simulation_stage(pattern, io::read_cmml(base + "-zigzag.cmml"), base + "-zigzag", simulation::Actuation::Motor);
    }
  }
  report["stiffness"] = stiffness_stage(dir, report["simulation"]);
  io::write_file_atomic((fs::path(dir) / "report.json").string(), report.dump(2) + "\n");
  std::cerr << "[demo] wrote " << dir << "/report.json\n";
  print_json(report);
  return kOk;
}

}  // namespace

Command add_demo(CLI::App& root) {
  auto dir = std::make_shared<std::string>("foldkit-demo");
  CLI::App* app = root.add_subcommand("demo", "Run the pipeline on built-in examples and write every output to a folder");
  writes_into(app->add_option("-o,--output", *dir, "Output folder"))->capture_default_str();
  return {app, [dir] { return run_demo(*dir); }};
}

}  // namespace foldkit::apps
