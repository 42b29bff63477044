// foldkit stiffness: static equilibrium of the folded structure on lumped 6-DOF springs.
#include <cmath>
#include <iostream>

#include "cli_common.hpp"
#include "progress_line.hpp"
#include "foldkit/analysis/load_case.hpp"
#include "foldkit/analysis/solver.hpp"
#include "foldkit/analysis/structure.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/parse_error.hpp"

namespace foldkit::apps {
namespace {

// JSON never carries NaN or inf: a non-finite figure is written as null.
nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }
nlohmann::json vec(const Eigen::Vector3d& v) { return {number(v.x()), number(v.y()), number(v.z())}; }

}  // namespace

Command add_stiffness(CLI::App& root) {
  struct Options {
    std::string pattern, load_case, state;
    bool linear = false, json = false;
    double tolerance = analysis::DetectOptions{}.tolerance;
    analysis::SolveOptions solve;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* app = root.add_subcommand("stiffness", "Static equilibrium of the folded structure under a load case (lumped 6-DOF springs)");
  add_pattern(app, opt->pattern);
  reads(app->add_option("loadcase", opt->load_case, "Load case (.loadcase, see docs/FORMATS.md)"))->required();
  add_state(app, opt->state, "analysed (default: flat)");
  app->add_flag("--linear", opt->linear, "Small displacements: one linear solve");
  positive(app->add_option("--detect-tolerance", opt->tolerance, "Contact detection tolerance, relative to the tile size"));
  positive(app->add_option("--max-iterations", opt->solve.max_total_iterations, "Newton iteration limit over all load steps"));
  add_json(app, opt->json);
  return {app, [opt] {
            const geometry::CreasePattern pattern = load_pattern(opt->pattern).pattern;
            const geometry::FoldState state = state_from(pattern, opt->state);
            const analysis::LoadCase lc = analysis::read_load_case(opt->load_case);
            analysis::DetectOptions detect;
            detect.tolerance = opt->tolerance;
            const analysis::Problem problem = analysis::make_problem(analysis::build_structure(pattern, state, detect), lc, opt->load_case);
            analysis::SolveOptions so = opt->solve;
            so.linear = opt->linear;
            ProgressLine progress("stiffness");
            so.progress = progress.callback();
            const analysis::SolveResult r = analysis::solve(problem, so);
            int counts[3] = {0, 0, 0};
            for (const auto& c : problem.structure.connections) ++counts[static_cast<int>(c.kind)];
            nlohmann::json modules = nlohmann::json::array();
            for (const auto& m : r.modules)
              modules.push_back({{"id", m.id}, {"fixed", m.fixed}, {"displacement", vec(m.displacement)}, {"rotation", vec(m.rotation)}});
            nlohmann::json out = {{"title", lc.title},
                                        {"converged", r.status.ok()},  // deprecated: status
                                        {"linear", opt->linear},
                                        {"iterations", r.iterations},
                                        {"load_steps", r.load_steps},
                                        {"max_displacement", number(r.max_displacement)},
                                        {"residual_norm", r.residual_norm >= 0 ? number(r.residual_norm) : nlohmann::json()},
                                        {"residual_floor", number(r.residual_floor)},
                                        {"condition_estimate", number(r.condition_estimate)},
                                        {"length_unit", number(problem.structure.tile)},
                                        {"connections", {{"hinged", counts[0]}, {"face", counts[1]}, {"edge", counts[2]}}},
                                        {"modules", modules}};
            add_status(out, r.status);
            std::cerr << opt->load_case << ": " << r.status.message << " (" << r.iterations << " iterations, " << counts[0] << " hinged, "
                      << counts[1] << " face, " << counts[2] << " edge connections); largest displacement " << r.max_displacement
                      << ", residual " << r.residual_norm << ", condition ~" << r.condition_estimate << '\n';
            if (opt->json) print_json(out);
            return r.status.ok() ? kOk : kNoPlan;
          }};
}

}  // namespace foldkit::apps
