// foldkit bench: planners × built-in scenes through ompl::tools::Benchmark, one OMPL log per scene
// (docs/BENCHMARKING.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <tuple>

#include <unistd.h>

#include "cli_common.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/bench/deterministic_planner.hpp"
#include "foldkit/bench/log.hpp"
#include "foldkit/bench/run.hpp"
#include "foldkit/bench/scenes.hpp"
#include "foldkit/planners/objectives.hpp"
#include "foldkit/planners/plan.hpp"
#include "foldkit/planners/planner_factory.hpp"

namespace foldkit::apps {
namespace {

std::vector<std::string> split_list(const std::string& text, const char* option) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    if (item.empty()) throw UsageError(std::string(option) + " '" + text + "': empty item");
    out.push_back(item);
  }
  if (out.empty()) throw UsageError(std::string(option) + " needs at least one item");
  return out;
}

std::vector<double> parse_times(const std::string& text) {
  std::vector<double> out;
  for (const std::string& item : split_list(text, "--error-vs-time")) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (*end != '\0' || !(v > 0.0) || !std::isfinite(v))
      throw UsageError("--error-vs-time: '" + item + "' is not a positive number of seconds");
    out.push_back(v);
  }
  return out;
}

std::pair<unsigned int, unsigned int> parse_shard(const std::string& text) {
  unsigned int k = 0, n = 0;
  char slash = 0, extra = 0;
  std::istringstream in(text);
  // Digits only: istream would read "-3" into an unsigned as 4294967293.
  const bool digits = !text.empty() && text.find_first_not_of("0123456789/") == std::string::npos;
  if (!digits || !(in >> k >> slash >> n) || slash != '/' || (in >> extra) || k < 1 || n < 1 || k > n)
    throw UsageError("--shard '" + text + "': expected K/N with 1 <= K <= N");
  return {k, n};
}

// A progress bar redrawn in place on a terminal; one line per scene otherwise (logs, CI).
class Progress {
 public:
  Progress() : tty_(isatty(fileno(stderr)) != 0) {}
  void operator()(const bench::BenchProgress& p) {
    if (tty_) {
      const int width = 30;
      const int filled = p.total ? static_cast<int>(width * p.done / p.total) : width;
      std::cerr << "\r[" << std::string(static_cast<std::size_t>(filled), '#')
                << std::string(static_cast<std::size_t>(width - filled), ' ') << "] " << p.done << '/' << p.total
                << " runs, " << std::fixed << std::setprecision(1) << p.elapsed << " s, " << p.scene
                << (p.planner.empty() ? "" : " " + p.planner) << "\033[K" << std::flush;
      if (p.done == p.total && p.scene_done) std::cerr << '\n';
    } else if (p.scene_done) {
      std::cerr << p.scene << ": " << p.done << '/' << p.total << " runs done, " << std::fixed << std::setprecision(1)
                << p.elapsed << " s\n";
    }
  }

 private:
  bool tty_;
};

int list(bool json) {
  nlohmann::json suites = nlohmann::json::array();
  for (const auto& s : bench::bench_suites())
    suites.push_back({{"name", s.name},
                      {"description", s.description},
                      {"scenes", s.scenes},
                      {"planners", s.planners},
                      {"objective", s.objective.empty() ? planners::PlanOptions{}.objective : s.objective}});
  nlohmann::json sampling = planners::planner_names(), deterministic = bench::deterministic_planner_names();
  nlohmann::json objectives = nlohmann::json::array();
  for (const auto& o : planners::objective_table())
    objectives.push_back({{"name", o.name}, {"unit", o.unit}, {"description", o.description}, {"additive", o.additive},
                          {"informed_sampler", o.informed_sampler}});
  if (json) {
    print_json({{"suites", suites},
                {"objectives", objectives},
                {"scenes", bench::bench_scene_names()},
                {"planners", {{"sampling", sampling}, {"deterministic", deterministic}}}});
    return kOk;
  }
  std::cerr << "suites:\n";
  for (const auto& s : bench::bench_suites()) {
    std::cerr << "  " << s.name << ": " << s.description << "\n    scenes:";
    for (const auto& x : s.scenes) std::cerr << ' ' << x;
    std::cerr << "\n    planners:";
    for (const auto& x : s.planners) std::cerr << ' ' << x;
    if (!s.objective.empty()) std::cerr << "\n    objective: " << s.objective;
    std::cerr << '\n';
  }
  std::cerr << "scenes (--scenes):";
  for (const auto& x : bench::bench_scene_names()) std::cerr << ' ' << x;
  std::cerr << "\nsampling planners (--planners):";
  for (const auto& x : planners::planner_names()) std::cerr << ' ' << x;
  std::cerr << "\ndeterministic planners (--planners):";
  for (const auto& x : bench::deterministic_planner_names()) std::cerr << ' ' << x;
  std::cerr << "\nobjectives (--objective; weighted sums NAME:WEIGHT,… of the additive ones):\n";
  for (const auto& o : planners::objective_table())
    std::cerr << "  " << o.name << " (" << o.unit << (o.additive ? ", additive" : "")
              << (o.informed_sampler ? "" : ", no informed sampler") << "): " << o.description << '\n';
  return kOk;
}

struct BenchArgs {
  std::string suite, output, shard = "1/1", planners, scenes, error_vs_time, space = "auto",
                                                                             objective = bench::BenchOptions{}.objective;
  double cost_threshold = 0.0;
  CLI::Option *cost_threshold_option = nullptr, *objective_option = nullptr;
  std::vector<std::string> params;
  double time = 1.0;
  unsigned int runs = 10, seed = 1;
  bool json = false, list = false, simplify = false;
};

void add_bench_options(CLI::App* app, const std::shared_ptr<BenchArgs>& opt) {
  app->add_option("suite", opt->suite, "Suite: quick, full, spaces, vertex-complete, miura-scale or optimal (see --list)");
  positive(app->add_option("--time", opt->time, "Seconds per run"));
  positive(app->add_option("--runs", opt->runs, "Runs per planner and scene (per time limit with --error-vs-time)"));
  app->add_option("--shard", opt->shard, "Run shard K of N of the (scene, planner, run) list")->capture_default_str();
  positive(app->add_option("--seed", opt->seed, "Seed of the scenes' goals and of OMPL"));
  app->add_option("--planners", opt->planners, "Planners, comma-separated (default: the suite's)");
  app->add_option("--scenes", opt->scenes, "Scenes, comma-separated (default: the suite's)");
  app->add_option("--space", opt->space,
                  "Space of every scene (auto: each scene's own); comma-separated spaces run every planner in each, "
                  "side by side in one log (entries PLANNER@SPACE)")
      ->check([](const std::string& value) {
        try {
          for (const auto& s : split_list(value, "--space")) planners::parse_space(s);
        } catch (const std::exception& e) {
          return std::string(e.what());
        }
        return std::string();
      })
      ->capture_default_str();
  app->add_option("--param", opt->params, "NAME=VALUE: a sampling planner's parameter by OMPL's name (repeatable)");
  // The suites' own objectives, as the suites declare them.
  std::string suite_objectives;
  for (const auto& suite : bench::bench_suites())
    if (!suite.objective.empty()) suite_objectives += suite.name + ": " + suite.objective + "; ";
  opt->objective_option = app->add_option("--objective", opt->objective,
                  "What the sampling planners optimise, as foldkit plan --objective (length, rotation, clearance, "
                  "NAME:WEIGHT,…); default: the suite's (" + suite_objectives + "the others: length)");
  opt->cost_threshold_option = app->add_option(
      "--cost-threshold", opt->cost_threshold, "An optimising planner stops once its path costs less than this (clearance: more)");
  app->add_option("--error-vs-time", opt->error_vs_time,
                  "Time limits, comma-separated seconds: write DIR/error_vs_time.csv (error reached per limit) instead of logs");
  app->add_flag("--simplify", opt->simplify,
                "Simplify each solution (OMPL's simplifier, as foldkit plan does) before measuring it");
  writes_into(app->add_option("-o,--output", opt->output, "Output folder"));
  app->add_flag("--list", opt->list, "List suites, scenes and planners");
  add_json(app, opt->json);
}

}  // namespace

Command add_bench(CLI::App& root) {
  auto opt = std::make_shared<BenchArgs>();
  CLI::App* app = root.add_subcommand("bench", "Benchmark planners on built-in scenes (OMPL benchmark logs)");
  add_bench_options(app, opt);
  return {app, [opt]() -> int {
            if (opt->list) return list(opt->json);
            if (opt->suite.empty()) throw UsageError("name a suite (quick, full; see --list)");
            if (opt->output.empty()) throw UsageError("-o DIR is required");
            bench::BenchOptions o;
            o.suite = opt->suite;
            o.time = opt->time;
            o.runs = opt->runs;
            o.seed = opt->seed;
            o.simplify = opt->simplify;
            o.space = opt->space;
            for (const auto& p : opt->params) o.params.push_back(planners::parse_planner_param(p));
            try {  // usage errors, before any scene is built
              if (opt->objective_option->count() > 0) planners::parse_objective(opt->objective);
            } catch (const std::invalid_argument& e) {
              throw UsageError(std::string("--objective: ") + e.what());
            }
            if (opt->cost_threshold_option->count() > 0) try {
                planners::check_cost_threshold(opt->cost_threshold, "--cost-threshold");
              } catch (const std::invalid_argument& e) {
                throw UsageError(e.what());
              }
            o.objective = opt->objective;
            if (opt->cost_threshold_option->count() > 0) o.cost_threshold = opt->cost_threshold;
            std::tie(o.shard, o.shards) = parse_shard(opt->shard);
            if (!opt->planners.empty()) o.planners = split_list(opt->planners, "--planners");
            if (!opt->scenes.empty()) o.scenes = split_list(opt->scenes, "--scenes");
            o.output_dir = opt->output;
            Progress progress;
            o.progress = [&progress](const bench::BenchProgress& p) { progress(p); };
            if (!opt->error_vs_time.empty()) {
              const std::vector<double> limits = parse_times(opt->error_vs_time);
              if (o.shards != 1) throw UsageError("--error-vs-time runs unsharded");
              const auto rows = bench::run_error_vs_time(o, limits);
              std::filesystem::create_directories(o.output_dir);
              const std::string csv = (std::filesystem::path(o.output_dir) / "error_vs_time.csv").string();
              io::write_file_atomic(csv, bench::error_vs_time_csv(rows));
              std::cerr << "wrote " << csv << " (" << rows.size() << " runs)\n";
              if (opt->json) {
                std::size_t exact = 0;
                for (const auto& r : rows) exact += r.solution == "exact";
                print_json({{"suite", o.suite}, {"csv", csv}, {"runs", rows.size()}, {"exact", exact}, {"time_limits", limits}});
              }
              return kOk;
            }
            const auto results = bench::run_bench(o);
            std::size_t runs = 0, solved = 0;
            nlohmann::json scenes = nlohmann::json::array(), logs = nlohmann::json::array();
            for (const auto& r : results) {
              runs += r.runs;
              solved += r.solved;
              if (r.log.empty()) continue;
              nlohmann::json per = nlohmann::json::object();
              for (const auto& [name, rs] : r.planners) per[name] = {{"runs", rs.first}, {"solved", rs.second}};
              scenes.push_back({{"scene", r.scene}, {"log", r.log}, {"runs", r.runs}, {"solved", r.solved}, {"planners", per}});
              logs.push_back(r.log);
              std::cerr << r.scene << ": " << r.solved << '/' << r.runs << " solved -> " << r.log << '\n';
            }
            if (opt->json)
              print_json({{"suite", o.suite},
                          {"shard", std::to_string(o.shard) + "/" + std::to_string(o.shards)},
                          {"time", o.time},
                          {"seed", o.seed},
                          {"runs", runs},
                          {"solved", solved},
                          {"scenes", scenes},
                          {"logs", logs}});
            return kOk;
          }};
}

}  // namespace foldkit::apps
