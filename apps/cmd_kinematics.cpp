// foldkit dof / foldkit project: mobility and closure of a pattern at a state.
#include <iostream>

#include "cli_common.hpp"
#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/mobility.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/parse_error.hpp"

namespace foldkit::apps {

Command add_dof(CLI::App& root) {
  struct Options {
    std::string pattern, state;
    double tolerance = geometry::kMobilityTolerance;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* app = root.add_subcommand("dof", "Instantaneous degrees of freedom: creases minus the rank of the closure Jacobian");
  add_pattern(app, opt->pattern);
  reads(app->add_option("--state", opt->state, "CMML whose end state is analysed (default: flat)"));
  app->add_option("--tolerance", opt->tolerance, "Rank tolerance, relative to the largest singular value")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app->add_flag("--json", opt->json, "Print one JSON object on stdout");
  return {app, [opt] {
            const geometry::CreasePattern pattern = load_pattern(opt->pattern).pattern;
            const geometry::FoldState state = state_from(pattern, opt->state);
            const geometry::ClosureSystem system(pattern);
            const geometry::Mobility m = geometry::mobility(system, state, opt->tolerance);
            const double error = system.max_error(state);
            const nlohmann::json out = {{"dof", m.dof},
                                        {"rank", m.rank},
                                        {"creases", m.creases},
                                        {"tolerance", m.tolerance},
                                        {"method", m.method},
                                        {"largest_zero_singular_value", m.decision.largest_zero},
                                        {"smallest_kept_singular_value", m.decision.smallest_kept},
                                        {"rank_gap", m.decision.gap()},
                                        {"vertex_loops", system.vertex_loops()},
                                        {"hole_cycles", system.hole_cycles()},
                                        {"closure_error", error}};
            std::cerr << opt->pattern << ": " << m.dof << " DOF (" << m.creases << " creases, rank " << m.rank << " at tolerance "
                      << m.tolerance << ", " << m.method << ", singular-value gap " << m.decision.gap() << ")";
            if (error > 1e-9) std::cerr << "; warning: the state is not closed (error " << error << " rad)";
            std::cerr << '\n';
            if (opt->json) print_json(out);
            return kOk;
          }};
}

Command add_project(CLI::App& root) {
  struct Options {
    std::string pattern, state, output;
    geometry::ProjectionOptions projection;
    bool free_signs = false;
    double velocity = 30.0;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* app = root.add_subcommand("project", "Write the nearest closed configuration to a state");
  add_pattern(app, opt->pattern);
  reads(app->add_option("--state", opt->state, "CMML whose end state is projected"))->required();
  writes(app->add_option("-o,--output", opt->output, "Output .cmml: one event from flat to the closed state"))->required();
  app->add_option("--tolerance", opt->projection.tolerance, "Largest loop error accepted, radians")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app->add_option("--max-iterations", opt->projection.max_iterations, "Iteration limit")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app->add_flag("--free-signs", opt->free_signs, "Let creases change between mountain and valley");
  app->add_option("--velocity", opt->velocity, "Velocity written into the CMML, degrees per second")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app->add_flag("--json", opt->json, "Print one JSON object on stdout");
  return {app, [opt] {
            const geometry::CreasePattern pattern = load_pattern(opt->pattern).pattern;
            const geometry::FoldState start = state_from(pattern, opt->state);
            const geometry::ClosureSystem system(pattern);
            geometry::ProjectionOptions po = opt->projection;
            po.keep_signs = !opt->free_signs;
            const geometry::ProjectionResult r = geometry::project(system, start, po);
            nlohmann::json out = {{"converged", r.status.ok()},
                                  {"iterations", r.iterations},
                                  {"closure_error", r.error},
                                  {"initial_error", system.max_error(start)},
                                  {"output", r.status.ok() ? nlohmann::json(opt->output) : nlohmann::json()}};
            add_status(out, r.status);
            std::cerr << opt->pattern << ": " << r.status.message << " after " << r.iterations << " iterations, closure error "
                      << r.error << " rad\n";
            if (r.status.ok()) {
              const std::string title = pattern.title().empty() ? "projected" : pattern.title() + " (projected)";
              io::write_file_atomic(opt->output,
                                    io::write_cmml(geometry::sequence_to(pattern, r.state, opt->velocity * M_PI / 180.0, title)));
            }
            if (opt->json) print_json(out);
            return r.status.ok() ? kOk : kNoPlan;
          }};
}

}  // namespace foldkit::apps
