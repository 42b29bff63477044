// foldkit dof: the mobility of a pattern at a state (creases minus the closure Jacobian's rank).
#include <iostream>

#include "cli_common.hpp"
#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/mobility.hpp"

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
  add_state(app, opt->state, "analysed (default: flat)");
  positive(app->add_option("--tolerance", opt->tolerance, "Rank tolerance, relative to the largest singular value"));
  add_json(app, opt->json);
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

}  // namespace foldkit::apps
