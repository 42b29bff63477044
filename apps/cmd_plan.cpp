// foldkit plan: a collision-free, closed fold sequence from a start to a goal, by an OMPL planner.
#include <algorithm>
#include <cmath>
#include <exception>
#include <future>
#include <iostream>
#include <limits>
#include <memory>

#include "cli_common.hpp"
#include "pending_output.hpp"
#include "progress_line.hpp"
#include "foldkit/geometry/closure_path.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/planners/experience.hpp"
#include "foldkit/planners/objectives.hpp"
#include "foldkit/planners/plan.hpp"
#include "foldkit/planners/planner_factory.hpp"

namespace foldkit::apps {
namespace {

// "ID:DEG,ID:DEG,…" → the angle (radians) of each named joint, by joint index.
std::vector<std::pair<int, double>> parse_goal_angles(const geometry::CreasePattern& pattern, const std::string& text) {
  auto out = parse_joint_values(pattern, text, "--goal-angles", "ID:DEGREES", [](double v) { return std::abs(v) <= 180.0; },
                                "an angle in degrees within [-180, 180]");
  for (auto& entry : out) entry.second *= M_PI / 180.0;
  return out;
}

struct PlanArgs {  // defaults: PlanOptions's
  std::string pattern, goal, goal_angles, start, space = planners::to_string(planners::PlanOptions{}.space),
                                                 planner = planners::PlanOptions{}.planner, output,
                                                 objective = planners::PlanOptions{}.objective, experience,
                                                 experience_framework = planners::PlanOptions::Experience{}.framework;
  std::vector<std::string> params;
  double time = planners::PlanOptions{}.time, search_margin = planners::PlanOptions{}.search_margin;
  double cost_threshold = std::numeric_limits<double>::quiet_NaN();  // NaN: none (PlanOptions::cost_threshold empty)
  CLI::Option *cost_threshold_option = nullptr, *framework_option = nullptr;
  unsigned int seed = planners::PlanOptions{}.seed;
  bool no_collision = false, free_signs = false, no_fallback = false, json = false;
};

void add_plan_options(CLI::App* app, PlanArgs& opt) {
  add_pattern(app, opt.pattern);
  CLI::Option* goal = reads(app->add_option("--goal", opt.goal, "CMML whose end state is the goal"));
  CLI::Option* goal_angles =
      app->add_option("--goal-angles", opt.goal_angles,
                      "Goal as ID:DEGREES,… for some creases: the nearest closed state to flat that holds them");
  goal->excludes(goal_angles);
  goal_angles->excludes(goal);
  reads(app->add_option("--start", opt.start, "CMML whose end state is the start (default: flat)"));
  app->add_option("--space", opt.space, "Space to search (auto: single-vertex for one vertex, else driving)")
      ->check(CLI::IsMember(planners::space_names()))
      ->capture_default_str();
  app->add_option("--planner", opt.planner, "OMPL geometric planner by name (RRTConnect, RRT*, PRM, KPIECE1, BiTRRT, …)")
      ->capture_default_str();
  std::string objectives;
  for (const auto& n : planners::objective_names()) objectives += (objectives.empty() ? "" : ", ") + n;
  app->add_option("--objective", opt.objective,
                  "What the planner optimises: " + objectives + ", or a weighted sum NAME:WEIGHT,… of length and rotation")
      ->capture_default_str();
  opt.cost_threshold_option = app->add_option(
      "--cost-threshold", opt.cost_threshold,
      "Stop at the first path whose cost is below this (clearance: above it); 0: optimise for all of --time (not for clearance)");
  app->add_option("--param", opt.params, "NAME=VALUE: a planner parameter by OMPL's name (repeatable), e.g. range=0.3");
  positive(app->add_option("--time", opt.time,
                  "Seconds the search may take: sampling, the Carpenter fallback and the way through flat (not the replay)"));
  positive(app->add_option("--seed", opt.seed, "Random seed (same seed, same plan)"));
  app->add_flag("--no-collision", opt.no_collision, "Closure only (no collision world is built)");
  app->add_option("--search-margin", opt.search_margin,
                  "Constrained spaces: sample only within the box of start and goal widened by this (radians)")
      ->check(CLI::NonNegativeNumber);
  app->add_flag("--free-signs", opt.free_signs, "Ignore the pattern's mountain/valley assignment");
  app->add_flag("--no-fallback", opt.no_fallback,
                "No way through flat when the planner finds none in a quarter of --time: no spherical Carpenter path "
                "(single vertex), no start -> flat -> goal plan (driving space, folded --start)");
  writes(app->add_option("--experience", opt.experience,
                         "Experience database (made when missing): recall a path from it (--experience-framework), plan "
                         "from scratch when that fails, then store this plan's path in it"));
  opt.framework_option = app->add_option("--experience-framework", opt.experience_framework,
                                         "How --experience recalls: lightning (the stored path nearest to this query, repaired) or "
                                         "thunder (a path through a sparse roadmap of the stored paths); both use the same file")
                             ->capture_default_str();
  writes(app->add_option("-o,--output", opt.output, "Output CMML"))->required();
  add_json(app, opt.json);
}

// A CMML file checked against the pattern: its first error ends the command.
geometry::FoldSequence read_sequence(const geometry::CreasePattern& pattern, const std::string& file) {
  const geometry::FoldSequence seq = io::read_cmml(file);
  for (const auto& d : geometry::check_sequence(pattern, seq))
    if (d.severity == geometry::Severity::Error) throw io::ParseError(file, d.line, d.message);
  return seq;
}

// The line of a sequence's end state in its file: its last fold's (0 when not read from a file).
int end_line(const geometry::FoldSequence& seq) {
  int line = 0;
  if (!seq.events.empty())
    for (const auto& f : seq.events.back().folds) line = std::max(line, f.line);
  return line;
}

// The goal from --goal or --goal-angles (`goal_line`: where the goal CMML ends); false (after
// saying so) when no closed state holds the angles asked for.
bool set_goal(const PlanArgs& opt, const geometry::CreasePattern& pattern, geometry::FoldState& goal, int& goal_line) {
  if (!opt.goal.empty()) {
    const geometry::FoldSequence seq = read_sequence(pattern, opt.goal);
    goal = geometry::end_state(pattern, seq);
    goal_line = end_line(seq);
    return true;
  }
  std::string why;
  const auto g = geometry::goal_from_angles(geometry::ClosureSystem(pattern), parse_goal_angles(pattern, opt.goal_angles), why);
  if (!g) {
    std::cerr << "no plan: no closed state holds the angles of --goal-angles (" << why << ")\n";
    if (opt.json) {
      nlohmann::json j{{"solved", false}};  // deprecated: status
      // The nearest closed state was not found; that proves no such state exists only sometimes.
      add_status(j, {geometry::StatusCode::NoProgress, "no closed goal state: " + why});
      print_json(j);
    }
    return false;
  }
  goal = *g;
  return true;
}

void set_start_and_settings(const PlanArgs& opt, const geometry::CreasePattern& pattern, planners::PlanOptions& options) {
  if (!opt.start.empty()) {
    options.start_sequence = read_sequence(pattern, opt.start);
    options.start = geometry::end_state(pattern, options.start_sequence);
  }
  options.space = planners::parse_space(opt.space);
  options.planner = opt.planner;
  options.time = opt.time;
  options.seed = opt.seed;
  options.collisions = !opt.no_collision;
  options.search_margin = opt.search_margin;
  options.use_assignment = !opt.free_signs;
  options.fallback = !opt.no_fallback;
  options.objective = opt.objective;
  if (opt.cost_threshold_option->count() > 0) options.cost_threshold = opt.cost_threshold;
  if (!opt.experience.empty())  // a missing file is a new database
    options.experience = planners::PlanOptions::Experience{opt.experience, io::read_file_if_present(opt.experience).value_or(""),
                                                           opt.experience_framework};
}

int report(const PlanArgs& opt, const planners::PlanResult& r, PendingOutput& output) {
  std::cerr << (r.status.ok() ? "solved" : "no plan") << ": " << r.status.message << " (" << r.planner << " in " << r.space
            << ", " << r.seconds << " s, " << r.waypoints.size() << " waypoints, objective " << r.objective;
  if (r.status.ok()) std::cerr << ", cost " << r.cost;
  if (!r.cost_history.empty())
    std::cerr << ", best cost " << r.cost_history.front().second << " at " << r.cost_history.front().first << " s to "
              << r.cost_history.back().second << " at " << r.cost_history.back().first << " s";
  std::cerr << ")\n";
  if (r.status.ok()) {
    output.commit(r.sequence);  // written during the replay (PlanOptions::sequence_ready)
    std::cerr << "wrote " << opt.output << '\n';
  }
  if (r.experience && !r.experience->bytes.empty()) {
    io::write_file_atomic(opt.experience, r.experience->bytes);
    std::cerr << opt.experience << ": " << r.experience->paths << " paths (" << r.experience->framework << ", "
              << (r.experience->recalled ? "recalled" : "planned from scratch") << ")\n";
  }
  if (opt.json) {
    nlohmann::json j{{"solved", r.status.ok()},  // deprecated: status
                     {"planner", r.planner},
                     {"space", r.space},
                     {"fallback", r.fallback},
                     {"via_flat", r.via_flat},
                     {"seconds", r.seconds},
                     {"time", r.seconds},  // deprecated: the name of `seconds` before issue 37
                     {"path_length", r.path_length},
                     {"objective", r.objective},
                     // null without a path, or for a clearance with no two facets apart (+∞)
                     {"cost", std::isfinite(r.cost) ? nlohmann::json(r.cost) : nlohmann::json(nullptr)},
                     {"cost_history", r.cost_history},
                     {"max_closure_error", r.max_closure_error},
                     {"waypoints", r.waypoints.size()}};
    if (r.experience)
      j["experience"] = {{"database", opt.experience},
                         {"framework", r.experience->framework},
                         {"recalled", r.experience->recalled},
                         {"recall_seconds", r.experience->recall_seconds},
                         {"load_seconds", r.experience->load_seconds},
                         {"loaded", r.experience->loaded},
                         {"paths", r.experience->paths},
                         {"states", r.experience->states},
                         {"bytes", r.experience->bytes.size()}};
    add_status(j, r.status);
    print_json(j);
  }
  return r.status.ok() ? kOk : kNoPlan;
}

int run_plan(PlanArgs& opt) {
  if (!is_kind(opt.output, FileKind::Cmml)) throw UsageError("-o needs a .cmml file name, not '" + opt.output + "'");
  std::vector<std::pair<std::string, std::string>> params;
  try {
    opt.planner = planners::canonical_planner(opt.planner);
    if (const std::string why = planners::planner_refusal(opt.planner); !why.empty()) throw planners::PlannerRefused(opt.planner, why);
    for (const auto& p : opt.params) params.push_back(planners::parse_planner_param(p));
    planners::check_planner_params(opt.planner, params);
    planners::Objective objective;
    try {
      objective = planners::parse_objective(opt.objective);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("--objective: ") + e.what());
    }
    if (const std::string why = planners::objective_refusal(opt.planner, objective); !why.empty())
      throw planners::PlannerRefused(opt.planner, why);
    if (opt.cost_threshold_option->count() > 0) planners::check_cost_threshold(opt.cost_threshold, "--cost-threshold");
    if (!opt.experience.empty() && (!objective.is_default() || opt.cost_threshold_option->count() > 0))
      throw std::invalid_argument("--experience recalls by path length only: not with --objective " + objective.name() +
                                  (opt.cost_threshold_option->count() > 0 ? " or --cost-threshold" : ""));
    try {
      planners::parse_experience_framework(opt.experience_framework);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("--experience-framework: ") + e.what());
    }
    if (opt.experience.empty() && opt.framework_option->count() > 0)
      throw std::invalid_argument("--experience-framework needs --experience DB");
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const geometry::CreasePattern pattern = load_pattern(opt.pattern).pattern;
  planners::PlanOptions options;
  if (opt.goal.empty() == opt.goal_angles.empty()) throw UsageError("give the goal as --goal CMML or --goal-angles ID:DEG,…");
  geometry::FoldState goal;
  int goal_line = 0;
  if (!set_goal(opt, pattern, goal, goal_line)) return kNoPlan;
  set_start_and_settings(opt, pattern, options);
  options.params = params;
  planners::PlanResult r;
  PendingOutput output(opt.output);
  options.sequence_ready = output.starter();
  try {
    ProgressLine progress("plan (replay)");
    options.progress = progress.callback();
    r = planners::plan(pattern, goal, options);
  } catch (const planners::PlanInputError& e) {
    // The file the faulty end came from, at the line where its sequence ends.
    if (e.end() == planners::PlanInputError::End::Start && !opt.start.empty())
      throw io::ParseError(opt.start, end_line(options.start_sequence), e.what());
    throw io::ParseError(opt.goal.empty() ? "--goal-angles" : opt.goal, opt.goal.empty() ? 0 : goal_line, e.what());
  } catch (const planners::ExperienceError& e) {
    throw io::ParseError(opt.experience, 0, e.reason());
  } catch (const planners::PlannerRefused& e) {
    throw UsageError(e.what());  // the planner asked for, not the goal, is what cannot be
  } catch (const std::invalid_argument& e) {
    throw io::ParseError(opt.goal.empty() ? "--goal-angles" : opt.goal, 0, e.what());
  }
  return report(opt, r, output);
}

}  // namespace

Command add_plan(CLI::App& root) {
  auto opt = std::make_shared<PlanArgs>();
  CLI::App* app = root.add_subcommand("plan", "Plan a closed, collision-free fold sequence with an OMPL planner");
  add_plan_options(app, *opt);
  return {app, [opt] { return run_plan(*opt); }};
}

}  // namespace foldkit::apps
