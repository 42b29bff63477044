// foldkit project: the closed state nearest to a given one, written as a one-event CMML.
#include <iostream>

#include "cli_common.hpp"
#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/cmml.hpp"

namespace foldkit::apps {

Command add_project(CLI::App& root) {
  struct Options {
    std::string pattern, state, output;
    geometry::ProjectionOptions projection;
    bool free_signs = false;
    double speed = 30.0;  // degrees per second
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* app = root.add_subcommand("project", "Write the nearest closed configuration to a state");
  add_pattern(app, opt->pattern);
  add_state(app, opt->state, "projected")->required();
  writes(app->add_option("-o,--output", opt->output, "Output .cmml: one event from flat to the closed state"))->required();
  positive(app->add_option("--tolerance", opt->projection.tolerance, "Largest loop error accepted, radians"));
  positive(app->add_option("--max-iterations", opt->projection.max_iterations, "Iteration limit"));
  app->add_flag("--free-signs", opt->free_signs, "Let creases change between mountain and valley");
  // --velocity: its name before issue 37 (velocity is fold's desired direction), kept one more release.
  positive(app->add_option("--speed,--velocity", opt->speed,
                           "Speed written into the CMML (its <Velocity>), degrees per second; --velocity is its deprecated name"));
  add_json(app, opt->json);
  return {app, [opt] {
            const geometry::CreasePattern pattern = load_pattern(opt->pattern).pattern;
            const geometry::FoldState start = state_from(pattern, opt->state);
            const geometry::ClosureSystem system(pattern);
            geometry::ProjectionOptions po = opt->projection;
            po.keep_signs = !opt->free_signs;
            const geometry::ProjectionResult r = geometry::project(system, start, po);
            nlohmann::json out = {{"converged", r.status.ok()},  // deprecated: status
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
                                    io::write_cmml(geometry::sequence_to(pattern, r.state, opt->speed * M_PI / 180.0, title)));
            }
            if (opt->json) print_json(out);
            return r.status.ok() ? kOk : kNoPlan;
          }};
}

}  // namespace foldkit::apps
