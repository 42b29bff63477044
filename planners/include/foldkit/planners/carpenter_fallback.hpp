#pragma once
/// @file
/// A complete planner for single vertices: a sampling planner first, then, when it finds no plan
/// in its share of the time, the path of Carpenter's rule on the sphere (start → flat → goal).
/// Every closed, non-crossing state of a single vertex is connected to flat by an expansive
/// motion (Streinu & Whiteley 2004), so the second stage reaches goals that sampling misses
/// (issue 16, item 4; docs/PLANNING.md).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <ompl/base/Planner.h>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/planners/plan_setup.hpp"
#include "foldkit/statespaces/single_vertex_space.hpp"
#include "foldkit/statespaces/validity.hpp"

namespace foldkit::planners {

/// The frames of Carpenter's rule on the sphere from `start` to flat and on to `goal`
/// (folding::flatten_single_vertex of each end; the goal's frames reversed), at most `step`
/// apart per crease; flat itself is one frame. Empty, with the reason in `why`, when either end
/// cannot be flattened (a crossing or singular state, a sector ≥ 180°, the step limit, `stop`).
/// @param pattern  a single interior vertex carrying every joint
/// @param start    closed, non-crossing; one angle per joint, radians
/// @param goal     closed, non-crossing; one angle per joint, radians
/// @param step     largest change of any fold angle between frames, radians (positive)
/// @param why      set to the reason when the result is empty; may be null
/// @param stop     asked before every step of Carpenter's rule (may be empty): true gives up
///                 (CarpenterSphericalOptions::stop), e.g. when a planner's time is up
std::vector<geometry::FoldState> carpenter_path(const geometry::CreasePattern& pattern, const geometry::FoldState& start,
                                                const geometry::FoldState& goal, double step, std::string* why,
                                                const std::function<bool()>& stop = {});

/// The share of a time limit that plan() and `foldkit bench` give the sampling planner before the
/// fallback: a quarter, so that the fallback (≈ 0.6 s at degree 32: LPs and checks) mostly fits
/// into a limit of 1 s; sampling that succeeds at all mostly does so in milliseconds. The
/// fallback itself stops when the caller's condition fires (the whole limit), so a limit too
/// short for it ends in TIMEOUT rather than running over.
constexpr double kSamplerShare = 0.25;

/// A sampling planner with the spherical Carpenter path as its fallback, on the single-vertex
/// space. solve() gives the inner planner `inner_time` seconds (or less, when the caller's
/// condition fires first) to find a path; an optimising inner planner (one that reports OMPL's
/// progress property "best cost": RRT*, PRM*, …) that has one by then goes on improving it until
/// the caller's condition. When it ends without an exact solution and the caller's condition
/// has not fired, the fallback runs until it ends or the caller's condition fires (then
/// TIMEOUT: the whole search keeps to the caller's limit, to one Carpenter step or one state
/// check). Its path is written into the space and checked in order, as one
/// motion, by `validity` (bounds, closure, crossing facets); a gap larger than the motion
/// validator's jump limit (a frame the space cannot hold was skipped) goes through the
/// SpaceInformation's motion validator instead. The path is added as the exact solution when all
/// pass. The planner's name is the inner planner's followed by "+Carpenter".
class CarpenterFallbackPlanner : public ompl::base::Planner {
 public:
  /// Wraps `inner` (made for `si`) for the single-vertex space `space` of `pattern`.
  /// @param si          the space information of `space`, validity checker and motion validator set
  /// @param inner       the sampling planner, made for `si`
  /// @param inner_time  seconds the inner planner may run before the fallback (positive)
  /// @param pattern     the single-vertex pattern (must outlive the planner)
  /// @param space       the single-vertex space the states belong to
  /// @param validity    what a valid state is (the one behind si's validity checker)
  /// @param step        largest change of a fold angle between the fallback's states, radians
  ///                    (positive; at most half the motion validator's jump limit)
  /// @throws std::invalid_argument when inner or validity is null, or inner_time or step is not
  ///         positive
  CarpenterFallbackPlanner(const ompl::base::SpaceInformationPtr& si, ompl::base::PlannerPtr inner, double inner_time,
                           const geometry::CreasePattern& pattern,
                           std::shared_ptr<const statespaces::SingleVertexStateSpace> space,
                           std::shared_ptr<const statespaces::FoldValidity> validity, double step = 0.02);
  /// Runs the inner planner, then the fallback (see the class comment).
  /// @return the inner planner's EXACT_SOLUTION; else EXACT_SOLUTION from the fallback; else the
  ///         inner planner's status when the caller's condition fired before the fallback,
  ///         TIMEOUT when it fired during the fallback, or ABORT (the fallback failed: the
  ///         reason is in fallback_message())
  ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition& ptc) override;
  /// Clears the inner planner and the fallback's outcome.
  void clear() override;
  /// Sets up the inner planner too.
  void setup() override;
  /// Gives the problem to the inner planner too (they share the problem definition).
  void setProblemDefinition(const ompl::base::ProblemDefinitionPtr& pdef) override;
  /// The inner planner's data (the fallback adds no graph).
  void getPlannerData(ompl::base::PlannerData& data) const override;
  /// Whether the last solve() took its path from the fallback.
  bool used_fallback() const { return used_fallback_; }
  /// Why the last fallback did not give a path (empty when it was not tried or succeeded).
  const std::string& fallback_message() const { return fallback_message_; }
  /// The inner planner.
  const ompl::base::PlannerPtr& inner() const { return inner_; }

 private:
  bool fallback(const ompl::base::PlannerTerminationCondition& ptc);

  ompl::base::PlannerPtr inner_;
  double inner_time_, step_;
  const geometry::CreasePattern* pattern_;
  std::shared_ptr<const statespaces::SingleVertexStateSpace> space_;
  std::shared_ptr<const statespaces::FoldValidity> validity_;
  bool used_fallback_ = false;
  std::string fallback_message_;
};

/// `inner` (made for setup.si) with the fallback on the single-vertex space of `setup`, given
/// kSamplerShare of `time`: what plan() does on a single vertex, and `foldkit bench`'s
/// "X+Carpenter" entries.
/// @param setup    a plan set-up whose space is the single-vertex one
/// @param pattern  its pattern (must outlive the planner)
/// @param inner    the sampling planner
/// @param time     the whole time limit, seconds (positive)
/// @param step     largest change of a fold angle between the fallback's states, radians
/// @throws std::invalid_argument when `setup` has no single-vertex space, or as the constructor
std::shared_ptr<CarpenterFallbackPlanner> with_carpenter_fallback(const PlanSetup& setup, const geometry::CreasePattern& pattern,
                                                                  ompl::base::PlannerPtr inner, double time, double step);

}  // namespace foldkit::planners
