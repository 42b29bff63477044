// `foldkit serve` (docs/SERVE.md) side by side with the way a script reaches the same answer
// without it: one HTTP request (POST /api/VERB, the server runs the CLI as a child process)
// against running `foldkit VERB … --json` itself. The difference is the server's overhead; issue
// 17 asks for the simulate round trip on the demo's patterns under 100 ms. Patterns: the demo's
// Miura-ori 4 × 4 folded to 0.9 and a Miura 10 × 10 folded to 0.5 (`foldkit fold`).
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include "serve_process.hpp"

#include <httplib.h>  // last: its <resolv.h> macros would break headers included after it

namespace {

namespace fs = std::filesystem;

void run(const std::string& command) {
  if (std::system(command.c_str()) != 0) throw std::runtime_error("failed: " + command);
}

// One server for the whole program, on files made by the CLI in a temporary root.
struct Served {
  // Removed after the server has stopped (members go in reverse order).
  struct Root {
    std::string path;
    ~Root() {
      fs::remove_all(path);
      fs::remove(path + ".log");
    }
  } root_folder{make_root()};
  const std::string& root = root_folder.path;
  foldkit::bench::ServeProcess process{FOLDKIT_CLI, root, root + ".log"};
  int port = process.port();

  static std::string make_root() {
    const std::string root = (fs::temp_directory_path() / ("bench-serve-" + std::to_string(getpid()))).string();
    fs::create_directories(root);
    const std::string cli = FOLDKIT_CLI;
    for (const auto& [n, fraction] : {std::pair<int, const char*>{4, "0.9"}, {10, "0.5"}}) {
      const std::string m = root + "/m" + std::to_string(n);
      run(cli + " generate miura --rows " + std::to_string(n) + " --cols " + std::to_string(n) + " -o " + m + ".pmml 2>/dev/null");
      run(cli + " fold " + m + ".pmml --fraction " + fraction + " -o " + m + ".cmml 2>/dev/null");
    }
    return root;
  }
  Served() {
    if (port == 0) throw std::runtime_error("foldkit serve did not start: " + process.log());
  }
};

Served& served() {
  static Served s;
  return s;
}

const char* const kVerbs[] = {"info", "simulate"};

std::string request_body(int verb, int n) {
  const std::string m = "m" + std::to_string(n);
  return verb == 0 ? "{\"pattern\": \"" + m + ".pmml\"}" : "{\"pattern\": \"" + m + ".pmml\", \"sequence\": \"" + m + ".cmml\"}";
}

// POST /api/VERB, to a server already running (connection per request, as a browser's fetch
// may open).
void BM_Serve(benchmark::State& state) {
  Served& s = served();
  const int verb = static_cast<int>(state.range(0)), n = static_cast<int>(state.range(1));
  const std::string body = request_body(verb, n), path = std::string("/api/") + kVerbs[verb];
  for (auto _ : state) {
    httplib::Client c("127.0.0.1", s.port);
    const auto r = c.Post(path.c_str(), body, "application/json");
    if (!r || r->status != 200) {
      state.SkipWithError("the request failed");
      break;
    }
    benchmark::DoNotOptimize(r->body.data());
  }
}
BENCHMARK(BM_Serve)->ArgNames({"verb", "n"})->ArgsProduct({{0, 1}, {4, 10}})->Unit(benchmark::kMillisecond);

// The same answer from the CLI itself (its process start included, as a script would run it).
void BM_Baseline(benchmark::State& state) {
  Served& s = served();
  const int verb = static_cast<int>(state.range(0)), n = static_cast<int>(state.range(1));
  const std::string m = s.root + "/m" + std::to_string(n);
  const std::string command = std::string(FOLDKIT_CLI) + " " + kVerbs[verb] + " " + m + ".pmml" + (verb == 1 ? " " + m + ".cmml" : "") +
                              " --json >/dev/null 2>&1";
  for (auto _ : state) {
    const int status = std::system(command.c_str());
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
      state.SkipWithError("the CLI failed");
      break;
    }
  }
}
BENCHMARK(BM_Baseline)->ArgNames({"verb", "n"})->ArgsProduct({{0, 1}, {4, 10}})->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
