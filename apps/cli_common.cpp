#include "cli_common.hpp"

#include <algorithm>
#include <cctype>
#include <iostream>
#include <map>

#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/fold_format.hpp"
#include "foldkit/io/number_format.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/io/pmml.hpp"
#include "foldkit/io/svg.hpp"

namespace foldkit::apps {

CLI::Option* reads(CLI::Option* option) { return option->type_name(kReadsType); }
CLI::Option* writes(CLI::Option* option) { return option->type_name(kWritesType); }
CLI::Option* writes_into(CLI::Option* option) { return option->type_name(kWritesIntoType); }

CLI::Option* add_pattern(CLI::App* app, std::string& path, const std::string& note) {
  return reads(app->add_option("pattern", path, "Crease pattern (" + io::extensions(io::reads_patterns) + ")" + note))->required();
}

CLI::Option* positive(CLI::Option* option) { return option->check(CLI::PositiveNumber)->capture_default_str(); }

CLI::Option* add_json(CLI::App* app, bool& json) { return app->add_flag("--json", json, "Print one JSON object on stdout"); }

CLI::Option* add_state(CLI::App* app, std::string& path, const std::string& what) {
  return reads(app->add_option("--state", path, "CMML whose end state is " + what));
}

bool is_kind(const std::string& path, FileKind kind) {
  const io::FileFormat* f = io::format_of(path);
  return f && f->kind == kind;
}

// The extension is the user's choice on the command line: a wrong one is a usage error (exit 2),
// also inside commands that turn the libraries' std::invalid_argument into an input error.
LoadedPattern load_pattern(const std::string& path, const geometry::BuildOptions& options) {
  try {
    return io::read_pattern_file(path, options);
  } catch (const io::UnknownFormat& e) {
    throw UsageError(e.what());
  }
}

void save_pattern(const std::string& path, const geometry::CreasePattern& pattern,
                  const std::optional<geometry::FoldState>& state, bool joint_ids) {
  io::PatternOutput output;
  output.state = state ? &*state : nullptr;
  output.joint_ids = joint_ids;
  std::string text;
  try {
    text = io::pattern_text(path, pattern, output);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  io::write_file_atomic(path, text);
}

void add_status(nlohmann::json& j, const geometry::Status& status) {
  j["status"] = geometry::to_string(status.code);
  j["message"] = status.message;
}

void print_json(const nlohmann::json& j) {
  // File names need not be UTF-8; JSON must be.
  std::cout << j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << std::endl;
}

nlohmann::json pattern_summary(const geometry::CreasePattern& p) {
  std::size_t triangles = 0;
  for (const auto& a : p.actors()) triangles += a.triangles.size();
  std::map<std::size_t, int> degrees;
  for (const auto& star : p.interior_vertices()) ++degrees[star.joints.size()];
  nlohmann::json degree_json = nlohmann::json::object();
  for (const auto& [d, n] : degrees) degree_json[std::to_string(d)] = n;
  Eigen::AlignedBox2d box;
  for (const auto& v : p.vertices()) box.extend(v);
  return {{"title", p.title()},
          {"actors", p.actors().size()},
          {"joints", p.joints().size()},
          {"triangles", triangles},
          {"vertices", p.vertices().size()},
          {"interior_vertices", p.vertices().size() - p.boundary_vertex_count()},
          {"boundary_vertices", p.boundary_vertex_count()},
          {"boundary_edges", p.boundary_edges().size()},
          {"interior_vertex_degrees", degree_json},
          {"bounds", {{box.min().x(), box.min().y()}, {box.max().x(), box.max().y()}}}};
}

geometry::FoldSequence load_sequence(const geometry::CreasePattern& pattern, const std::string& cmml) {
  geometry::FoldSequence seq = io::read_cmml(cmml);
  for (const auto& d : geometry::check_sequence(pattern, seq))
    if (d.severity == geometry::Severity::Error) throw io::ParseError(cmml, d.line, d.message);
  return seq;
}

geometry::FoldState state_from(const geometry::CreasePattern& pattern, const std::string& cmml) {
  if (cmml.empty()) return geometry::FoldState::flat(pattern);
  return geometry::end_state(pattern, load_sequence(pattern, cmml));
}

std::vector<std::pair<int, double>> parse_joint_values(const geometry::CreasePattern& pattern, const std::string& text,
                                                       const std::string& option, const std::string& item,
                                                       const std::function<bool(double)>& valid, const std::string& rule) {
  std::vector<std::pair<int, double>> out;
  std::vector<bool> seen(pattern.joints().size(), false);
  std::size_t begin = 0;
  while (begin <= text.size()) {
    const std::size_t end = std::min(text.find(',', begin), text.size());
    const std::string entry = text.substr(begin, end - begin);
    const std::size_t colon = entry.find(':');
    if (colon == std::string::npos) throw UsageError(option + ": '" + entry + "' is not " + item);
    const auto id = io::parse_int(entry.substr(0, colon));
    const io::NumberList value = io::parse_numbers(entry.substr(colon + 1));
    if (!id) throw UsageError(option + ": '" + entry.substr(0, colon) + "' is not a joint ID");
    if (!value.error.empty() || value.values.size() != 1 || !valid(value.values[0]))
      throw UsageError(option + ": '" + entry.substr(colon + 1) + "' is not " + rule);
    const auto j = pattern.joint_index(*id);
    if (!j) throw UsageError(option + ": the pattern has no joint " + std::to_string(*id));
    if (seen[static_cast<std::size_t>(*j)]) throw UsageError(option + ": joint " + std::to_string(*id) + " is named twice");
    seen[static_cast<std::size_t>(*j)] = true;
    out.emplace_back(*j, value.values[0]);
    begin = end + 1;
  }
  return out;
}

}  // namespace foldkit::apps
