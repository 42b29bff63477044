// foldkit bench-merge: the shard logs of foldkit bench joined into one OMPL log per scene
// (docs/BENCHMARKING.md); every scene is checked before any file is written.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "cli_common.hpp"
#include "foldkit/bench/log.hpp"
#include "foldkit/io/atomic_write.hpp"

namespace foldkit::apps {

Command add_bench_merge(CLI::App& root) {
  struct Options {
    std::vector<std::string> inputs;
    std::string output;
    bool json = false;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* app = root.add_subcommand("bench-merge", "Join the shard logs of foldkit bench into one log per scene");
  reads(app->add_option("dirs", opt->inputs, "Folders holding shard logs (*.log)"))->required();
  writes_into(app->add_option("-o,--output", opt->output, "Output folder"))->required();
  add_json(app, opt->json);
  return {app, [opt]() -> int {
            std::map<std::string, std::vector<std::pair<std::string, bench::BenchLog>>> by_scene;
            for (const std::string& dir : opt->inputs) {
              if (!std::filesystem::is_directory(dir)) throw UsageError(dir + " is not a folder");
              std::vector<std::string> files;
              for (const auto& e : std::filesystem::directory_iterator(dir))
                if (e.is_regular_file() && has_extension(e.path().string(), ".log")) files.push_back(e.path().string());
              std::sort(files.begin(), files.end());
              for (const auto& f : files) {
                bench::BenchLog log;
                try {
                  log = bench::parse_bench_log(io::read_file(f), f);
                } catch (const std::invalid_argument& e) {
                  std::cerr << e.what() << '\n';
                  return kInvalidInput;
                }
                by_scene[log.experiment].emplace_back(f, std::move(log));
              }
            }
            if (by_scene.empty()) throw UsageError("no .log files in the given folders");
            std::filesystem::create_directories(opt->output);
            nlohmann::json scenes = nlohmann::json::array();
            std::vector<std::pair<std::string, std::string>> outputs;
            for (const auto& [scene, entries] : by_scene) {
              std::vector<bench::BenchLog> logs;
              std::vector<std::string> files;
              for (const auto& [f, l] : entries) {
                files.push_back(f);
                logs.push_back(l);
              }
              bench::BenchLog merged;
              try {
                merged = bench::merge_bench_logs(logs, files);
              } catch (const std::invalid_argument& e) {
                std::cerr << "foldkit bench-merge: " << e.what() << '\n';
                return kInvalidInput;
              }
              // The scene name comes from the logs read: it must not lead the file out of -o.
              if (scene.empty() || scene.find_first_of("/\\") != std::string::npos || scene == "." || scene == "..") {
                std::cerr << "foldkit bench-merge: " << files.front() << ": experiment name '" << scene
                          << "' is not a plain file name\n";
                return kInvalidInput;
              }
              const std::string out = (std::filesystem::path(opt->output) / (scene + ".log")).string();
              outputs.emplace_back(out, bench::write_bench_log(merged));
              std::size_t runs = 0;
              for (const auto& p : merged.planners) runs += p.runs.size();
              scenes.push_back({{"scene", scene}, {"log", out}, {"shards", files.size()}, {"runs", runs}});
            }
            // Every scene checked before any file is written: a refused merge leaves nothing behind.
            for (const auto& [path, text] : outputs) {
              io::write_file_atomic(path, text);
              std::cerr << "wrote " << path << '\n';
            }
            if (opt->json) print_json({{"scenes", scenes}});
            return kOk;
          }};
}

}  // namespace foldkit::apps
