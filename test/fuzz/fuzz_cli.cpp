// Any argument vector (the input split at NUL bytes): parsing the foldkit command line either
// succeeds or fails with CLI11's ParseError (usage, help, version) — never a crash, a hang or
// another exception. Commands are parsed but not run (they would read and write files).
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "cli_app.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args;
  std::string current;
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == 0) {
      args.push_back(current);
      current.clear();
      if (args.size() > 64) return 0;
    } else {
      current += static_cast<char>(data[i]);
    }
  }
  args.push_back(current);
  const auto cli = foldkit::apps::make_cli();
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
  try {
    cli->app.parse(reversed);
  } catch (const CLI::ParseError&) {
    return 0;
  }
  // A parse that succeeds chose exactly one verb (require_subcommand(1)).
  int chosen = 0;
  for (const auto& c : cli->commands) chosen += c.app->parsed() ? 1 : 0;
  if (chosen != 1) std::abort();
  return 0;
}
