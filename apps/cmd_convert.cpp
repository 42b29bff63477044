#include <iostream>

#include "cli_common.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/fold_format.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/io/svg.hpp"

namespace foldkit::apps {
namespace {

struct ConvertArgs {
  std::string input, output, pattern;
  bool joint_ids = false;
};

// A CMML is meaningful only with its pattern: FOLD gets one frame per event, SVG the end state.
int convert_sequence(const ConvertArgs& opt) {
  if (opt.pattern.empty()) throw UsageError("converting a .cmml needs --pattern PMML");
  const geometry::CreasePattern pattern = load_pattern(opt.pattern).pattern;
  const geometry::FoldSequence seq = io::read_cmml(opt.input);
  const geometry::Diagnostics problems = geometry::check_sequence(pattern, seq);
  if (geometry::has_errors(problems)) {
    for (const auto& d : problems) std::cerr << geometry::format(d, opt.input) << '\n';
    return kInvalidInput;
  }
  std::vector<geometry::FoldState> states = geometry::event_states(pattern, seq);
  if (is_kind(opt.output, FileKind::Cmml)) {
    io::write_cmml_file(opt.output, seq);
  } else if (is_kind(opt.output, FileKind::Fold)) {
    io::FoldExport extra;
    extra.state = states.back();
    extra.frames.assign(states.begin() + 1, states.end());
    io::write_file_atomic(opt.output, io::write_fold(pattern, extra));
  } else if (is_kind(opt.output, FileKind::Svg)) {
    save_pattern(opt.output, pattern, states.back(), opt.joint_ids);
  } else {
    throw UsageError(opt.output + ": a .cmml converts to .cmml, .fold or .svg");
  }
  return kOk;
}

int run_convert(const ConvertArgs& opt) {
  if (is_kind(opt.input, FileKind::Cmml)) return convert_sequence(opt);
  LoadedPattern loaded = load_pattern(opt.input);
  for (const auto& w : loaded.warnings) std::cerr << geometry::format(w, opt.input) << '\n';
  save_pattern(opt.output, loaded.pattern, loaded.state, opt.joint_ids);
  std::cerr << opt.input << " -> " << opt.output << '\n';
  return kOk;
}

}  // namespace

Command add_convert(CLI::App& root) {
  auto opt = std::make_shared<ConvertArgs>();
  CLI::App* app = root.add_subcommand("convert", "Convert between the formats of docs/FORMATS.md by file extension");
  const std::string written = io::extensions([](const io::FileFormat& f) { return io::writes_patterns(f) || f.sequence; });
  reads(app->add_option("input", opt->input,
                        "Input file: a crease pattern (" + io::extensions(io::reads_patterns) +
                            "), or .cmml with --pattern; any of them may be gzip-compressed (X.cmml.gz)"))
      ->required();
  writes(app->add_option("output", opt->output, "Output file (" + written + "; a trailing .gz compresses it: X.fold.gz)"))->required();
  reads(app->add_option("--pattern", opt->pattern, "The crease pattern a .cmml input folds"));
  app->add_flag("--joint-ids", opt->joint_ids, "Label joints with their IDs in SVG output");
  return {app, [opt] { return run_convert(*opt); }};
}

}  // namespace foldkit::apps
