#pragma once
/// @file
/// What one kind of state space brings to a plan: how far its start must leave a singular state,
/// how it is built, how a fold state enters it, how its paths are densified and which way through
/// flat applies when its planner finds nothing. One implementation per kind, each in its own file
/// under planners/src/spaces/, registered in the table of plan_space.cpp (docs/ARCHITECTURE.md,
/// "One place to extend").
#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <ompl/base/State.h>
#include <ompl/geometric/PathGeometric.h>

#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/planners/plan.hpp"
#include "foldkit/statespaces/angle_bounds.hpp"

namespace foldkit::planners {

struct PlanSetup;

/// The way through flat a plan takes when its planner finds no path (PlanOptions::fallback).
enum class Fallback {
  None,       ///< none: the planner has all of the time
  Carpenter,  ///< Carpenter's rule on the sphere, start → flat → goal (CarpenterFallbackPlanner)
  ViaFlat,    ///< from a folded start, two plans from flat: to the start reversed, then to the goal
};

/// One kind of state space in plan() and `foldkit bench`. make_plan_setup() asks lead_in_rank(),
/// leaves a start below that rank along geometry::lead_in (the one lead-in all spaces share), then
/// build()s the space from the end of that way out; the rest of the pipeline reaches the space
/// only through these members. Implementations hold what they built (not thread-safe while
/// building; const afterwards).
class PlanSpace {
 public:
  /// A space named `name` (the name make_plan_space()'s table gives its kind; a string literal).
  explicit PlanSpace(const char* name) : name_(name) {}
  virtual ~PlanSpace() = default;

  /// The space's name in results and messages: "single-vertex", "driving", "projected", "atlas",
  /// "tangent-bundle" (to_string() of its kind) or "joint" (the box of a pattern without loops).
  const char* name() const { return name_; }

  /// The rank of the closure Jacobian the planner's first state must have; a start below it is
  /// left along geometry::lead_in to that rank first. May build what it needs to tell (the
  /// single-vertex space asks its closed form).
  /// @param setup   the checked problem (setup.pattern, setup.start, setup.goal, setup.system)
  /// @param options the plan's settings
  /// @param bounds  the per-joint angle bounds of the plan (radians)
  /// @return 0 when the start needs no way out
  virtual Eigen::Index lead_in_rank(const PlanSetup& setup, const PlanOptions& options,
                                    const statespaces::AngleBounds& bounds) = 0;

  /// Builds setup.space, setup.si (motion validator set; make_plan_setup() adds the validity
  /// checker) and setup.reader, for a plan from setup.prefix.back() to setup.goal.
  /// @throws PlanInputError when an end is a singular state of the space; std::invalid_argument
  ///         when the space cannot be built on the pattern
  virtual void build(PlanSetup& setup, const PlanOptions& options, const statespaces::AngleBounds& bounds) = 0;

  /// Writes a closed fold state into a state of the built space.
  /// @return false when the space cannot hold it (a singular state of its closed form or chart)
  virtual bool write(const geometry::FoldState& state, ompl::base::State* out) const = 0;

  /// Marks the planner's start and goal states in the space (the Atlas charts); nothing by default.
  virtual void anchor(ompl::base::State* start, ompl::base::State* goal) const;

  /// Receives a path's fold states one at a time, in the path's order.
  using StateSink = std::function<void(const geometry::FoldState&)>;
  /// Asked between the expensive steps of path_states(); true: the states are no longer wanted.
  using Stop = std::function<bool()>;

  /// A solution path's states as fold states, densified along the space's own motion so that no
  /// crease moves more than `step` (radians) between neighbours where the space can tell; by
  /// default OMPL's path.interpolate() (the constrained spaces follow their manifold's geodesic).
  /// `sink`, when set, gets each of the returned states in order, the driving and single-vertex
  /// spaces' as soon as it is computed (the plan's replay starts on them), the others' at the end.
  /// `stop`, when set, is asked between the continuation's steps; once it returns true (and it must
  /// stay true), the driving space returns what it has at its next step (the states then end
  /// short of the path's end; the caller drops them). With a `stop` the driving space also does
  /// not halve a segment its continuation falls short of (the halving borrows the space's shared
  /// solvers, which a planner on another thread may be using): it returns no states at all, and
  /// its sink gets none after those of the segments before (only then is the result empty).
  virtual std::vector<geometry::FoldState> path_states(const PlanSetup& setup, ompl::geometric::PathGeometric path, double step,
                                                       const StateSink& sink, const Stop& stop = {}) const;

  /// The way through flat that applies to this space (PlanOptions::fallback); None by default.
  virtual Fallback fallback() const;

  /// Whether the space's motion between two states is the continuation along its manifold over
  /// the straight segment between their coordinates, whatever states lie between: then a path as
  /// short as the distance between its ends is that one motion, and plan() replaces it by its
  /// first and last state (the driving space; false by default).
  virtual bool straight_paths() const;

 private:
  const char* name_;
};

/// A new, unbuilt space of `kind` (not SpaceKind::Auto): the one place that maps a kind to its
/// implementation.
/// @throws std::invalid_argument for SpaceKind::Auto
std::shared_ptr<PlanSpace> make_plan_space(SpaceKind kind);

/// A new, unbuilt joint-angle box: the space of a pattern without closed loops, where every state
/// is closed (`foldkit bench` only; plan() refuses such patterns).
std::shared_ptr<PlanSpace> make_joint_plan_space();

}  // namespace foldkit::planners
