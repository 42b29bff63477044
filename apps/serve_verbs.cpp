#include "serve_verbs.hpp"

#include <cmath>
#include <iostream>
#include <sstream>

#include "cli_app.hpp"

namespace foldkit::apps {

namespace {

using K = ArgKind;

ArgSpec positional_arg(std::string name, ArgKind kind, bool required = true) { return {std::move(name), kind, true, required}; }
ArgSpec option_arg(std::string name, ArgKind kind, bool required = false) { return {std::move(name), kind, false, required}; }

std::string number_text(double v) {
  std::ostringstream out;
  out.precision(17);
  out << v;
  return out.str();
}

// The value of one argument as command-line words.
void append_words(const ArgSpec& a, const nlohmann::json& v, const RootedPaths& paths, std::vector<std::string>& words) {
  const std::string flag = "--" + a.name + "=";
  const auto wrong = [&](const char* expected) { return UsageError("'" + a.name + "': expected " + expected + ", got " + v.dump()); };
  const auto word = [&](const std::string& value) { words.push_back(a.positional ? value : flag + value); };
  switch (a.kind) {
    case K::Number:
      if (!v.is_number() || !std::isfinite(v.get<double>())) throw wrong("a finite number");
      return word(number_text(v.get<double>()));
    case K::Integer:
      if (!v.is_number_integer()) throw wrong("an integer");
      return word(std::to_string(v.get<long long>()));
    case K::Text:
      if (!v.is_string()) throw wrong("a string");
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
        option_arg("max-steps", K::Integer), option_arg("velocity", K::Text), option_arg("no-collision", K::Flag), option_arg("partial", K::Flag),
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

VerbRun run_captured(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  struct Capture {
    std::streambuf* out;
    std::streambuf* err;
    ~Capture() {
      std::cout.rdbuf(out);
      std::cerr.rdbuf(err);
    }
  } capture{std::cout.rdbuf(out.rdbuf()), std::cerr.rdbuf(err.rdbuf())};
  std::vector<const char*> argv = {"foldkit"};
  for (const auto& a : args) argv.push_back(a.c_str());
  const auto cli = make_cli();  // fresh: a parsed CLI11 app keeps its options' values
  VerbRun run;
  run.exit = run_cli(*cli, static_cast<int>(argv.size()), argv.data());
  std::cout.flush();
  std::cerr.flush();
  run.out = out.str();
  run.err = err.str();
  return run;
}

}  // namespace foldkit::apps
