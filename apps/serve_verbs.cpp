#include "serve_verbs.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_common.hpp"

extern char** environ;

namespace foldkit::apps {

namespace {

using K = ArgKind;

ArgSpec positional_arg(std::string name, ArgKind kind, bool required = true) { return {std::move(name), kind, true, required, {}}; }
ArgSpec option_arg(std::string name, ArgKind kind, bool required = false) { return {std::move(name), kind, false, required, {}}; }

std::string number_text(double v) {
  std::ostringstream out;
  out.precision(17);
  out << v;
  return out.str();
}

// The value of one argument as command-line words.
void append_words(const ArgSpec& a, const nlohmann::json& v, const RootedPaths& paths, std::vector<std::string>& words) {
  const std::string flag = "--" + a.name + "=";
  // The value's type, not its text: a client's value may be nested arbitrarily deep or be huge.
  const auto wrong = [&](const char* expected) {
    return UsageError("'" + a.name + "': expected " + expected + ", got " + (v.is_primitive() && !v.is_string() ? v.dump() : v.type_name()));
  };
  const auto word = [&](const std::string& value) { words.push_back(a.positional ? value : flag + value); };
  switch (a.kind) {
    case K::Number:
      if (!v.is_number() || !std::isfinite(v.get<double>())) throw wrong("a finite number");
      return word(number_text(v.get<double>()));
    case K::Integer:
      if (!v.is_number_integer() || (v.is_number_unsigned() && v.get<unsigned long long>() > 1ull << 62)) throw wrong("an integer");
      return word(std::to_string(v.get<long long>()));
    case K::Text:
      if (!v.is_string()) throw wrong("a string");
      if (!a.choices.empty() && std::find(a.choices.begin(), a.choices.end(), v.get<std::string>()) == a.choices.end()) {
        std::string list;
        for (const auto& c : a.choices) list += (list.empty() ? "" : ", ") + c;
        throw UsageError("'" + a.name + "': expected one of " + list + ", got '" + v.get<std::string>() + "'");
      }
      return word(v.get<std::string>());
    case K::Texts:
      if (!v.is_array()) throw wrong("an array of strings");
      for (const auto& item : v) {
        if (!item.is_string()) throw wrong("an array of strings");
        word(item.get<std::string>());
      }
      return;
    case K::Flag:
      if (!v.is_boolean()) throw wrong("true or false");
      if (v.get<bool>()) words.push_back("--" + a.name);
      return;
    case K::Input:
      if (!v.is_string()) throw wrong("a file name under the server's root");
      return word(paths.input(v.get<std::string>()).string());
    case K::Inputs:
      if (!v.is_array() || v.empty()) throw wrong("an array of file names under the server's root");
      for (const auto& item : v) {
        if (!item.is_string()) throw wrong("an array of file names under the server's root");
        word(paths.input(item.get<std::string>()).string());
      }
      return;
    case K::Output:
      if (!v.is_string()) throw wrong("a file name under the server's root");
      return word(paths.output(v.get<std::string>()).string());
    case K::OutputFolder:
      if (!v.is_string()) throw wrong("a folder name under the server's root");
      return word(paths.output_folder(v.get<std::string>()).string());
  }
}

// `generate KIND`: the kind is checked against the generators (a free word could be an option),
// every generator's options are accepted and the CLI refuses those the kind does not have.
std::vector<ArgSpec> generate_args() {
  ArgSpec kind = positional_arg("kind", K::Text);
  kind.choices = {"single-vertex", "strip", "grid", "circular", "miura", "waterbomb", "boat", "cube-sheet", "square-twist"};
  std::vector<ArgSpec> args = {kind, option_arg("output", K::Output, true), option_arg("title", K::Text), option_arg("sectors", K::Text)};
  for (const char* n : {"rows", "cols", "units", "cubes", "rings", "spokes", "degree", "panels", "seed"}) args.push_back(option_arg(n, K::Integer));
  for (const char* n : {"spring", "damping", "a", "b", "angle", "length", "half-width", "bow", "tile", "cell", "ring-width", "width", "height",
                        "side", "twist", "pleat", "radius"})
    args.push_back(option_arg(n, K::Number));
  return args;
}

}  // namespace

const std::vector<VerbSpec>& served_verbs() {
  static const std::vector<VerbSpec> verbs = {
      {"validate", {positional_arg("files", K::Inputs), option_arg("pattern", K::Input), option_arg("auto-joints", K::Flag)}},
      {"info", {positional_arg("pattern", K::Input)}},
      {"dof", {positional_arg("pattern", K::Input), option_arg("state", K::Input), option_arg("tolerance", K::Number)}},
      {"project",
       {positional_arg("pattern", K::Input), option_arg("state", K::Input, true), option_arg("output", K::Output, true), option_arg("tolerance", K::Number),
        option_arg("max-iterations", K::Integer), option_arg("free-signs", K::Flag), option_arg("velocity", K::Number)}},
      {"simulate",
       {positional_arg("pattern", K::Input), positional_arg("sequence", K::Input), option_arg("model", K::Text), option_arg("time-step", K::Number),
        option_arg("closure-tolerance", K::Number), option_arg("collision-tolerance", K::Number), option_arg("no-collision", K::Flag),
        option_arg("max-event-time", K::Number), option_arg("frames", K::Output), option_arg("max-frames", K::Integer), option_arg("svg", K::OutputFolder)}},
      {"fold",
       {positional_arg("pattern", K::Input), option_arg("fraction", K::Number), option_arg("step", K::Number), option_arg("chord-tolerance", K::Number),
        option_arg("max-steps", K::Integer), option_arg("velocity", K::Text), option_arg("toward", K::Input), option_arg("no-collision", K::Flag), option_arg("partial", K::Flag),
        option_arg("output", K::Output, true)}},
      {"plan",
       {positional_arg("pattern", K::Input), option_arg("goal", K::Input), option_arg("goal-angles", K::Text), option_arg("start", K::Input), option_arg("space", K::Text),
        option_arg("planner", K::Text), option_arg("param", K::Texts), option_arg("time", K::Number), option_arg("seed", K::Integer),
        option_arg("no-collision", K::Flag), option_arg("search-margin", K::Number), option_arg("free-signs", K::Flag), option_arg("no-fallback", K::Flag),
        option_arg("output", K::Output, true)}},
      {"stiffness",
       {positional_arg("pattern", K::Input), positional_arg("loadcase", K::Input), option_arg("state", K::Input), option_arg("linear", K::Flag),
        option_arg("detect-tolerance", K::Number), option_arg("max-iterations", K::Integer)}},
      {"convert", {positional_arg("input", K::Input), positional_arg("output", K::Output), option_arg("pattern", K::Input), option_arg("joint-ids", K::Flag)}, false},
      {"generate", generate_args()},
  };
  return verbs;
}

const VerbSpec* find_served_verb(const std::string& verb) {
  for (const auto& v : served_verbs())
    if (v.verb == verb) return &v;
  return nullptr;
}

std::vector<std::string> command_line(const VerbSpec& spec, const nlohmann::json& request, const RootedPaths& paths,
                                      const WorkLimits& limits) {
  if (!request.is_object()) throw UsageError("the request body must be a JSON object of the verb's arguments");
  for (const auto& [key, value] : request.items()) {
    bool known = false;
    for (const auto& a : spec.args) known = known || a.name == key;
    if (!known) throw UsageError("'" + key + "': " + spec.verb + " takes no such argument (see docs/SERVE.md)");
  }
  nlohmann::json r = request;
  if (spec.verb == "plan") {  // the one verb whose work a request sets directly
    const double time = r.contains("time") && r["time"].is_number() ? r["time"].get<double>() : 5.0;
    if (time > limits.max_plan_time) r["time"] = limits.max_plan_time;
  }
  std::vector<std::string> words = {spec.verb};
  for (bool positional : {true, false})
    for (const auto& a : spec.args) {
      if (a.positional != positional) continue;
      if (!r.contains(a.name)) {
        if (a.required) throw UsageError("'" + a.name + "' is required for " + spec.verb);
        continue;
      }
      append_words(a, r[a.name], paths, words);
    }
  if (spec.json) words.push_back("--json");
  return words;
}

std::string this_executable() {
  std::error_code ec;
  const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) throw std::runtime_error("cannot find the foldkit executable (/proc/self/exe): " + ec.message());
  return p.string();
}

VerbRun run_verb(const std::string& executable, const std::vector<std::string>& args, double seconds, std::size_t max_output) {
  int out[2], err[2];
  if (pipe2(out, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  if (pipe2(err, O_CLOEXEC) != 0) {
    close(out[0]), close(out[1]);
    throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out[1], 1);
  posix_spawn_file_actions_adddup2(&actions, err[1], 2);
  // cpp-httplib's sockets are not close-on-exec: without this the verb would hold the listening
  // port and the clients' connections open for as long as it runs.
  posix_spawn_file_actions_addclosefrom_np(&actions, 3);
  std::vector<std::string> words = {executable};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int spawned = posix_spawn(&pid, executable.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(out[1]), close(err[1]);
  if (spawned != 0) {
    close(out[0]), close(err[0]);
    throw std::runtime_error("cannot start " + executable + ": " + std::strerror(spawned));
  }

  VerbRun run;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  pollfd fds[2] = {{out[0], POLLIN, 0}, {err[0], POLLIN, 0}};
  std::string* sinks[2] = {&run.out, &run.err};
  int open_fds = 2;
  char buffer[65536];
  while (open_fds > 0) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()).count();
    if (left <= 0) {
      run.timed_out = true;
      break;
    }
    if (poll(fds, 2, static_cast<int>(std::min<long long>(left, 1000))) < 0 && errno != EINTR) break;
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const ssize_t n = read(fds[i].fd, buffer, sizeof buffer);
      if (n > 0) {
        sinks[i]->append(buffer, static_cast<std::size_t>(n));
      } else if (n == 0 || errno != EINTR) {
        close(fds[i].fd);
        fds[i].fd = -1;
        --open_fds;
      }
    }
    if (run.out.size() > max_output || run.err.size() > max_output) {
      run.flooded = true;
      break;
    }
  }
  if (open_fds > 0) kill(pid, SIGKILL);  // out of time or output
  for (const auto& f : fds)
    if (f.fd >= 0) close(f.fd);
  // A child that closed its outputs may still run: it too is held to the deadline.
  int status = 0;
  for (;;) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid || (done < 0 && errno != EINTR)) break;
    if (done == 0 && std::chrono::steady_clock::now() > deadline && !run.timed_out) {
      run.timed_out = true;
      kill(pid, SIGKILL);
    }
    if (done == 0) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  if (WIFEXITED(status)) {
    run.exit = WEXITSTATUS(status);
  } else {
    run.exit = -1;
    run.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  }
  return run;
}

}  // namespace foldkit::apps
