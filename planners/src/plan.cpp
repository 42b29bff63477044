#include "foldkit/planners/plan.hpp"
#include "foldkit/planners/plan_setup.hpp"

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/geometric/PathSimplifier.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "foldkit/geometry/closure_path.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/planners/carpenter_fallback.hpp"
#include "foldkit/planners/experience.hpp"
#include "foldkit/planners/objectives.hpp"
#include "foldkit/planners/planner_factory.hpp"
#include "foldkit/planners/plan_space.hpp"
#include "foldkit/statespaces/validity.hpp"
#include "cost_history.hpp"
#include "plan_finish.hpp"
#include "replay_pipeline.hpp"
#include "straight_plan.hpp"

namespace foldkit::planners {

namespace ob = ompl::base;
namespace og = ompl::geometric;
using geometry::FoldState;

namespace {

double elapsed(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

ob::PlannerStatus run_planner(const PlanSetup& setup, og::SimpleSetup& ss, double seconds, bool until_threshold) {
  const statespaces::FoldValidity::TimeLimit limit(*setup.validity, seconds);
  const ob::ProblemDefinitionPtr pdef = ss.getProblemDefinition();
  // With a cost threshold, an exact path that does not meet it is no reason to stop: the
  // planner's solution is "optimized" once its cost satisfies the objective.
  const ob::PlannerTerminationCondition solved =
      until_threshold ? ob::PlannerTerminationCondition([pdef] { return pdef->hasOptimizedSolution(); })
                      : ob::exactSolnPlannerTerminationCondition(pdef);
  return ss.solve(ob::plannerOrTerminationCondition(ob::timedPlannerTerminationCondition(seconds), solved));
}

void set_start_and_goal(const PlanSetup& setup, og::SimpleSetup& ss, const FoldState& goal) {
  ob::ScopedState<> s(setup.space), g(setup.space);
  setup.plan_space->write(setup.prefix.back(), s.get());
  if (!setup.plan_space->write(goal, g.get()))
    throw PlanInputError(PlanInputError::End::Goal, std::string("plan: the goal is a singular state of the ") + setup.plan_space->name() +
                                                        " space (try --space projected)");
  ss.setStartAndGoalStates(s, g, 1e-9);
  setup.plan_space->anchor(s.get(), g.get());
}

namespace {

// The start and goal must close, keep the assignment and not cross (std::invalid_argument).
void check_ends(const PlanSetup& setup, const statespaces::AngleBounds& bounds) {
  const FoldState& start = setup.start;
  const double start_error = setup.system->max_error(start), goal_error = setup.system->max_error(setup.goal);
  if (start_error > 1e-6) throw PlanInputError(PlanInputError::End::Start, "plan: the start is not closed (error " + std::to_string(start_error) + " rad)");
  if (goal_error > 1e-6) throw PlanInputError(PlanInputError::End::Goal, "plan: the goal is not closed (error " + std::to_string(goal_error) + " rad)");
  if (!bounds.contains(start, 1e-9)) throw PlanInputError(PlanInputError::End::Start, "plan: the start breaks the mountain/valley assignment");
  if (!bounds.contains(setup.goal, 1e-9)) throw PlanInputError(PlanInputError::End::Goal, "plan: the goal breaks the mountain/valley assignment");
  if (!setup.validity->valid(start)) throw PlanInputError(PlanInputError::End::Start, "plan: the start state is not valid (facets cross)");
  if (!setup.validity->valid(setup.goal)) throw PlanInputError(PlanInputError::End::Goal, "plan: the goal state is not valid (facets cross)");
}

// The space of the options' kind (SpaceKind::Auto: single-vertex for one interior vertex and no
// hole, else driving), or the joint box for a pattern without loops.
std::shared_ptr<PlanSpace> space_of(const PlanSetup& setup, const PlanOptions& options) {
  if (setup.system->rows() == 0) return make_joint_plan_space();
  SpaceKind kind = options.space;
  if (kind == SpaceKind::Auto)
    kind = setup.pattern->interior_vertices().size() == 1 && geometry::hole_count(*setup.pattern) == 0 ? SpaceKind::SingleVertex
                                                                                                    : SpaceKind::Driving;
  return make_plan_space(kind);
}

// The prefix: the start, or, below the space's rank, its way out along geometry::lead_in (the one
// lead-in every space shares).
void lead_in(PlanSetup& setup, const PlanOptions& options, const statespaces::AngleBounds& bounds) {
  setup.prefix = {setup.start};
  const Eigen::Index rank = setup.plan_space->lead_in_rank(setup, options, bounds);
  if (rank == 0) return;
  setup.prefix = geometry::lead_in(*setup.system, setup.start, setup.goal, rank, options.waypoint_step);
  if (setup.prefix.empty()) throw PlanInputError(PlanInputError::End::Start, "plan: no closed way out of the singular start state");
}

}  // namespace

PlanSetup make_plan_setup(const geometry::CreasePattern& pattern, const FoldState& goal, const PlanOptions& options,
                          bool allow_no_loops) {
  const auto n = static_cast<Eigen::Index>(pattern.joints().size());
  if (goal.angles.size() != n) throw PlanInputError(PlanInputError::End::Goal, "plan: the goal does not hold one angle per joint");
  PlanSetup setup;
  setup.pattern = &pattern;
  setup.goal = goal;
  setup.start = options.start ? *options.start : FoldState::flat(pattern);
  if (setup.start.angles.size() != n) throw PlanInputError(PlanInputError::End::Start, "plan: the start does not hold one angle per joint");
  if (!(options.resolution > 0.0) || !(options.waypoint_step > 0.0) || !(options.speed > 0.0))
    throw std::invalid_argument("plan: resolution, waypoint step and speed must be positive");

  auto system = std::make_shared<const geometry::ClosureSystem>(pattern);
  setup.system = system;
  if (system->rows() == 0 && !allow_no_loops)
    throw std::invalid_argument("plan: the pattern has no closed loop (every state is closed)");
  const statespaces::AngleBounds bounds = statespaces::AngleBounds::of(pattern, options.use_assignment);
  auto validity = std::make_shared<statespaces::FoldValidity>(pattern, bounds, options.collisions);
  setup.validity = validity;
  check_ends(setup, bounds);

  setup.plan_space = space_of(setup, options);
  lead_in(setup, options, bounds);
  setup.plan_space->build(setup, options, bounds);
  if (setup.prefix.size() > 1) {
    ob::ScopedState<> probe(setup.space);
    if (!setup.plan_space->write(setup.prefix.back(), probe.get()))
      throw PlanInputError(PlanInputError::End::Start, "plan: no closed way out of the singular start state");
  }
  setup.si->setStateValidityChecker(std::make_shared<statespaces::FoldValidityChecker>(setup.si, validity, setup.reader));
  for (std::size_t i = 1; i < setup.prefix.size() && setup.blocked.empty(); ++i)
    if (!validity->valid(setup.prefix[i])) setup.blocked = "the way out of the start state collides";
  return setup;
}

std::optional<std::vector<FoldState>> path_waypoints(const PlanSetup& setup, og::PathGeometric path, const PlanOptions& options,
                                                     bool to_goal, std::string* why, const PlanSpace::StateSink& sink,
                                                     const PlanSpace::Stop& stop) {
  // densify() of the whole list is that of each pair of neighbours joined (its projections and
  // gap checks are per pair), so each pair is densified as its second state arrives.
  std::vector<FoldState> dense;
  std::size_t added = 0;  // states of the list before densifying
  bool jumped = false;
  const auto add = [&](const FoldState& s) {
    ++added;
    if (jumped || (stop && stop())) return;  // stopped: no densifying across what was left out
    if (dense.empty()) {
      dense.push_back(s);
      if (sink) sink(s);
      return;
    }
    auto piece = geometry::densify(*setup.system, {dense.back(), s}, options.waypoint_step);
    if (!piece) {
      jumped = true;
      return;
    }
    for (std::size_t i = 1; i < piece->size(); ++i) {
      if (sink) sink((*piece)[i]);
      dense.push_back(std::move((*piece)[i]));
    }
  };
  for (const FoldState& s : setup.prefix) add(s);
  bool first = true;  // the path's first state is the prefix's last
  const bool gave_up = setup.plan_space->path_states(
      setup, std::move(path), options.waypoint_step,
      [&](const FoldState& s) {
        if (!first) add(s);
        first = false;
      },
      stop).empty();
  const bool stopped = stop && stop();
  if (stopped || (stop && gave_up)) {
    if (why) *why = stopped ? "the waypoints were stopped" : "the path needs halving, which a stop rules out";
    return std::nullopt;
  }
  // Before a jump, dense.back() is the list's last state.
  if (to_goal && !jumped && (added < 2 || (dense.back().angles - setup.goal.angles).cwiseAbs().maxCoeff() > 1e-6)) add(setup.goal);
  if (jumped) {
    if (why) *why = "the planned path jumps (interpolation left the manifold)";
    return std::nullopt;
  }
  return dense;
}

geometry::FoldSequence plan_sequence(const PlanSetup& setup, const PlanOptions& options, const std::vector<FoldState>& waypoints) {
  const geometry::CreasePattern& pattern = *setup.pattern;
  geometry::FoldSequence seq = geometry::path_sequence(pattern, waypoints, options.speed, pattern.title());
  if (!options.start_sequence.events.empty()) {
    // path_sequence starts from the flat sheet: its first event (flat → start) is replaced by
    // the start's own sequence.
    geometry::FoldSequence joined = options.start_sequence;
    const bool start_flat = setup.start.angles.cwiseAbs().maxCoeff() == 0.0;
    for (std::size_t e = start_flat ? 0 : 1; e < seq.events.size(); ++e) joined.events.push_back(seq.events[e]);
    for (std::size_t e = 0; e < joined.events.size(); ++e) joined.events[e].number = static_cast<int>(e) + 1;
    joined.title = seq.title;
    seq = std::move(joined);
  }
  return seq;
}

namespace {

// Runs the options' planner (with the single-vertex fallback where it applies) until its first
// exact solution or the time limit; the solution path, or nothing with result.status set.
// With `db`, the planner is the experience planner around it (recall, then it from scratch).
std::optional<og::PathGeometric> solve(const PlanSetup& setup, const PlanOptions& options, PlanResult& result,
                                       const ExperienceDatabase* db) {
  og::SimpleSetup ss(setup.si);
  if (const std::string why = objective_refusal(options.planner, parse_objective(options.objective)); !why.empty())
    throw PlannerRefused(canonical_planner(options.planner), why);
  ob::PlannerPtr planner = make_planner(options.planner, setup.si);
  set_planner_params(*planner, options.planner, options.params);
  const ob::PlannerPtr optimiser = planner;  // the one that reports its best cost, not the fallback around it
  std::shared_ptr<ExperiencePlanner> experience;
  if (db) {
    experience =
        std::make_shared<ExperiencePlanner>(setup.si, db, planner, make_planner("RRTConnect", setup.si), kRecallShare * options.time);
    planner = experience;
  }
  std::shared_ptr<CarpenterFallbackPlanner> fallback;
  if (setup.plan_space->fallback() == Fallback::Carpenter && options.fallback) {
    fallback = with_carpenter_fallback(setup, *setup.pattern, planner, options.time, options.waypoint_step);
    planner = fallback;
  }
  ss.setPlanner(planner);
  set_start_and_goal(setup, ss, setup.goal);
  if (auto objective = plan_objective(setup, options)) ss.setOptimizationObjective(objective);
  ss.setup();

  detail::CostRecorder costs(*optimiser, 0.02, result.cost_history);
  const auto t0 = std::chrono::steady_clock::now();
  const ob::PlannerStatus status = run_planner(setup, ss, options.time, options.cost_threshold.has_value());
  result.seconds = elapsed(t0);
  costs.stop();
  result.fallback = fallback && fallback->used_fallback();
  if (experience && result.experience) {
    result.experience->recalled = experience->recalled() && !result.fallback;
    result.experience->recall_seconds += experience->recall_seconds();
  }
  if (status == ob::PlannerStatus::EXACT_SOLUTION) return ss.getSolutionPath();
  // The fallback failed (its reason), or the time ran out (OMPL's TIMEOUT, or only an approximate
  // path in that time); anything else OMPL reports is named as it says it.
  const std::string why_not = fallback ? fallback->fallback_message() : std::string();
  if (status == ob::PlannerStatus::TIMEOUT || status == ob::PlannerStatus::APPROXIMATE_SOLUTION)
    result.status = {geometry::StatusCode::LimitReached,
                     "no plan found within " + std::to_string(options.time) + " s" + (why_not.empty() ? "" : " (" + why_not + ")")};
  else if (!why_not.empty())
    result.status = {geometry::StatusCode::NoProgress, "no plan: " + options.planner + " found none in " +
                                                           std::to_string(kSamplerShare * options.time) + " s, and " + why_not};
  else if (status == ob::PlannerStatus::INVALID_START || status == ob::PlannerStatus::INVALID_GOAL)
    result.status = {geometry::StatusCode::InvalidInput, "no plan: OMPL reports " + status.asString()};
  else
    result.status = {geometry::StatusCode::NoProgress, "no plan: OMPL reports " + status.asString()};
  return std::nullopt;
}

// Whether `path` is as short as the space's metric allows, its length the distance between its
// ends (to rounding). No shortcut can shorten it then (the triangle inequality), and reducing its
// vertices only repeats the planner's motion checks as one: for a Miura 40×40 plan whose path runs
// straight in the driving creases, 0.7 s, most of a planner time, for the same path.
bool already_shortest(const PlanSetup& setup, const og::PathGeometric& path) {
  if (path.getStateCount() < 2) return true;
  const auto last = static_cast<unsigned int>(path.getStateCount() - 1);
  const double direct = setup.si->distance(path.getState(0), path.getState(last));
  return path.length() <= direct * (1.0 + 1e-9);
}

// OMPL's simplifier on the found path, as the options ask. A path that is already shortest stays
// as it is, or, in a space of straight paths (PlanSpace::straight_paths), becomes its two ends:
// the same motion, which a StraightPlan may have followed while the planner searched.
void simplify(const PlanSetup& setup, const PlanOptions& options, og::PathGeometric& path) {
  if (options.simplify && parse_objective(options.objective).is_default() && !options.cost_threshold) {
    if (!already_shortest(setup, path)) {
      og::PathSimplifier simplifier(setup.si);
      simplifier.reduceVertices(path);
      simplifier.shortcutPath(path);
    } else if (setup.plan_space->straight_paths() && path.getStateCount() > 2) {
      og::PathGeometric ends(setup.si, path.getState(0), path.getState(static_cast<unsigned int>(path.getStateCount() - 1)));
      path = std::move(ends);
    }
  } else if (options.simplify) {
    // reduceVertices joins any two states a valid motion joins, whatever that costs (it would
    // straighten a clearance path); shortcutPath keeps a shortcut only where the objective gains.
    og::PathSimplifier simplifier(setup.si, ob::GoalPtr(), plan_objective(setup, options));
    simplifier.shortcutPath(path);
  }
}

// The options' experience database read into the setup's space (result.experience filled), or
// none without one.
std::unique_ptr<ExperienceDatabase> load_experience(const PlanSetup& setup, const PlanOptions& options, PlanResult& result) {
  if (!options.experience) return nullptr;
  if (!parse_objective(options.objective).is_default() || options.cost_threshold)
    throw std::invalid_argument(
        "plan: experience recalls by path length only: no other objective, no cost threshold (docs/PLANNING.md)");
  const ExperienceFramework framework = parse_experience_framework(options.experience->framework);
  auto db = std::make_unique<ExperienceDatabase>(setup.si, result.space, pattern_fingerprint(*setup.pattern), framework);
  const auto t0 = std::chrono::steady_clock::now();
  db->read(options.experience->bytes, options.experience->name);
  result.experience = ExperienceOutcome{};
  result.experience->framework = to_string(framework);
  result.experience->load_seconds = elapsed(t0);
  result.experience->loaded = result.experience->paths = db->paths();
  result.experience->states = db->states();
  return db;
}

}  // namespace

PlanResult plan(const geometry::CreasePattern& pattern, const FoldState& goal, const PlanOptions& options) {
  if (!(options.time > 0.0) || !std::isfinite(options.time)) throw std::invalid_argument("plan: the time limit must be positive");
  if (options.cost_threshold) check_cost_threshold(*options.cost_threshold, "plan");
  parse_objective(options.objective);  // before any work: an unknown objective is the caller's error
  if (options.experience) parse_experience_framework(options.experience->framework);
  if (options.quiet) ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  ompl::RNG::setSeed(std::max(1u, options.seed));

  const PlanSetup setup = make_plan_setup(pattern, goal, options);
  PlanResult result;
  result.planner = options.planner;
  result.objective = parse_objective(options.objective).name();
  result.space = setup.plan_space->name();
  const std::unique_ptr<ExperienceDatabase> db = load_experience(setup, options, result);
  if (!setup.blocked.empty()) {
    result.status = {geometry::StatusCode::Collision, setup.blocked};
    return result;
  }
  // A folded start in the driving space: when the planner finds no way in kSamplerShare of the
  // time, or the goal is known to lie on another branch, the plan goes through flat. A goal the
  // start's straight continuation reaches has a direct path: the planner keeps all of the time
  // (a Miura 40×40 from a fold to 0.5 to one to 0.9 needs 1.7 s, more than the quarter).
  const bool via_flat =
      options.fallback && setup.plan_space->fallback() == Fallback::ViaFlat && !setup.continues_to_goal &&
      setup.start.angles.cwiseAbs().maxCoeff() > 0.0;
  if (!setup.other_branch.empty()) {
    if (via_flat) return detail::plan_via_flat(setup, options, result, setup.other_branch);
    result.status = {geometry::StatusCode::NoProgress, "no plan: " + setup.other_branch + ": plan each end from flat instead"};
    return result;
  }
  PlanOptions direct = options;
  if (via_flat) direct.time = kSamplerShare * options.time;
  // The path the planner most often finds, followed and replayed while it searches.
  std::optional<detail::StraightPlan> straight;
  if (detail::StraightPlan::wanted(setup, options, via_flat, db != nullptr)) straight.emplace(setup, options);
  std::optional<og::PathGeometric> path = solve(setup, direct, result, db.get());
  if (!path) straight.reset();
  if (!path && via_flat)
    return detail::plan_via_flat(
        setup, options, result, options.planner + " found no direct plan in " + std::to_string(direct.time) + " s (" + result.status.message + ")");
  if (!path) return result;
  simplify(setup, options, *path);
  std::optional<std::vector<FoldState>> dense;
  if (straight && straight->matches(*path)) dense = straight->waypoints();
  if (!dense) straight.reset();
  // Otherwise the replay starts on the first waypoints while the later ones are computed
  // (2-core machines: the replay and the continuation were each about a planner time of a Miura
  // 40×40 plan).
  std::optional<detail::ReplayPipeline> own;
  if (!straight) own.emplace(setup, options);
  detail::ReplayPipeline& pipeline = straight ? straight->pipeline() : *own;
  std::string why;
  if (!dense) dense = path_waypoints(setup, *path, options, true, &why, [&](const FoldState& s) { pipeline.push(s); });
  if (!dense) {
    result.status = {geometry::StatusCode::ClosureViolated, why};
    return result;
  }
  detail::finish_plan(setup, options, *dense, result,
                      result.fallback ? "solved by the Carpenter fallback (" + options.planner + " found no plan in " +
                                            std::to_string(kSamplerShare * options.time) + " s)"
                                      : std::string("solved"),
                      &pipeline);
  // A plan that checks out is experience: the space's own states (a straight path cut to its ends).
  if (db && result.status) {
    if (!result.fallback) db->add(*path);
    result.experience->paths = db->paths();
    result.experience->states = db->states();
    result.experience->bytes = db->bytes();
  }
  return result;
}

}  // namespace foldkit::planners
