#pragma once
// The verbs `foldkit serve` runs for a request: which arguments each accepts, how a JSON request
// becomes its command line, and running the CLI itself on it, so that the answer is exactly the
// CLI's (the same code, the same JSON, the same exit code and messages).
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "serve_paths.hpp"

namespace foldkit::apps {

// How a request's value for an argument is checked and passed on.
enum class ArgKind {
  Number,        // a finite JSON number → --name=VALUE
  Integer,       // a JSON integer → --name=VALUE
  Text,          // a JSON string → --name=VALUE
  Texts,         // a JSON array of strings → --name=VALUE for each
  Flag,          // true → --name; false → nothing
  Input,         // a file under the root that exists
  Inputs,        // an array of such files
  Output,        // a file under the root the verb writes
  OutputFolder,  // a folder under the root the verb writes into
};

struct ArgSpec {
  std::string name;         // the CLI's option name without dashes, or the positional's name
  ArgKind kind;
  bool positional = false;  // passed in order, before the options
  bool required = false;
  std::vector<std::string> choices;  // when not empty: the only values a Text argument may take
  std::vector<std::string> aliases;  // the option's other long names (deprecated ones), accepted too
};

struct VerbSpec {
  std::string verb;
  std::vector<ArgSpec> args;
  bool json = true;  // the verb has --json (convert has not)
};

// The verbs a server runs: validate, info, dof, project, simulate, fold, plan, stiffness, convert,
// generate, each with the arguments its CLI subcommand declares (make_cli(): names, required,
// flags, value types, and file roles from cli_common.hpp's reads/writes/writes_into), so that an
// option added to the CLI is served without more code.
const std::vector<VerbSpec>& served_verbs();
// nullptr for a verb the server does not run.
const VerbSpec* find_served_verb(const std::string& verb);

// Limits on the work one request may ask for.
struct WorkLimits {
  double max_plan_time = 60.0;  // seconds: plan's --time is capped to it
  double max_time = 300.0;      // seconds of wall-clock time a verb may run before it is killed
};

// The command line (without the program name) for `spec` from a request object {name: value}.
// Throws UsageError for an unknown or missing argument or a value of the wrong type, PathRefused
// for a path outside the root.
std::vector<std::string> command_line(const VerbSpec& spec, const nlohmann::json& request, const RootedPaths& paths,
                                      const WorkLimits& limits);

// What one run of the CLI printed, and how it ended.
struct VerbRun {
  int exit = 0;            // its exit code; -1 when it was killed or crashed
  std::string out;         // stdout: the --json object
  std::string err;         // stderr: messages and progress
  bool timed_out = false;  // killed after the time limit
  bool flooded = false;    // killed for printing more than the output limit
  int signal = 0;          // the signal that ended it, if one did
};

// Runs `executable` (the foldkit CLI) on `args` as a child process, its stdout and stderr read
// through pipes, killed after `seconds` or when either output passes `max_output` bytes. A
// process rather than a call: a verb that runs away or crashes cannot take the server with it.
VerbRun run_verb(const std::string& executable, const std::vector<std::string>& args, double seconds,
                 std::size_t max_output = std::size_t(64) << 20);

// The path of the running executable (/proc/self/exe).
std::string this_executable();

}  // namespace foldkit::apps
