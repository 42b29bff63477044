#include <iostream>

#include "cli_common.hpp"

namespace foldkit::apps {

Command add_info(CLI::App& root) {
  struct Options {
    std::string file;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* app = root.add_subcommand("info", "Counts and facts about a crease pattern");
  add_pattern(app, opt->file);
  add_json(app, opt->json);
  return {app, [opt] {
            const LoadedPattern loaded = load_pattern(opt->file);
            const nlohmann::json s = pattern_summary(loaded.pattern);
            if (opt->json) {
              print_json(s);
            } else {
              std::cerr << opt->file << ": \"" << s["title"].get<std::string>() << "\"\n";
              for (const char* key : {"actors", "joints", "triangles", "vertices", "interior_vertices", "boundary_vertices"})
                std::cerr << "  " << key << ": " << s[key].dump() << '\n';
              std::cerr << "  interior vertex degrees: " << s["interior_vertex_degrees"].dump() << '\n';
            }
            return kOk;
          }};
}

}  // namespace foldkit::apps
