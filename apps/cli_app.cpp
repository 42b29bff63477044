#include "cli_app.hpp"

#include <iostream>
#include <new>

#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/parse_error.hpp"

namespace foldkit::apps {

std::unique_ptr<Cli> make_cli() {
  auto cli = std::make_unique<Cli>();
  CLI::App& app = cli->app;
  app.set_version_flag("--version", std::string("foldkit 0.1.0"));
  app.require_subcommand(1);
  cli->commands = {add_validate(app), add_info(app),     add_generate(app), add_convert(app),   add_dof(app),
                   add_project(app),  add_simulate(app), add_plan(app),     add_stiffness(app), add_demo(app),
                   add_hamiltonian(app), add_fold(app), add_bench(app), add_bench_merge(app), add_carpenter(app),
                   add_serve(app)};
  return cli;
}

int run_cli(Cli& cli, int argc, const char* const* argv) {
  CLI::App& app = cli.app;
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "foldkit: " << e.what() << "\nRun 'foldkit --help' or 'foldkit VERB --help'.\n";
    return kUsage;
  }
  for (const Command& c : cli.commands) {
    if (!c.app->parsed()) continue;
    try {
      return c.run();
    } catch (const foldkit::io::ParseError& e) {
      std::cerr << e.what() << '\n';
      return kInvalidInput;
    } catch (const UsageError& e) {
      std::cerr << "foldkit " << c.app->get_name() << ": " << e.what() << '\n';
      return kUsage;
    } catch (const foldkit::io::WriteError& e) {
      std::cerr << e.what() << '\n';
      return kInvalidInput;
    } catch (const std::bad_alloc&) {
      std::cerr << "foldkit " << c.app->get_name() << ": out of memory\n";
      return kInvalidInput;
    } catch (const std::invalid_argument& e) {
      std::cerr << "foldkit " << c.app->get_name() << ": " << e.what() << '\n';
      return kUsage;
    } catch (const std::exception& e) {
      std::cerr << "foldkit " << c.app->get_name() << ": " << e.what() << '\n';
      return kInvalidInput;
    }
  }
  return kUsage;
}

}  // namespace foldkit::apps
