// `foldkit serve` (docs/SERVE.md) side by side with the way a script reaches the same answer
// without it: one HTTP request (POST /api/VERB, the server runs the CLI as a child process)
// against running `foldkit VERB … --json` itself. The difference is the server's overhead; issue
// 17 asks for the simulate round trip on the demo's patterns under 100 ms. Patterns: the demo's
// Miura-ori 4 × 4 folded to 0.9 and a Miura 10 × 10 folded to 0.5 (`foldkit fold`).
#include <benchmark/benchmark.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include <httplib.h>

namespace {

namespace fs = std::filesystem;

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void run(const std::string& command) {
  if (std::system(command.c_str()) != 0) throw std::runtime_error("failed: " + command);
}

// One server for the whole program, on files made by the CLI in a temporary root.
struct Served {
  std::string root = (fs::temp_directory_path() / ("bench-serve-" + std::to_string(getpid()))).string();
  pid_t pid = -1;
  int port = 0;

  Served() {
    fs::create_directories(root);
    const std::string cli = FOLDKIT_CLI;
    for (const auto& [n, fraction] : {std::pair<int, const char*>{4, "0.9"}, {10, "0.5"}}) {
      const std::string m = root + "/m" + std::to_string(n);
      run(cli + " generate miura --rows " + std::to_string(n) + " --cols " + std::to_string(n) + " -o " + m + ".pmml 2>/dev/null");
      run(cli + " fold " + m + ".pmml --fraction " + fraction + " -o " + m + ".cmml 2>/dev/null");
    }
    const std::string log = root + "/serve.log";
    pid = fork();
    if (pid == 0) {
      freopen(log.c_str(), "w", stderr);
      execl(cli.c_str(), cli.c_str(), "serve", "--port", "0", "--root", root.c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    for (int i = 0; i < 200 && port == 0; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(25));
      const std::string text = slurp(log);
      const auto at = text.find("127.0.0.1:");
      if (at != std::string::npos && text.find('/', at) != std::string::npos) port = std::stoi(text.substr(at + 10));
    }
    if (port == 0) throw std::runtime_error("foldkit serve did not start: " + slurp(log));
  }
  ~Served() {
    kill(pid, SIGTERM);
    waitpid(pid, nullptr, 0);
    fs::remove_all(root);
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
