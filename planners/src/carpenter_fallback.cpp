#include "foldkit/planners/carpenter_fallback.hpp"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <memory>
#include <stdexcept>

#include <ompl/base/PlannerData.h>
#include <ompl/base/PlannerTerminationCondition.h>
#include <ompl/base/goals/GoalState.h>
#include <ompl/geometric/PathGeometric.h>

#include "foldkit/folding/carpenter_spherical.hpp"

namespace foldkit::planners {

namespace ob = ompl::base;
namespace og = ompl::geometric;
using geometry::FoldState;

std::vector<FoldState> carpenter_path(const geometry::CreasePattern& pattern, const FoldState& start, const FoldState& goal,
                                      double step, std::string* why, const std::function<bool()>& stop) {
  folding::CarpenterSphericalOptions options;
  options.frame_step = step;
  options.stop = stop;
  // An end → flat (the end itself when it is flat already).
  const auto flatten = [&](const FoldState& end, const char* which) -> std::vector<FoldState> {
    if (end.angles.cwiseAbs().maxCoeff() == 0.0) return {end};
    try {
      folding::CarpenterSphericalResult r = folding::flatten_single_vertex(pattern, end, options);
      if (r.status.ok()) return std::move(r.frames);
      if (stop && r.status.code == geometry::StatusCode::LimitReached && stop()) {
        if (why) *why = std::string("the time ran out while Carpenter's rule flattened the ") + which;
        return {};
      }
      if (why) *why = std::string("Carpenter's rule does not flatten the ") + which + ": " + r.status.message;
    } catch (const std::invalid_argument& e) {
      if (why) *why = std::string("Carpenter's rule does not take the ") + which + ": " + e.what();
    }
    return {};
  };
  std::vector<FoldState> way = flatten(start, "start");
  if (way.empty()) return {};
  const std::vector<FoldState> back = flatten(goal, "goal");
  if (back.empty()) return {};
  way.insert(way.end(), back.rbegin() + 1, back.rend());  // both end exactly flat: one flat frame
  return way;
}

CarpenterFallbackPlanner::CarpenterFallbackPlanner(const ob::SpaceInformationPtr& si, ob::PlannerPtr inner, double inner_time,
                                                   const geometry::CreasePattern& pattern,
                                                   std::shared_ptr<const statespaces::SingleVertexStateSpace> space,
                                                   std::shared_ptr<const statespaces::FoldValidity> validity, double step)
    : ob::Planner(si, inner ? inner->getName() + "+Carpenter" : std::string("+Carpenter")),
      inner_(std::move(inner)),
      inner_time_(inner_time),
      step_(step),
      pattern_(&pattern),
      space_(std::move(space)),
      validity_(std::move(validity)) {
  if (!inner_ || !validity_) throw std::invalid_argument("CarpenterFallbackPlanner: no inner planner or no validity");
  if (!(inner_time_ > 0.0) || !(step_ > 0.0))
    throw std::invalid_argument("CarpenterFallbackPlanner: the inner planner's time and the step must be positive");
  specs_ = inner_->getSpecs();
}

std::shared_ptr<CarpenterFallbackPlanner> with_carpenter_fallback(const PlanSetup& setup, const geometry::CreasePattern& pattern,
                                                                  ob::PlannerPtr inner, double time, double step) {
  auto space = std::dynamic_pointer_cast<const statespaces::SingleVertexStateSpace>(setup.space);
  if (!space) throw std::invalid_argument("the Carpenter fallback needs the single-vertex space (it is Carpenter's rule on the sphere)");
  return std::make_shared<CarpenterFallbackPlanner>(setup.si, std::move(inner), kSamplerShare * time, pattern, std::move(space),
                                                    setup.validity, step);
}

void CarpenterFallbackPlanner::clear() {
  ob::Planner::clear();
  inner_->clear();
  used_fallback_ = false;
  fallback_message_.clear();
}

void CarpenterFallbackPlanner::setup() {
  ob::Planner::setup();
  inner_->setup();
}

void CarpenterFallbackPlanner::setProblemDefinition(const ob::ProblemDefinitionPtr& pdef) {
  ob::Planner::setProblemDefinition(pdef);
  inner_->setProblemDefinition(pdef);
}

void CarpenterFallbackPlanner::getPlannerData(ob::PlannerData& data) const { inner_->getPlannerData(data); }

ob::PlannerStatus CarpenterFallbackPlanner::solve(const ob::PlannerTerminationCondition& ptc) {
  checkValidity();
  used_fallback_ = false;
  fallback_message_.clear();
  ob::PlannerStatus status;
  {
    // An optimising planner (one that reports its best cost: RRT*, PRM*, …) that has its first
    // path within its share keeps improving it until the caller's condition: the share bounds the
    // search for a first path, not the optimisation. Any other planner stops at its share, its
    // loops that ignore the termination condition too.
    ob::Planner::PlannerProgressProperty best;
    for (const auto& [name, property] : inner_->getPlannerProgressProperties())
      if (name.rfind("best cost", 0) == 0) best = property;
    std::optional<statespaces::FoldValidity::TimeLimit> limit;
    ob::PlannerTerminationCondition share = ob::timedPlannerTerminationCondition(inner_time_);
    if (best) {
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(inner_time_);
      const ob::ProblemDefinitionPtr pdef = pdef_;
      share = ob::PlannerTerminationCondition([deadline, best, pdef] {
        if (std::chrono::steady_clock::now() < deadline || pdef->hasExactSolution()) return false;
        return !std::isfinite(std::strtod(best().c_str(), nullptr));
      });
    } else {
      limit.emplace(*validity_, inner_time_);
    }
    status = inner_->solve(ob::plannerOrTerminationCondition(ptc, share));
  }
  if (status == ob::PlannerStatus::EXACT_SOLUTION || ptc()) return status;
  if (status == ob::PlannerStatus::INVALID_START || status == ob::PlannerStatus::INVALID_GOAL ||
      status == ob::PlannerStatus::UNRECOGNIZED_GOAL_TYPE)
    return status;
  // The Carpenter path is no search: it ends on its own, and its checks must not expire midway.
  const statespaces::FoldValidity::TimeLimit none(*validity_, std::chrono::steady_clock::time_point::max());
  if (!fallback(ptc)) return ptc() ? ob::PlannerStatus::TIMEOUT : ob::PlannerStatus::ABORT;
  used_fallback_ = true;
  return ob::PlannerStatus::EXACT_SOLUTION;
}

bool CarpenterFallbackPlanner::fallback(const ob::PlannerTerminationCondition& ptc) {
  const auto* goal = dynamic_cast<const ob::GoalState*>(pdef_->getGoal().get());
  if (!goal || pdef_->getStartStateCount() == 0) {
    fallback_message_ = "the fallback needs one start state and a goal state";
    return false;
  }
  const ob::State* start = pdef_->getStartState(0);
  const std::vector<FoldState> frames =
      carpenter_path(*pattern_, space_->to_fold_state(start), space_->to_fold_state(goal->getState()), step_, &fallback_message_, [&ptc] { return ptc(); });
  if (frames.empty()) return false;
  // Frames the closed form cannot hold (flat, where the passive axes may line up) are skipped.
  // The frames are one motion: checked in order by one collision world (stacked facets are
  // judged against the frame before), each state once; a gap the skipping left wider than the
  // motion validator's jump limit goes through the motion validator, which bisects it.
  const double max_jump = 2.5 * step_;
  auto path = std::make_shared<og::PathGeometric>(si_, start);
  auto motion = std::make_unique<statespaces::FoldValidity::Motion>(*validity_);
  FoldState last = space_->to_fold_state(start);
  bool ok = motion->valid_first(last);
  ob::State* next = si_->allocState();
  const auto take = [&](const ob::State* s) {
    const FoldState f = space_->to_fold_state(s);
    if ((f.angles - last.angles).cwiseAbs().maxCoeff() <= max_jump) {
      ok = motion->valid_next(f);
    } else {
      ok = si_->checkMotion(path->getStates().back(), s);
      motion = std::make_unique<statespaces::FoldValidity::Motion>(*validity_);
      ok = ok && motion->valid_first(f);
    }
    last = f;
  };
  for (std::size_t i = 1; i + 1 < frames.size() && ok; ++i) {
    if (ptc()) {
      si_->freeState(next);
      fallback_message_ = "the time ran out while the Carpenter path was checked";
      return false;
    }
    if (!space_->from_fold_state(frames[i], next)) continue;
    take(next);
    if (ok) path->append(next);
  }
  si_->freeState(next);
  if (ok) take(goal->getState());
  if (!ok) {
    fallback_message_ = "the Carpenter path leaves the space (a bound, a jump or a collision on the way)";
    return false;
  }
  path->append(goal->getState());
  pdef_->addSolutionPath(path, false, 0.0, getName());
  return true;
}

}  // namespace foldkit::planners
