// foldkit simulate: replay a CMML on a pattern and say whether it is physically possible.
#include <iostream>

#include "cli_common.hpp"
#include "progress_line.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/parse_error.hpp"
#include "simulation_report.hpp"

namespace foldkit::apps {

Command add_simulate(CLI::App& root) {
  struct Options {
    std::string pattern, sequence, model = simulation::to_string(simulation::SimulationOptions{}.model), frames, svg;
    simulation::SimulationOptions sim;
    bool no_collision = false;
    std::size_t max_frames = 1000;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* app = root.add_subcommand("simulate", "Replay a CMML fold sequence: closure error and self-collision at every step");
  add_pattern(app, opt->pattern);
  reads(app->add_option("sequence", opt->sequence, "Fold sequence (.cmml)"))->required();
  app->add_option("--model", opt->model, "Actuation: motor (CMML speeds), spring (PMML constants), sync (joints arrive together)")
      ->check(CLI::IsMember({"motor", "spring", "sync"}))
      ->capture_default_str();
  positive(app->add_option("--time-step", opt->sim.time_step, "Seconds per step"));
  positive(app->add_option("--closure-tolerance", opt->sim.closure_tolerance, "Largest loop error accepted, radians"));
  app->add_option("--collision-tolerance", opt->sim.collision.tolerance,
                  "Touching distance, relative to the sheet's bounding-box diagonal")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  app->add_flag("--no-collision", opt->no_collision, "Check closure only (no collision world is built)");
  positive(app->add_option("--max-event-time", opt->sim.max_event_time, "Spring model: seconds an event may take to settle"));
  writes(app->add_option("--frames", opt->frames, "Write the trajectory as FOLD file_frames (.fold)"));
  positive(app->add_option("--max-frames", opt->max_frames, "Frames kept in --frames, evenly thinned"));
  writes_into(app->add_option("--svg", opt->svg, "Folder for SVG snapshots: each event's end and the first collisions"));
  add_json(app, opt->json);
  return {app, [opt] {
            if (!opt->frames.empty() && !is_kind(opt->frames, FileKind::Fold))
              throw UsageError("--frames needs a .fold file name, not '" + opt->frames + "'");
            const geometry::CreasePattern pattern = load_pattern(opt->pattern).pattern;
            const geometry::FoldSequence seq = load_sequence(pattern, opt->sequence);
            simulation::SimulationOptions sim = opt->sim;
            sim.model = simulation::parse_actuation(opt->model);
            sim.collisions = !opt->no_collision;
            sim.record_frames = !opt->frames.empty();
            simulation::SimulationReport report;
            try {
              ProgressLine progress("simulate");
              sim.progress = progress.callback();
              report = simulation::simulate(pattern, seq, sim);
            } catch (const simulation::SequenceError& e) {
              throw io::ParseError(opt->sequence, e.line, e.what());
            }
            print_summary(opt->sequence, report);
            if (!opt->frames.empty()) {
              io::write_file_atomic(opt->frames, trajectory_fold(pattern, report, opt->max_frames));
              std::cerr << "wrote " << opt->frames << '\n';
            }
            if (!opt->svg.empty()) {
              const auto files = write_snapshots(pattern, report, opt->svg);
              std::cerr << "wrote " << files.size() << " snapshots to " << opt->svg << '\n';
            }
            if (opt->json) print_json(report_json(pattern, report));
            return report.status.ok() ? kOk : kInvalidSequence;
          }};
}

}  // namespace foldkit::apps
