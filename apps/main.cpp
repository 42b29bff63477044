#include "cli_app.hpp"

int main(int argc, char** argv) {
  const auto cli = foldkit::apps::make_cli();
  return foldkit::apps::run_cli(*cli, argc, argv);
}
