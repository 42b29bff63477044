#include "serve_verbs.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <thread>

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_app.hpp"
#include "cli_common.hpp"

extern char** environ;

namespace foldkit::apps {

namespace {

using K = ArgKind;

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

// How a request's value reaches an option, from what the CLI declares: a flag, a file by its
// role (cli_common.hpp: reads/writes/writes_into), else the option's value type.
ArgKind kind_of(const CLI::Option& o, const std::string& name) {
  if (o.get_expected_max() == 0) return K::Flag;
  const bool many = o.get_items_expected_max() > 1;
  const std::string full = o.get_type_name();
  const std::string type = full.substr(0, full.find(':'));
  if (type == kReadsType) return many ? K::Inputs : K::Input;
  if (type == kWritesType && !many) return K::Output;
  if (type == kWritesIntoType && !many) return K::OutputFolder;
  if (type == "FLOAT" && !many) return K::Number;
  if ((type == "INT" || type == "UINT") && !many) return K::Integer;
  if (type == "TEXT") return many ? K::Texts : K::Text;
  throw std::logic_error("served option '" + name + "' has a type (" + full + ") no JSON value maps to");
}

// The arguments of one verb as its CLI declares them; --help is not served, --json always given.
void add_args(const CLI::App& app, VerbSpec& spec) {
  for (const CLI::Option* o : app.get_options()) {
    const bool positional = o->get_positional() && !o->nonpositional();
    const std::string name = positional ? o->get_name() : o->get_lnames().front();
    if (name == "help") continue;
    if (name == "json") {
      spec.json = true;
      continue;
    }
    const ArgKind kind = kind_of(*o, name);
    const auto same = std::find_if(spec.args.begin(), spec.args.end(), [&](const ArgSpec& a) { return a.name == name; });
    if (same == spec.args.end()) {
      const std::vector<std::string> lnames = positional ? std::vector<std::string>{} : o->get_lnames();
      spec.args.push_back({name, kind, positional, o->get_required(), {}, {lnames.begin() + (lnames.empty() ? 0 : 1), lnames.end()}});
    } else if (same->kind != kind) {
      // Two generators with one option name: a number takes integers too.
      if (!((same->kind == K::Number && kind == K::Integer) || (same->kind == K::Integer && kind == K::Number)))
        throw std::logic_error("served option '" + name + "' has two kinds");
      same->kind = K::Number;
    }
  }
}

// A verb as its CLI declares it. A verb whose choices are subcommands (`generate KIND`) takes the
// choice as the positional "kind", checked against their names (a free word could be an option),
// and the options of every choice; the CLI refuses those the chosen one does not have.
VerbSpec served_spec(const CLI::App& app) {
  VerbSpec spec{app.get_name(), {}, false};
  const auto choices = app.get_subcommands([](const CLI::App*) { return true; });
  if (!choices.empty()) {
    ArgSpec kind{"kind", K::Text, true, true, {}, {}};
    for (const CLI::App* c : choices) kind.choices.push_back(c->get_name());
    spec.args.push_back(kind);
  }
  add_args(app, spec);
  for (const CLI::App* c : choices) add_args(*c, spec);
  return spec;
}

}  // namespace

const std::vector<VerbSpec>& served_verbs() {
  static const std::vector<VerbSpec> verbs = [] {
    const std::unique_ptr<Cli> cli = make_cli();
    std::vector<VerbSpec> out;
    for (const char* verb : {"validate", "info", "dof", "project", "simulate", "fold", "plan", "stiffness", "convert", "generate"})
      out.push_back(served_spec(*cli->app.get_subcommand(verb)));
    return out;
  }();
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
  nlohmann::json r = nlohmann::json::object();
  for (const auto& [key, value] : request.items()) {
    // An option's other long names (a deprecated one, such as project's velocity) name it too.
    const auto arg = std::find_if(spec.args.begin(), spec.args.end(), [&](const ArgSpec& a) {
      return a.name == key || std::find(a.aliases.begin(), a.aliases.end(), key) != a.aliases.end();
    });
    if (arg == spec.args.end()) throw UsageError("'" + key + "': " + spec.verb + " takes no such argument (see docs/SERVE.md)");
    if (r.contains(arg->name)) throw UsageError("'" + key + "': " + spec.verb + " takes '" + arg->name + "' once (one name of it)");
    r[arg->name] = value;
  }
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
