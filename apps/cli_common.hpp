#pragma once
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/geometry/status.hpp"
#include "foldkit/io/file_name.hpp"
#include "foldkit/io/formats.hpp"

namespace foldkit::apps {

// Exit codes, as docs/CLI.md lists them.
enum Exit : int { kOk = 0, kInvalidInput = 1, kUsage = 2, kInvalidSequence = 3, kNoPlan = 4 };

// A subcommand and what runs when it was chosen; run() returns the exit code.
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};

Command add_validate(CLI::App& root);
Command add_info(CLI::App& root);
Command add_generate(CLI::App& root);
Command add_convert(CLI::App& root);
Command add_demo(CLI::App& root);
Command add_dof(CLI::App& root);
Command add_project(CLI::App& root);
Command add_simulate(CLI::App& root);
Command add_plan(CLI::App& root);
Command add_stiffness(CLI::App& root);
Command add_hamiltonian(CLI::App& root);
Command add_carpenter(CLI::App& root);
Command add_fold(CLI::App& root);
Command add_bench(CLI::App& root);
Command add_bench_merge(CLI::App& root);
Command add_serve(CLI::App& root);

// File arguments say what is done with them in their type name, which --help shows and from
// which `foldkit serve` derives how it checks a request's paths against its root
// (serve_verbs.cpp): read, written, or a folder written into. Each returns `option`.
inline constexpr const char* kReadsType = "FILE";
inline constexpr const char* kWritesType = "OUT";
inline constexpr const char* kWritesIntoType = "DIR";
CLI::Option* reads(CLI::Option* option);
CLI::Option* writes(CLI::Option* option);
CLI::Option* writes_into(CLI::Option* option);

// The positional PATTERN of every verb that takes one, required, its formats listed from io's
// table; `note` is appended to the description.
CLI::Option* add_pattern(CLI::App* app, std::string& path, const std::string& note = "");

// A positive number whose default --help shows. Returns `option`.
CLI::Option* positive(CLI::Option* option);
// --json: print one JSON object on stdout (every verb that reports has it).
CLI::Option* add_json(CLI::App* app, bool& json);
// --state CMML: the end state of a fold sequence, `what` is done with it ("analysed (default:
// flat)", "projected").
CLI::Option* add_state(CLI::App* app, std::string& path, const std::string& what);

// Usage errors (bad parameters the parser could not catch) are thrown as UsageError → exit 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The formats by extension: one table, io::file_formats() (foldkit/io/formats.hpp).
using io::FileKind;
// Whether `path`'s extension names the format `kind` (ignoring case).
bool is_kind(const std::string& path, FileKind kind);
// Whether `path` ends with `extension` (".csv"), ignoring case.
using io::has_extension;

// A crease pattern by the extension of `path` (io::read_pattern_file: pattern, the fold angles
// the file carried, warnings); throws ParseError, UsageError for an extension no pattern has.
using LoadedPattern = io::PatternFile;
LoadedPattern load_pattern(const std::string& path, const geometry::BuildOptions& options = {});

// Writes by the extension of `path` (io::pattern_text: .pmml, .fold, .svg; .cmml needs a state),
// atomically; UsageError for an extension no pattern is written as.
void save_pattern(const std::string& path, const geometry::CreasePattern& pattern,
                  const std::optional<geometry::FoldState>& state = std::nullopt, bool joint_ids = false);

// A CMML checked against its pattern: ParseError at the CMML's line for joints the pattern lacks
// or a joint twice in one event.
geometry::FoldSequence load_sequence(const geometry::CreasePattern& pattern, const std::string& cmml);

// The state at the end of a CMML (angles carried through from flat), or flat for an empty path;
// ParseError at the CMML's line for joints the pattern lacks.
geometry::FoldState state_from(const geometry::CreasePattern& pattern, const std::string& cmml);

// One JSON object on stdout.
void print_json(const nlohmann::json& j);

// The keys every verb's JSON carries for how its algorithm ended: "status" (the code's name,
// geometry::to_string) and "message".
void add_status(nlohmann::json& j, const geometry::Status& status);

// "ID:VALUE,ID:VALUE,…" → (joint index, value) per named joint of `pattern`. `option` names the
// option in messages, `item` the expected item ("ID:DEGREES"); a value for which `valid` is false
// is refused as "not <rule>". UsageError on any bad item, unknown joint or joint named twice.
std::vector<std::pair<int, double>> parse_joint_values(const geometry::CreasePattern& pattern, const std::string& text,
                                                       const std::string& option, const std::string& item,
                                                       const std::function<bool(double)>& valid, const std::string& rule);

// Facts `foldkit info` reports, shared with the demo.
nlohmann::json pattern_summary(const geometry::CreasePattern& pattern);

}  // namespace foldkit::apps
