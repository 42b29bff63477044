#include <iostream>

#include "cli_common.hpp"
#include "foldkit/geometry/status.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/fold_format.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/io/pmml.hpp"

namespace foldkit::apps {
namespace {

using geometry::Diagnostic;
using geometry::Diagnostics;
using geometry::Severity;

struct ValidateArgs {
  std::vector<std::string> files;
  std::string pattern;
  bool auto_joints = false;
  bool json = false;
};

// Every finding about one file; a ParseError stops the reading of that file only.
Diagnostics check_file(const std::string& path, const ValidateArgs& opt, const std::optional<geometry::CreasePattern>& pattern,
                       std::string& summary) {
  geometry::BuildOptions build;
  build.auto_joints = opt.auto_joints;
  try {
    const io::FileFormat* format = io::format_of(path);
    if (!format || !io::readable(*format))
      return {{Severity::Error, 0, "unknown file type (expected " + io::extensions(io::readable) + ")"}};
    if (format->kind == FileKind::Pmml) {
      // Every problem of the pattern, not only the first that stops its building.
      geometry::BuildResult r = geometry::build_pattern(io::read_pmml_spec(path), build);
      if (r.pattern)
        summary = std::to_string(r.pattern->actors().size()) + " actors, " + std::to_string(r.pattern->joints().size()) +
                  " joints";
      return r.diagnostics;
    }
    if (format->sequence) {
      const geometry::FoldSequence seq = io::read_cmml(path);
      std::size_t folds = 0;
      for (const auto& e : seq.events) folds += e.folds.size();
      summary = std::to_string(seq.events.size()) + " events, " + std::to_string(folds) + " folds";
      if (!pattern) {
        summary += opt.pattern.empty() ? " (not checked against a pattern: give --pattern)"
                                       : " (not checked against " + opt.pattern + ", which is invalid)";
        return {};
      }
      return geometry::check_sequence(*pattern, seq);
    }
    io::PatternFile f = format->read_pattern(path, build);
    summary = std::to_string(f.pattern.actors().size()) + " actors, " + std::to_string(f.pattern.joints().size()) + " joints";
    return f.warnings;
  } catch (const io::ParseError& e) {
    return {{Severity::Error, e.line(), e.message()}};
  }
}

int run_validate(const ValidateArgs& opt) {
  bool all_ok = true;
  nlohmann::json files = nlohmann::json::array();
  std::optional<geometry::CreasePattern> pattern;
  if (!opt.pattern.empty()) {
    // The pattern is checked like any file; CMML files are then checked against it, or not at all.
    geometry::BuildOptions build;
    build.auto_joints = opt.auto_joints;
    try {
      pattern = load_pattern(opt.pattern, build).pattern;
    } catch (const io::ParseError& e) {
      std::cerr << e.what() << '\n';
      all_ok = false;
      files.push_back({{"file", opt.pattern},
                       {"status", geometry::to_string(geometry::StatusCode::InvalidInput)},
                       {"ok", false},  // deprecated: status
                       {"errors", {{{"line", e.line()}, {"message", e.message()}}}},
                       {"warnings", nlohmann::json::array()}});
    }
  }
  for (const std::string& path : opt.files) {
    std::string summary;
    const Diagnostics found = check_file(path, opt, pattern, summary);
    const bool ok = !geometry::has_errors(found);
    all_ok = all_ok && ok;
    nlohmann::json errors = nlohmann::json::array(), warnings = nlohmann::json::array();
    for (const Diagnostic& d : found) {
      std::cerr << geometry::format(d, path) << '\n';
      (d.severity == Severity::Error ? errors : warnings).push_back({{"line", d.line}, {"message", d.message}});
    }
    if (ok) std::cerr << path << ": ok" << (summary.empty() ? "" : " (" + summary + ")") << '\n';
    files.push_back({{"file", path},
                     {"status", geometry::to_string(ok ? geometry::StatusCode::Success : geometry::StatusCode::InvalidInput)},
                     {"ok", ok},  // deprecated: status
                     {"errors", errors},
                     {"warnings", warnings}});
  }
  if (opt.json) {
    nlohmann::json j{{"ok", all_ok}, {"files", files}};  // "ok": deprecated, status
    add_status(j, all_ok ? geometry::Status{geometry::StatusCode::Success, "every file is valid"}
                         : geometry::Status{geometry::StatusCode::InvalidInput, "a file has errors"});
    print_json(j);
  }
  return all_ok ? kOk : kInvalidInput;
}

}  // namespace

Command add_validate(CLI::App& root) {
  auto opt = std::make_shared<ValidateArgs>();
  CLI::App* app = root.add_subcommand("validate", "Check PMML, CMML and FOLD files; print every problem as FILE:LINE: message");
  reads(app->add_option("files", opt->files, "Files to check (" + io::extensions(io::readable) + ")"))->required();
  reads(app->add_option("--pattern", opt->pattern, "Crease pattern (" + io::extensions(io::reads_patterns) + ") to check CMML files against"));
  app->add_flag("--auto-joints", opt->auto_joints, "Treat an edge shared by two actors without a joint as a joint");
  add_json(app, opt->json);
  return {app, [opt] { return run_validate(*opt); }};
}

}  // namespace foldkit::apps
