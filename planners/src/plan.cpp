#include "foldkit/planners/plan.hpp"
#include "foldkit/planners/plan_setup.hpp"

#include <chrono>
#include <cmath>
#include <functional>
#include <optional>
#include <stdexcept>

#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/constraint/AtlasStateSpace.h>
#include <ompl/geometric/PathSimplifier.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include "foldkit/geometry/closure_path.hpp"
#include "foldkit/geometry/driving_chart.hpp"
#include "foldkit/geometry/mobility.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/planners/carpenter_fallback.hpp"
#include "foldkit/planners/planner_factory.hpp"
#include "foldkit/statespaces/closure_constraint.hpp"
#include "foldkit/statespaces/driving_space.hpp"
#include "foldkit/statespaces/single_vertex_space.hpp"
#include "foldkit/statespaces/validity.hpp"
#include "plan_finish.hpp"

namespace foldkit::planners {

namespace ob = ompl::base;
namespace og = ompl::geometric;
using geometry::FoldState;

namespace {

constexpr SpaceKind kSpaceKinds[] = {SpaceKind::Auto,      SpaceKind::SingleVertex, SpaceKind::Driving,
                                     SpaceKind::Projected, SpaceKind::Atlas,        SpaceKind::TangentBundle};

}  // namespace

std::vector<std::string> space_names() {
  std::vector<std::string> names;
  for (SpaceKind k : kSpaceKinds) names.emplace_back(to_string(k));
  return names;
}

SpaceKind parse_space(const std::string& name) {
  for (SpaceKind k : kSpaceKinds)
    if (name == to_string(k)) return k;
  std::string known;
  for (const auto& n : space_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown space '" + name + "' (" + known + ")");
}

const char* to_string(SpaceKind kind) {
  switch (kind) {
    case SpaceKind::SingleVertex: return "single-vertex";
    case SpaceKind::Driving: return "driving";
    case SpaceKind::Projected: return "projected";
    case SpaceKind::Atlas: return "atlas";
    case SpaceKind::TangentBundle: return "tangent-bundle";
    default: return "auto";
  }
}

namespace {

double elapsed(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

bool PlanSetup::write(const FoldState& state, ob::State* out) const {
  if (single_vertex) return single_vertex->from_fold_state(state, out);
  if (driving) return driving->from_fold_state(state, out);
  if (joint_space) {
    auto* v = out->as<ob::RealVectorStateSpace::StateType>();
    for (Eigen::Index j = 0; j < state.angles.size(); ++j) v->values[j] = state.angles[j];
    return true;
  }
  out->as<ob::ConstrainedStateSpace::StateType>()->copy(state.angles);
  return true;
}

ob::PlannerStatus PlanSetup::solve(og::SimpleSetup& ss, double seconds) const {
  const statespaces::FoldValidity::TimeLimit limit(*validity, seconds);
  return ss.solve(ob::plannerOrTerminationCondition(ob::timedPlannerTerminationCondition(seconds),
                                                    ob::exactSolnPlannerTerminationCondition(ss.getProblemDefinition())));
}

void PlanSetup::set_start_and_goal(og::SimpleSetup& ss, const FoldState& goal) const {
  ob::ScopedState<> s(space), g(space);
  write(prefix.back(), s.get());
  if (!write(goal, g.get()))
    throw PlanInputError(PlanInputError::End::Goal, std::string("plan: the goal is a singular state of the ") + (driving ? "driving" : "single-vertex") +
                                " space (try --space projected)");
  ss.setStartAndGoalStates(s, g, 1e-9);
  if (kind == SpaceKind::Atlas || kind == SpaceKind::TangentBundle) {
    auto atlas = std::static_pointer_cast<ob::AtlasStateSpace>(constrained.space);
    atlas->anchorChart(s.get());
    atlas->anchorChart(g.get());
  }
}

namespace {

// The SpaceInformation of setup.space (setup.reader set first), with the motion validator every
// space but the constrained ones uses (those bring their own).
void use_space(PlanSetup& setup, const PlanRequest& req) {
  setup.si = std::make_shared<ob::SpaceInformation>(setup.space);
  setup.si->setMotionValidator(std::make_shared<statespaces::FoldMotionValidator>(setup.si, setup.validity, setup.reader,
                                                                                   req.resolution, 2.5 * req.resolution));
}

// The joint-angle box: a pattern without a closed loop, where every state is closed.
void set_up_joint_space(PlanSetup& setup, const PlanRequest& req, const statespaces::AngleBounds& bounds) {
  const auto n = static_cast<Eigen::Index>(req.pattern->joints().size());
  auto box = std::make_shared<ob::RealVectorStateSpace>(static_cast<unsigned int>(n));
  ob::RealVectorBounds b(static_cast<unsigned int>(n));
  for (Eigen::Index j = 0; j < n; ++j) {
    b.setLow(static_cast<unsigned int>(j), bounds.lower[j]);
    b.setHigh(static_cast<unsigned int>(j), bounds.upper[j]);
  }
  box->setBounds(b);
  setup.space = box;
  setup.reader = [n](const ob::State* s, FoldState& f) {
    f.angles = Eigen::Map<const Eigen::VectorXd>(s->as<ob::RealVectorStateSpace::StateType>()->values, n);
    return true;
  };
  use_space(setup, req);
}

// The exact single-vertex space (n − 3 active angles, the rest in closed form).
void set_up_single_vertex_space(PlanSetup& setup, const PlanRequest& req, const statespaces::AngleBounds& bounds) {
  auto chain = std::make_shared<statespaces::SingleVertexChain>(*req.pattern);
  auto sv = std::make_shared<statespaces::SingleVertexStateSpace>(chain, bounds);
  setup.single_vertex = sv;
  setup.space = sv;
  setup.reader = statespaces::single_vertex_reader(sv);
  use_space(setup, req);
  ob::ScopedState<> probe_state(setup.space);
  if (!sv->from_fold_state(setup.start, probe_state.get())) {
    // The start is singular for the closed form (e.g. a flat vertex whose passive axes line up):
    // leave it along a short closed segment first.
    setup.prefix = geometry::lead_in(*setup.system, setup.start, req.goal, 3, req.waypoint_step);
    if (setup.prefix.empty() || !sv->from_fold_state(setup.prefix.back(), probe_state.get()))
      throw PlanInputError(PlanInputError::End::Start, "plan: no closed way out of the singular start state");
  }
}

// The driving space's focus box: the box of the plan's start and goal, widened by this (radians),
// receives this share of the uniform samples (docs/PLANNING.md: measured at 0.5 and 0.9).
constexpr double kFocusMargin = 0.2, kFocusShare = 0.9;

// Why the driving space cannot reach `goal` from `from`, or "" when it may; `reaches` says whether
// the straight continuation in the chart from `from` to the goal's driving angles ends at the goal
// (then a direct path exists, collisions aside). With one degree of freedom the closed states near
// `from` are one curve, a graph over the driving crease while the chart stays regular, and every
// motion of the space is a continuation along it. Following it to the goal's driving angle either
// reaches the goal, stops at a singular state (then nothing is known: the planner searches as
// usual), or reaches another closed state: the goal is on another branch (another mode of
// folding), and the planner would only run out its time.
std::string other_branch(const geometry::ClosureSystem& system, const geometry::DrivingChart& chart, const FoldState& from,
                         const FoldState& goal, bool& reaches) {
  geometry::PassiveSolver solver(system, chart);
  FoldState reached;
  reaches = false;
  if (!solver.follow(from, solver.driving_of(goal), reached).ok()) return {};
  Eigen::Index worst = 0;
  const double gap = (reached.angles - goal.angles).cwiseAbs().maxCoeff(&worst);
  reaches = gap <= 1e-6;
  if (reaches || chart.driving.size() != 1) return {};
  const auto& joints = system.pattern().joints();
  const int driving = joints[static_cast<std::size_t>(chart.driving[0])].id, id = joints[static_cast<std::size_t>(worst)].id;
  return "the goal is on another branch than the start: the start's one-DOF motion reaches the goal's driving angle "
         "(crease " + std::to_string(driving) + ") with crease " + std::to_string(id) + " at " +
         std::to_string(reached.angles[worst] * 180.0 / M_PI) + " deg instead of the goal's " +
         std::to_string(goal.angles[worst] * 180.0 / M_PI) + " deg; the branches meet only at a singular state "
         "(flat, for a Miura sheet), which no motion of the driving space passes";
}

// The driving-crease space: the chart is chosen at the goal (or, when the goal is singular, at
// the end of the way out of the start), DOF-many coordinates, the rest by closure.
void set_up_driving_space(PlanSetup& setup, const PlanRequest& req, const statespaces::AngleBounds& bounds) {
  const geometry::ClosureSystem& system = *setup.system;
  const geometry::Mobility at_goal = geometry::mobility(system, req.goal);
  const geometry::Mobility at_start = geometry::mobility(system, setup.start);
  const Eigen::Index rank = std::max(at_goal.rank, at_start.rank);
  if (at_start.rank < rank) {
    // Flat (or another singular state): leave it along a short closed segment first.
    setup.prefix = geometry::lead_in(system, setup.start, req.goal, rank, req.waypoint_step);
    if (setup.prefix.empty()) throw PlanInputError(PlanInputError::End::Start, "plan: no closed way out of the singular start state");
  }
  const FoldState& from = setup.prefix.back();
  const FoldState& chart_state = at_goal.rank >= rank ? req.goal : from;
  const int dof = static_cast<int>(system.cols() - rank);
  if (dof == 0) throw std::invalid_argument("plan: the pattern is rigid (0 degrees of freedom): nothing can move");
  geometry::DrivingChart chart = geometry::choose_driving_chart(system, chart_state, dof, std::max(1u, req.seed));
  // Sampling bounds of each driving crease: its angle bounds, narrowed to the side of flat that
  // both ends of the plan are on (flat is singular; the goal's signs pick the branch).
  // Most uniform samples go to the focus box, that of start and goal widened by kFocusMargin: a
  // box of many driving creases is mostly out of reach, and RRTConnect's extensions towards such
  // samples each cost a continuation (waterbomb 4x4, 13 DOF: 20x faster). The other samples keep
  // the whole box covered.
  Eigen::VectorXd lo(dof), hi(dof), focus_lo(dof), focus_hi(dof);
  for (int i = 0; i < dof; ++i) {
    const int j = chart.driving[static_cast<std::size_t>(i)];
    lo[i] = bounds.lower[j];
    hi[i] = bounds.upper[j];
    if (req.goal.angles[j] > 0.0 && from.angles[j] > 0.0) lo[i] = std::max(lo[i], 0.0);
    if (req.goal.angles[j] < 0.0 && from.angles[j] < 0.0) hi[i] = std::min(hi[i], 0.0);
    focus_lo[i] = std::min(req.goal.angles[j], from.angles[j]) - kFocusMargin;
    focus_hi[i] = std::max(req.goal.angles[j], from.angles[j]) + kFocusMargin;
  }
  setup.unreachable = other_branch(system, chart, from, req.goal, setup.reachable);
  auto space = std::make_shared<statespaces::DrivingStateSpace>(setup.system, std::move(chart), bounds, lo, hi);
  space->set_focus(focus_lo, focus_hi, kFocusShare);
  if (!space->add_anchor(from)) throw PlanInputError(PlanInputError::End::Start, "plan: the start is a singular state of the driving space (try --space projected)");
  if (!space->add_anchor(req.goal)) throw PlanInputError(PlanInputError::End::Goal, "plan: the goal is a singular state of the driving space (try --space projected)");
  setup.driving = space;
  setup.space = space;
  setup.reader = statespaces::driving_reader(space);
  use_space(setup, req);
}

// OMPL's Projected, Atlas or TangentBundle space on the closure constraint.
void set_up_constrained_space(PlanSetup& setup, const PlanRequest& req, const statespaces::AngleBounds& bounds) {
  const FoldState& start = setup.start;
  const auto ck = setup.kind == SpaceKind::Atlas           ? statespaces::ConstrainedKind::Atlas
                  : setup.kind == SpaceKind::TangentBundle ? statespaces::ConstrainedKind::TangentBundle
                                                           : statespaces::ConstrainedKind::Projected;
  statespaces::AngleBounds box = bounds;
  if (req.search_margin >= 0.0) {
    box.lower = box.lower.array().max(start.angles.cwiseMin(req.goal.angles).array() - req.search_margin).matrix();
    box.upper = box.upper.array().min(start.angles.cwiseMax(req.goal.angles).array() + req.search_margin).matrix();
  }
  setup.constrained = statespaces::make_constrained(*req.pattern, req.goal, ck, box, req.numerical_jacobian, 2.5 * req.resolution);
  setup.space = setup.constrained.space;
  setup.si = setup.constrained.si;
  setup.reader = statespaces::constrained_reader();
  const auto rank = static_cast<Eigen::Index>(setup.constrained.constraint->getCoDimension());
  if (geometry::mobility(*setup.system, start).rank < rank) {
    // Flat (or another singular state): the Jacobian loses rank, charts cannot be anchored
    // and projections may flip branches; plan from a nearby regular state instead.
    setup.prefix = geometry::lead_in(*setup.system, start, req.goal, rank, req.waypoint_step);
    if (setup.prefix.empty()) throw PlanInputError(PlanInputError::End::Start, "plan: no closed way out of the singular start state");
  }
}

// The start and goal must close, keep the assignment and not cross (std::invalid_argument).
void check_ends(const PlanSetup& setup, const PlanRequest& req, const statespaces::AngleBounds& bounds) {
  const FoldState& start = setup.start;
  const double start_error = setup.system->max_error(start), goal_error = setup.system->max_error(req.goal);
  if (start_error > 1e-6) throw PlanInputError(PlanInputError::End::Start, "plan: the start is not closed (error " + std::to_string(start_error) + " rad)");
  if (goal_error > 1e-6) throw PlanInputError(PlanInputError::End::Goal, "plan: the goal is not closed (error " + std::to_string(goal_error) + " rad)");
  if (!bounds.contains(start, 1e-9)) throw PlanInputError(PlanInputError::End::Start, "plan: the start breaks the mountain/valley assignment");
  if (!bounds.contains(req.goal, 1e-9)) throw PlanInputError(PlanInputError::End::Goal, "plan: the goal breaks the mountain/valley assignment");
  if (!setup.validity->valid(start)) throw PlanInputError(PlanInputError::End::Start, "plan: the start state is not valid (facets cross)");
  if (!setup.validity->valid(req.goal)) throw PlanInputError(PlanInputError::End::Goal, "plan: the goal state is not valid (facets cross)");
}

}  // namespace

PlanSetup make_plan_setup(const PlanRequest& req, bool allow_no_loops) {
  if (!req.pattern) throw std::invalid_argument("plan: no pattern");
  const geometry::CreasePattern& pattern = *req.pattern;
  const auto n = static_cast<Eigen::Index>(pattern.joints().size());
  if (req.goal.angles.size() != n) throw PlanInputError(PlanInputError::End::Goal, "plan: the goal does not hold one angle per joint");
  PlanSetup setup;
  setup.start = req.start ? *req.start : FoldState::flat(pattern);
  if (setup.start.angles.size() != n) throw PlanInputError(PlanInputError::End::Start, "plan: the start does not hold one angle per joint");
  if (!(req.resolution > 0.0) || !(req.waypoint_step > 0.0) || !(req.velocity > 0.0))
    throw std::invalid_argument("plan: resolution, waypoint step and velocity must be positive");

  SpaceKind kind = req.space;
  if (kind == SpaceKind::Auto)
    kind = pattern.interior_vertices().size() == 1 && geometry::hole_count(pattern) == 0 ? SpaceKind::SingleVertex
                                                                                       : SpaceKind::Driving;
  auto system = std::make_shared<const geometry::ClosureSystem>(pattern);
  setup.system = system;
  if (system->rows() == 0 && !allow_no_loops)
    throw std::invalid_argument("plan: the pattern has no closed loop (every state is closed)");
  setup.joint_space = system->rows() == 0;
  if (setup.joint_space) kind = SpaceKind::Auto;
  setup.kind = kind;
  setup.space_name = setup.joint_space ? "joint" : to_string(kind);
  const statespaces::AngleBounds bounds = statespaces::AngleBounds::of(pattern, req.use_assignment);
  auto validity = std::make_shared<statespaces::FoldValidity>(pattern, bounds, req.collisions);
  setup.validity = validity;
  check_ends(setup, req, bounds);

  setup.prefix = {setup.start};
  if (setup.joint_space)
    set_up_joint_space(setup, req, bounds);
  else if (kind == SpaceKind::SingleVertex)
    set_up_single_vertex_space(setup, req, bounds);
  else if (kind == SpaceKind::Driving)
    set_up_driving_space(setup, req, bounds);
  else
    set_up_constrained_space(setup, req, bounds);
  setup.si->setStateValidityChecker(std::make_shared<statespaces::FoldValidityChecker>(setup.si, validity, setup.reader));
  for (std::size_t i = 1; i < setup.prefix.size() && setup.blocked.empty(); ++i)
    if (!validity->valid(setup.prefix[i])) setup.blocked = "the way out of the start state collides";
  return setup;
}

namespace {

// The states strictly between `a` and `b` on the single-vertex space's motion from one to the
// other, appended to `out`: the motion is linear in the active angles, so evenly spaced states at
// most `step` apart in every crease.
void single_vertex_motion(const PlanSetup& setup, const ob::State* a, const ob::State* b, double step, ob::State* tmp,
                          std::vector<FoldState>& out) {
  const auto& sv = setup.single_vertex;
  const FoldState fa = sv->to_fold_state(a), fb = sv->to_fold_state(b);
  const int parts = std::max(1, static_cast<int>(std::ceil((fb.angles - fa.angles).cwiseAbs().maxCoeff() / step)));
  for (int k = 1; k < parts; ++k) {
    sv->interpolate(a, b, static_cast<double>(k) / parts, tmp);
    FoldState f;
    if (!setup.reader(tmp, f)) break;
    out.push_back(f);
  }
}

// The states strictly between `a` and `b` on the driving space's motion from one to the other,
// appended to `out`: the interval of the motion is halved until neighbours differ by at most
// `step` in every crease (or after 16 halvings; densify() then judges the gap).
void driving_motion(const PlanSetup& setup, const ob::State* a, const ob::State* b, double step, ob::State* tmp,
                    std::vector<FoldState>& out) {
  FoldState fa, fb;
  if (!setup.reader(a, fa) || !setup.reader(b, fb)) return;
  const std::function<void(double, const FoldState&, double, const FoldState&, int)> fill =
      [&](double ta, const FoldState& sa, double tb, const FoldState& sb, int depth) {
        if (depth == 0 || (sb.angles - sa.angles).cwiseAbs().maxCoeff() <= step) return;
        const double tm = 0.5 * (ta + tb);
        setup.driving->interpolate(a, b, tm, tmp);
        FoldState sm;
        if (!setup.reader(tmp, sm)) return;
        fill(ta, sa, tm, sm, depth - 1);
        out.push_back(sm);
        fill(tm, sm, tb, sb, depth - 1);
      };
  fill(0.0, fa, 1.0, fb, 16);
}

}  // namespace

std::optional<std::vector<FoldState>> path_waypoints(const PlanSetup& setup, og::PathGeometric path, const PlanRequest& req,
                                                     bool to_goal, std::string* why) {
  // The path's states, densified along the space's own interpolation: single-vertex segments
  // are linear in the active angles; driving ones are halved until no crease moves more than the
  // waypoint step (near a fold of the chart the passives move much faster than the driving angles,
  // and OMPL's path.interpolate(), spaced by the driving distance, left gaps there that densify()'s
  // straight projections could not bridge: a Resch plan was refused as a jump); constrained ones
  // follow the manifold (OMPL's geodesic).
  std::vector<FoldState> states;
  if (setup.single_vertex || setup.driving) {
    const auto motion = setup.single_vertex ? single_vertex_motion : driving_motion;
    ob::State* tmp = setup.si->allocState();
    for (unsigned int i = 0; i < static_cast<unsigned int>(path.getStateCount()); ++i) {
      FoldState f;
      if (i > 0) motion(setup, path.getState(i - 1), path.getState(i), req.waypoint_step, tmp, states);
      if (setup.reader(path.getState(i), f)) states.push_back(f);
    }
    setup.si->freeState(tmp);
  } else {
    path.interpolate();
    for (unsigned int i = 0; i < static_cast<unsigned int>(path.getStateCount()); ++i) {
      FoldState f;
      setup.reader(path.getState(i), f);
      states.push_back(f);
    }
  }
  std::vector<FoldState> full = setup.prefix;
  full.insert(full.end(), states.begin() + (states.empty() ? 0 : 1), states.end());
  if (to_goal && (full.size() < 2 || (full.back().angles - req.goal.angles).cwiseAbs().maxCoeff() > 1e-6))
    full.push_back(req.goal);
  auto dense = geometry::densify(*setup.system, full, req.waypoint_step);
  if (!dense && why) *why = "the planned path jumps (interpolation left the manifold)";
  return dense;
}

geometry::FoldSequence plan_sequence(const PlanRequest& req, const PlanSetup& setup, const std::vector<FoldState>& waypoints) {
  const geometry::CreasePattern& pattern = *req.pattern;
  geometry::FoldSequence seq = geometry::path_sequence(pattern, waypoints, req.velocity, pattern.title());
  if (!req.start_sequence.events.empty()) {
    // path_sequence starts from the flat sheet: its first event (flat → start) is replaced by
    // the start's own sequence.
    geometry::FoldSequence joined = req.start_sequence;
    const bool start_flat = setup.start.angles.cwiseAbs().maxCoeff() == 0.0;
    for (std::size_t e = start_flat ? 0 : 1; e < seq.events.size(); ++e) joined.events.push_back(seq.events[e]);
    for (std::size_t e = 0; e < joined.events.size(); ++e) joined.events[e].number = static_cast<int>(e) + 1;
    joined.title = seq.title;
    seq = std::move(joined);
  }
  return seq;
}

namespace {

// Runs the request's planner (with the single-vertex fallback where it applies) until its first
// exact solution or the time limit; the solution path, or nothing with result.status set.
std::optional<og::PathGeometric> solve(const PlanSetup& setup, const PlanRequest& req, PlanResult& result) {
  og::SimpleSetup ss(setup.si);
  ob::PlannerPtr planner = make_planner(req.planner, setup.si);
  set_planner_params(*planner, req.planner, req.params);
  std::shared_ptr<CarpenterFallbackPlanner> fallback;
  if (setup.single_vertex && req.fallback) {
    fallback = with_carpenter_fallback(setup, *req.pattern, planner, req.time, req.waypoint_step);
    planner = fallback;
  }
  ss.setPlanner(planner);
  setup.set_start_and_goal(ss, req.goal);
  ss.setup();

  const auto t0 = std::chrono::steady_clock::now();
  const ob::PlannerStatus status = setup.solve(ss, req.time);
  result.time = elapsed(t0);
  result.fallback = fallback && fallback->used_fallback();
  if (status == ob::PlannerStatus::EXACT_SOLUTION) return ss.getSolutionPath();
  // The fallback failed (its reason), or the time ran out (OMPL's TIMEOUT, or only an approximate
  // path in that time); anything else OMPL reports is named as it says it.
  const std::string why_not = fallback ? fallback->fallback_message() : std::string();
  if (status == ob::PlannerStatus::TIMEOUT || status == ob::PlannerStatus::APPROXIMATE_SOLUTION)
    result.status = {geometry::StatusCode::LimitReached,
                     "no plan found within " + std::to_string(req.time) + " s" + (why_not.empty() ? "" : " (" + why_not + ")")};
  else if (!why_not.empty())
    result.status = {geometry::StatusCode::NoProgress, "no plan: " + req.planner + " found none in " +
                                                           std::to_string(kSamplerShare * req.time) + " s, and " + why_not};
  else if (status == ob::PlannerStatus::INVALID_START || status == ob::PlannerStatus::INVALID_GOAL)
    result.status = {geometry::StatusCode::InvalidInput, "no plan: OMPL reports " + status.asString()};
  else
    result.status = {geometry::StatusCode::NoProgress, "no plan: OMPL reports " + status.asString()};
  return std::nullopt;
}

}  // namespace

PlanResult plan(const PlanRequest& req) {
  if (!req.pattern) throw std::invalid_argument("plan: no pattern");
  if (!(req.time > 0.0) || !std::isfinite(req.time)) throw std::invalid_argument("plan: the time limit must be positive");
  if (req.quiet) ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
  ompl::RNG::setSeed(std::max(1u, req.seed));

  const PlanSetup setup = make_plan_setup(req);
  PlanResult result;
  result.planner = req.planner;
  result.space = setup.space_name;
  if (!setup.blocked.empty()) {
    result.status = {geometry::StatusCode::Collision, setup.blocked};
    return result;
  }
  // A folded start in the driving space: when the planner finds no way in kSamplerShare of the
  // time, or the goal is known to lie on another branch, the plan goes through flat. A goal the
  // start's straight continuation reaches has a direct path: the planner keeps all of the time
  // (a Miura 40×40 from a fold to 0.5 to one to 0.9 needs 1.7 s, more than the quarter).
  const bool via_flat =
      req.fallback && setup.driving && !setup.reachable && setup.start.angles.cwiseAbs().maxCoeff() > 0.0;
  if (!setup.unreachable.empty()) {
    if (via_flat) return detail::plan_via_flat(req, setup, result, setup.unreachable);
    result.status = {geometry::StatusCode::NoProgress, "no plan: " + setup.unreachable + ": plan each end from flat instead"};
    return result;
  }
  PlanRequest direct = req;
  if (via_flat) direct.time = kSamplerShare * req.time;
  std::optional<og::PathGeometric> path = solve(setup, direct, result);
  if (!path && via_flat)
    return detail::plan_via_flat(
        req, setup, result, req.planner + " found no direct plan in " + std::to_string(direct.time) + " s (" + result.status.message + ")");
  if (!path) return result;
  if (req.simplify) {
    og::PathSimplifier simplifier(setup.si);
    simplifier.reduceVertices(*path);
    simplifier.shortcutPath(*path);
  }
  std::string why;
  const auto dense = path_waypoints(setup, *path, req, true, &why);
  if (!dense) {
    result.status = {geometry::StatusCode::ClosureViolated, why};
    return result;
  }
  return detail::finish_plan(req, setup, *dense, result,
                             result.fallback ? "solved by the Carpenter fallback (" + req.planner + " found no plan in " +
                                                   std::to_string(kSamplerShare * req.time) + " s)"
                                             : std::string("solved"));
}

}  // namespace foldkit::planners
