// Deterministic folding methods as OMPL planners, so that ompl::tools::Benchmark times them and
// records the same properties as for the sampling planners.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include <ompl/base/goals/GoalState.h>
#include <ompl/geometric/PathGeometric.h>

#include "foldkit/folding/projected_folding.hpp"
#include "foldkit/geometry/closure_path.hpp"
#include "foldkit/bench/deterministic_planner.hpp"
#include "foldkit/bench/scenes.hpp"
#include "foldkit/planners/carpenter_fallback.hpp"
#include "foldkit/planners/plan.hpp"
#include "foldkit/planners/planner_factory.hpp"

namespace foldkit::bench {

using planners::canonical_planner;

namespace ob = ompl::base;
namespace og = ompl::geometric;
using geometry::FoldState;

DeterministicPlanner::DeterministicPlanner(const ob::SpaceInformationPtr& si, const std::string& name,
                                           DeterministicMethod method, const geometry::CreasePattern& pattern,
                                           statespaces::StateReader reader, Writer writer, std::vector<FoldState> lead_in,
                                           double step)
    : ob::Planner(si, name),
      method_(std::move(method)),
      pattern_(&pattern),
      reader_(std::move(reader)),
      writer_(std::move(writer)),
      lead_in_(std::move(lead_in)),
      step_(step) {
  specs_.approximateSolutions = true;
}

void DeterministicPlanner::clear() { ob::Planner::clear(); }

ob::PlannerStatus DeterministicPlanner::solve(const ob::PlannerTerminationCondition& ptc) {
  checkValidity();
  const ob::State* start_state = pis_.nextStart();
  if (!start_state) return ob::PlannerStatus::INVALID_START;
  const auto* goal = dynamic_cast<const ob::GoalState*>(pdef_->getGoal().get());
  if (!goal) return ob::PlannerStatus::UNRECOGNIZED_GOAL_TYPE;
  DeterministicProblem problem;
  problem.pattern = pattern_;
  problem.step = step_;
  if (!reader_(start_state, problem.start)) return ob::PlannerStatus::INVALID_START;
  if (!reader_(goal->getState(), problem.goal)) return ob::PlannerStatus::INVALID_GOAL;
  problem.lead_in = lead_in_.empty() ? std::vector<FoldState>{problem.start} : lead_in_;

  const std::vector<FoldState> way = method_(problem, ptc);
  if (way.empty()) return ptc() ? ob::PlannerStatus::TIMEOUT : ob::PlannerStatus::ABORT;

  // The longest prefix the space accepts: every state valid, every motion valid.
  auto path = std::make_shared<og::PathGeometric>(si_);
  path->append(start_state);
  ob::State* next = si_->allocState();
  const std::size_t first = (way.front().angles - problem.start.angles).cwiseAbs().maxCoeff() < 1e-9 ? 1 : 0;
  for (std::size_t i = first; i < way.size(); ++i) {
    if (!writer_(way[i], next) || !si_->isValid(next) || !si_->checkMotion(path->getStates().back(), next)) break;
    path->append(next);
  }
  si_->freeState(next);
  double distance = 0.0;
  const bool exact = goal->isSatisfied(path->getStates().back(), &distance);
  pdef_->addSolutionPath(path, !exact, distance, getName());
  return exact ? ob::PlannerStatus::EXACT_SOLUTION : ob::PlannerStatus::APPROXIMATE_SOLUTION;
}

namespace {

struct Method {
  const char* name;
  DeterministicMethod method;
};

// Methods that fold from the flat sheet, while the planner starts where the way out of a
// singular start ends (flat itself may be a state the space cannot hold): the way joins the
// method's path at its state nearest to the planner's start, and the goal is appended when the
// path ends within two steps of it (the motion validator judges both joins like any segment).
std::vector<FoldState> from_flat(const DeterministicProblem& p, const std::vector<FoldState>& out_of_flat) {
  if (out_of_flat.size() < 2) return {};
  std::size_t nearest = 1;
  for (std::size_t i = 1; i < out_of_flat.size(); ++i)
    if ((out_of_flat[i].angles - p.start.angles).cwiseAbs().maxCoeff() <
        (out_of_flat[nearest].angles - p.start.angles).cwiseAbs().maxCoeff())
      nearest = i;
  std::vector<FoldState> way{p.start};
  way.insert(way.end(), out_of_flat.begin() + static_cast<std::ptrdiff_t>(nearest), out_of_flat.end());
  const double gap = (way.back().angles - p.goal.angles).cwiseAbs().maxCoeff();
  if (gap > 1e-9 && gap <= 2.0 * p.step) way.push_back(p.goal);
  return way;
}

const std::vector<Method>& methods() {
  static const std::vector<Method> m = {
      {"ProjectedLine",
       [](const DeterministicProblem& p, const ob::PlannerTerminationCondition&) {
         return geometry::projected_line(geometry::ClosureSystem(*p.pattern), p.start, p.goal, p.step);
       }},
      // Tachi's projected-velocity folding from flat, the desired velocity pointing at the goal,
      // until the largest fold angle is the goal's.
      {"ProjectedFolding",
       [](const DeterministicProblem& p, const ob::PlannerTerminationCondition&) -> std::vector<FoldState> {
         folding::ProjectedFoldingOptions o;
         o.velocity = p.goal.angles;
         o.target_fraction = std::min(1.0, p.goal.angles.cwiseAbs().maxCoeff() / M_PI);
         o.max_step = p.step;
         o.replay = false;
         try {
           return from_flat(p, folding::fold_projected(*p.pattern, o).states);
         } catch (const std::invalid_argument&) {
           return {};
         }
       }},
      // Carpenter's rule on the sphere (single vertices): the goal flattened, the frames reversed
      // (planners::carpenter_path from flat, as the fallback of plan() uses it).
      {"SphericalCarpenter",
       [](const DeterministicProblem& p, const ob::PlannerTerminationCondition&) -> std::vector<FoldState> {
         return from_flat(p, planners::carpenter_path(*p.pattern, FoldState::flat(*p.pattern), p.goal, p.step, nullptr));
       }},
  };
  return m;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

}  // namespace

std::vector<std::string> deterministic_planner_names() {
  std::vector<std::string> names;
  for (const Method& m : methods()) names.emplace_back(m.name);
  return names;
}

bool is_deterministic_planner(const std::string& name) {
  for (const Method& m : methods())
    if (lower(name) == lower(m.name)) return true;
  return false;
}

DeterministicMethod deterministic_method(const std::string& name) {
  for (const Method& m : methods())
    if (lower(name) == lower(m.name)) return m.method;
  throw std::invalid_argument("unknown deterministic planner '" + name + "'");
}

std::string fallback_inner(const std::string& name) {
  const std::string tail = "+carpenter";
  const std::string l = lower(name);
  if (l.size() <= tail.size() || l.compare(l.size() - tail.size(), tail.size(), tail) != 0) return {};
  return name.substr(0, name.size() - tail.size());
}

std::pair<std::string, std::string> planner_and_space(const std::string& entry) {
  const auto at = entry.rfind('@');
  if (at == std::string::npos) return {entry, ""};
  return {entry.substr(0, at), entry.substr(at + 1)};
}

std::string canonical_bench_planner(const std::string& entry) {
  const auto [name, space] = planner_and_space(entry);
  if (!space.empty()) return canonical_bench_planner(name) + "@" + planners::to_string(planners::parse_space(space));
  for (const Method& m : methods())
    if (lower(name) == lower(m.name)) return m.name;
  const std::string inner = fallback_inner(name);
  if (!inner.empty() && !is_deterministic_planner(inner)) return canonical_planner(inner) + "+Carpenter";
  try {
    return canonical_planner(name);
  } catch (const std::invalid_argument& e) {
    std::string known;
    for (const auto& d : deterministic_planner_names()) known += ", " + d;
    throw std::invalid_argument(std::string(e.what()).substr(0, std::string(e.what()).size() - 1) + known + ")");
  }
}

}  // namespace foldkit::bench
