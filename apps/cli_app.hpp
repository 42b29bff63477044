#pragma once
#include <memory>
#include <vector>

#include "cli_common.hpp"

namespace foldkit::apps {

// The whole command line: every verb with its options, and what runs for each.
struct Cli {
  CLI::App app{"foldkit: plan, simulate and analyse foldable programmable matter"};
  std::vector<Command> commands;
};
std::unique_ptr<Cli> make_cli();

// Parses argv and runs the chosen verb; returns the exit code of docs/CLI.md (errors are printed
// on stderr, never thrown).
int run_cli(Cli& cli, int argc, const char* const* argv);

}  // namespace foldkit::apps
