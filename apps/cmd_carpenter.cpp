// foldkit carpenter: Carpenter's rule — straighten an open planar chain, convexify a closed one
// (docs/CARPENTER.md), or flatten a single-vertex crease pattern on the sphere.
#include <algorithm>
#include <limits>
#include <iostream>
#include <stdexcept>

#include "cli_common.hpp"
#include "progress_line.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/chain_file.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/folding/carpenter.hpp"
#include "foldkit/folding/carpenter_spherical.hpp"

namespace foldkit::apps {
namespace {

struct CarpenterArgs {
  std::string chain, output, frames_csv, state;
  bool closed = false, fold = false, json = false;
  std::string method = folding::to_string(folding::CarpenterPlanarOptions{}.method);  // folding::parse_carpenter_method
  std::size_t max_steps = folding::CarpenterPlanarOptions{}.max_steps;
  std::size_t frame_stride = folding::CarpenterPlanarOptions{}.frame_stride;
  bool frame_stride_given = false;  // --frame-stride on the command line (planar chains only)
};

// Whether `path` names an output of that extension, plain or gzip-compressed (X.cmml.gz:
// io::write_file_atomic compresses what it writes to a .gz path, as every other verb's writer).
bool is_output(const std::string& path, const std::string& extension) {
  return has_extension(path, extension) || has_extension(path, extension + ".gz");
}

// A single-vertex crease pattern (PMML or FOLD) in the state of --state (or the FOLD file's own
// fold angles): flattened on the sphere by the spherical Carpenter's rule.
int run_spherical(const CarpenterArgs& opt) {
  if (opt.closed) throw UsageError("--closed is for planar chains; a single vertex is always a closed spherical chain");
  if (!opt.frames_csv.empty()) throw UsageError("--frames-csv is for planar chains");
  if (opt.frame_stride_given) throw UsageError("--frame-stride is for planar chains");
  LoadedPattern loaded = load_pattern(opt.chain);
  geometry::FoldState folded = loaded.state ? *loaded.state : geometry::FoldState::flat(loaded.pattern);
  if (!opt.state.empty()) folded = state_from(loaded.pattern, opt.state);
  else if (!loaded.state) throw UsageError(opt.chain + ": a single vertex needs its folded state: --state FOLDED.cmml");
  const folding::CarpenterSphericalResult r = [&] {
    try {
      folding::CarpenterSphericalOptions options;
      options.max_steps = static_cast<int>(std::min<std::size_t>(opt.max_steps, std::numeric_limits<int>::max()));
      return folding::flatten_single_vertex(loaded.pattern, folded, options);
    } catch (const std::invalid_argument& e) {
      throw io::ParseError(opt.chain, 0, e.what());
    }
  }();
  if (!opt.output.empty()) {
    if (!is_output(opt.output, ".cmml")) throw UsageError(opt.output + ": a single vertex's output is CMML (.cmml or .cmml.gz)");
    io::write_cmml_file(opt.output, r.folding);
  }
  std::cerr << opt.chain << ": " << (r.status.ok() ? "flattened" : "not flattened") << " in " << r.steps << " steps: " << r.status.message
            << '\n';
  if (opt.json) {
    nlohmann::json j{{"spherical", true},
                     {"steps", r.steps},
                     {"frames", r.frames.size()},
                     {"max_length_error", r.max_sector_error},
                     {"min_distance_growth", r.min_distance_growth},
                     {"max_closure_error", r.max_closure_error},
                     {"flat", r.status.ok()}};  // deprecated: status
    add_status(j, r.status);
    print_json(j);
  }
  return r.status.ok() ? kOk : kNoPlan;
}

// `--json` of a planar chain: every metric of CarpenterPlanarResult under its own name, as
// Python's CarpenterResult has it (docs/CARPENTER.md, Metrics). Unpacked member by member so that
// a metric added to the result stops this from compiling until it is printed here too.
nlohmann::json planar_json(const CarpenterArgs& opt, std::size_t vertices, const folding::CarpenterPlanarResult& r) {
  const auto& [frames, closed, status, steps, lp_solves, carried_steps, window_lp_solves, held_steps, max_struts, flips,
               straightenings, pseudo_lp_steps, certificate_seconds, seconds, max_length_error, min_distance_growth] = r;
  nlohmann::json j{{"closed", closed},
                   {"vertices", vertices},
                   {"method", opt.method},
                   {"steps", steps},
                   {"frames", frames.size()},
                   {"lp_solves", lp_solves},
                   {"window_lp_solves", window_lp_solves},
                   {"carried_steps", carried_steps},
                   {"held_steps", held_steps},
                   {"max_struts", max_struts},
                   {"flips", flips},
                   {"straightenings", straightenings},
                   {"pseudo_lp_steps", pseudo_lp_steps},
                   {"certificate_seconds", certificate_seconds},
                   {"seconds", seconds},
                   {"time", seconds},  // deprecated: the name of `seconds` before issue 37
                   {"max_length_error", max_length_error},
                   {"min_distance_growth", min_distance_growth},
                   {closed ? "convex" : "straight", status.ok()}};  // deprecated: status
  add_status(j, status);
  return j;
}

int run_planar(const CarpenterArgs& opt) {
  if (!opt.output.empty() && !is_output(opt.output, ".cmml") && !is_output(opt.output, ".json") && !is_output(opt.output, ".csv"))
    throw UsageError(opt.output + ": unknown output format (expected .cmml, .json or .csv, each optionally .gz)");
  folding::PlanarChain chain{io::parse_chain_points(io::read_file(opt.chain), opt.chain), opt.closed};
  try {
    folding::check_simple_chain(chain);
  } catch (const std::invalid_argument& e) {
    throw io::ParseError(opt.chain, 0, e.what());
  }
  folding::CarpenterPlanarOptions options;
  options.max_steps = opt.max_steps;
  options.frame_stride = opt.frame_stride;
  options.method = folding::parse_carpenter_method(opt.method);
  ProgressLine progress("carpenter");
  options.progress = progress.callback();
  const folding::CarpenterPlanarResult r = folding::carpenter_planar(chain, options);
  const std::vector<folding::Frame2> frames = opt.fold ? folding::reversed(r.frames) : r.frames;
  if (!opt.output.empty()) {
    std::string text;
    if (is_output(opt.output, ".cmml"))
      text = io::write_cmml(folding::turning_angle_sequence(frames, opt.closed, opt.chain));
    else if (is_output(opt.output, ".json"))
      text = io::frames_json(frames, opt.closed);
    else
      text = io::frames_csv(frames);
    io::write_file_atomic(opt.output, text);
  }
  if (!opt.frames_csv.empty()) io::write_file_atomic(opt.frames_csv, io::frames_csv(frames));
  const char* goal = opt.closed ? "convex" : "straight";
  if (r.status.ok())
    std::cerr << opt.chain << ": " << goal << " after " << r.steps << " steps, " << r.frames.size() << " frames ("
              << r.seconds << " s)\n";
  else
    std::cerr << opt.chain << ": not " << goal << ": " << r.status.message << '\n';
  if (opt.json) print_json(planar_json(opt, chain.points.size(), r));
  return r.status.ok() ? kOk : kNoPlan;
}

}  // namespace

Command add_carpenter(CLI::App& root) {
  auto opt = std::make_shared<CarpenterArgs>();
  CLI::App* app = root.add_subcommand(
      "carpenter", "Carpenter's rule: straighten a planar chain, convexify a polygon, or flatten a single vertex");
  reads(app->add_option("chain", opt->chain,
                        "Chain file: one 'x y' per line ('#' comments); or a single-vertex crease pattern (" +
                            io::extensions(io::reads_patterns) + ")"))
      ->required();
  app->add_flag("--closed", opt->closed, "The chain is a polygon (last point joins the first): convexify it");
  writes(app->add_option("-o,--output", opt->output,
                         "Write the motion: .cmml (turning angles, docs/CARPENTER.md), .json or .csv (frames)"));
  writes(app->add_option("--frames-csv", opt->frames_csv, "Also write the frames as CSV: frame,vertex,x,y"));
  app->add_flag("--fold", opt->fold, "Write the frames backwards: the folding motion, straight (convex) to the input");
  reads(app->add_option("--state", opt->state, "Single vertex: CMML whose end state is the folded input"));
  app->add_option("--method", opt->method,
                  "Planar chains: 'carried' (default: the last step's motion carried over each event, mended "
                  "by small LPs), 'lp' (one global LP per step, the baseline) or 'pseudo' (Streinu's "
                  "pseudo-triangulation mechanism, flips at events); docs/CARPENTER.md")
      ->check(CLI::IsMember(folding::carpenter_method_names()));
  positive(app->add_option("--max-steps", opt->max_steps, "Stop after this many steps (exit 4)"));
  CLI::Option* stride = positive(app->add_option(
      "--frame-stride", opt->frame_stride,
      "Planar chains: write one frame every N steps (the input and the end always): a chain of thousands of "
      "links takes thousands of steps, each a frame of every vertex otherwise"));
  add_json(app, opt->json);
  return {app, [opt, stride] {
            opt->frame_stride_given = stride->count() > 0;
            const io::FileFormat* format = io::format_of(opt->chain);
            if (format && io::reads_patterns(*format)) return run_spherical(*opt);
            if (!opt->state.empty()) throw UsageError("--state is for a single-vertex crease pattern (.pmml, .fold)");
            return run_planar(*opt);
          }};
}

}  // namespace foldkit::apps
