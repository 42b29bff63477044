#pragma once
/// @file
/// The OMPL state space of a multi-vertex pattern in driving-crease coordinates: as many
/// coordinates as the pattern has degrees of freedom, every other crease solved by closure
/// (docs/PLANNING.md).
#include <memory>
#include <mutex>
#include <vector>

#include <ompl/base/StateSampler.h>
#include <ompl/base/StateSpace.h>

#include "foldkit/geometry/driving_chart.hpp"
#include "foldkit/statespaces/angle_bounds.hpp"
#include "foldkit/statespaces/closed_angles_space.hpp"
#include "foldkit/statespaces/state_reader.hpp"

namespace foldkit::statespaces {

/// A space whose coordinates are the driving creases of a geometry::DrivingChart. A state holds
/// the full angle vector (closed to the solver's tolerance) and whether it closes at all; the
/// passive creases of a new state are found by continuation (geometry::PassiveSolver::follow)
/// from a known state: the state it is interpolated from, or, for a sampled one, the nearest
/// *anchor* (closed states given to the space: the planner's start and goal). A state whose
/// driving angles cannot be reached that way is marked not `closed`; the validity checker
/// rejects it, it is never accepted silently.
///
/// Distance: Euclidean over the driving angles. Interpolation: continuation along the straight
/// line in driving coordinates from the from-state; a planner's successive calls along one line
/// (the motion validator's, PathGeometric::interpolate's) continue from the last point computed,
/// so checking a motion costs one continuation, not one per check. Safe for several threads
/// (each takes a solver of its own from a pool).
class DrivingStateSpace : public ClosedAnglesSpace {
 public:
  /// A state of the space: the full angle vector and whether it closes (false when the
  /// continuation did not reach the driving angles).
  using StateType = ClosedAnglesState;

  /// The space of `system` in `chart`'s coordinates.
  /// @param system          the closure equations (kept; must outlive the space)
  /// @param chart           the driving creases (geometry::choose_driving_chart)
  /// @param bounds          per-joint angle bounds of a valid state
  /// @param driving_lower   sampling bounds of the driving creases (chart order), radians: within
  ///                        `bounds`, and on one side of flat for each, since flat is singular
  /// @param driving_upper   as driving_lower, the upper bounds
  /// @param options         the passive solver's settings
  /// @throws ompl::Exception when the bounds do not match the pattern or the chart, or the chart
  ///         has no driving crease
  DrivingStateSpace(std::shared_ptr<const geometry::ClosureSystem> system, geometry::DrivingChart chart, AngleBounds bounds,
                    Eigen::VectorXd driving_lower, Eigen::VectorXd driving_upper, geometry::PassiveSolverOptions options = {});
  ~DrivingStateSpace() override;  ///< Frees the pooled solvers.

  /// The chart whose driving creases are the coordinates.
  const geometry::DrivingChart& chart() const { return chart_; }
  /// The closure equations.
  const geometry::ClosureSystem& system() const { return *system_; }
  /// Sampling bounds of the driving creases, chart order, radians.
  const Eigen::VectorXd& driving_lower() const { return driving_lower_; }
  /// See driving_lower().
  const Eigen::VectorXd& driving_upper() const { return driving_upper_; }

  /// Makes a share of the uniform samples fall in a smaller box of driving angles (clamped into
  /// the driving bounds), e.g. around the plan's start and goal: uniform samples of a box of many
  /// driving creases mostly lie where no continuation from an anchor reaches, while the rest of
  /// the samples still cover the whole box (the sampler stays probabilistically complete). Not
  /// thread-safe: set it before planning.
  /// @param lower  lower corner, chart order, radians
  /// @param upper  upper corner, chart order, radians
  /// @param share  the probability that a uniform sample is drawn in the box, in [0, 1]
  /// @throws std::invalid_argument for corners of the wrong size or out of order, or a share
  ///         outside [0, 1]
  void set_focus(const Eigen::VectorXd& lower, const Eigen::VectorXd& upper, double share);
  /// The focus box's lower corner (the driving bounds' when none was set).
  const Eigen::VectorXd& focus_lower() const { return focus_lower_; }
  /// The focus box's upper corner (the driving bounds' when none was set).
  const Eigen::VectorXd& focus_upper() const { return focus_upper_; }
  /// The probability that a uniform sample is drawn in the focus box (0 when none was set).
  double focus_share() const { return focus_share_; }

  /// Adds a closed state that sampled states are continued from (the nearest one, by driving
  /// distance). Not thread-safe: add anchors before planning.
  /// @return false (nothing added) when `state` does not close in this chart
  bool add_anchor(const geometry::FoldState& state);
  /// The anchors added so far.
  const std::vector<geometry::FoldState>& anchors() const { return anchors_; }

  /// Sets `state` from a full angle vector, its passives corrected by Newton.
  /// @return false when `angles` has the wrong size, does not close in this chart, or the
  ///         correction moves a crease more than `tolerance` (radians)
  bool from_fold_state(const geometry::FoldState& angles, ompl::base::State* state, double tolerance = 1e-6) const;
  /// The fold angles of `state` (one per joint, radians), closed or not.
  geometry::FoldState to_fold_state(const ompl::base::State* state) const;
  /// Sets `state`'s driving angles to `driving` (chart order) and solves its passives by
  /// continuation from `from` (closed), or from the nearest anchor when `from` is null; marks it
  /// not closed when that fails.
  void solve(const Eigen::VectorXd& driving, const geometry::FoldState* from, ompl::base::State* state) const;
  /// The driving angles of `state`, chart order.
  Eigen::VectorXd driving_of(const ompl::base::State* state) const;

  /// The number of driving creases (the degrees of freedom).
  unsigned int getDimension() const override;
  /// Length of the diagonal of the driving bounds.
  double getMaximumExtent() const override;
  /// Volume of the driving bounds.
  double getMeasure() const override;
  /// Clamps the driving angles into their bounds and, when that changes them or the state is
  /// not closed, solves the passives again (a closed state within bounds is left as it is).
  void enforceBounds(ompl::base::State* state) const override;
  /// Whether the state is closed, every angle within its bounds and every driving angle within
  /// the driving bounds (to 1e-12 rad).
  bool satisfiesBounds(const ompl::base::State* state) const override;
  /// Euclidean distance over the driving angles, radians.
  double distance(const ompl::base::State* state1, const ompl::base::State* state2) const override;
  /// Whether both are closed or both not, with every angle within 1e-12 rad.
  bool equalStates(const ompl::base::State* state1, const ompl::base::State* state2) const override;
  /// The state a fraction `t` of the way from `from` to `to` in driving coordinates, its
  /// passives continued from `from` (from the nearest anchor when `from` is not closed); `to`
  /// itself at t ≥ 1. `state` may alias either argument.
  void interpolate(const ompl::base::State* from, const ompl::base::State* to, double t,
                   ompl::base::State* state) const override;
  /// A DrivingSampler.
  ompl::base::StateSamplerPtr allocDefaultStateSampler() const override;
  /// The driving angles, and "(not closed)" for a state that is not.
  void printState(const ompl::base::State* state, std::ostream& out) const override;
  /// Registers the default projection (for planners that grid the space): the first two driving
  /// angles, cells of 0.1 rad.
  void registerProjections() override;

 protected:
  /// A StateType, not closed until it is set.
  ClosedAnglesState* new_state() const override;

 private:
  struct Worker;  // a solver and its interpolation memory, one per thread at a time
  class Lease;
  std::unique_ptr<Worker> take() const;
  void give(std::unique_ptr<Worker> worker) const;
  const geometry::FoldState* nearest_anchor(const Eigen::VectorXd& driving) const;
  void set_open(StateType* state, const Eigen::VectorXd& driving) const;

  std::shared_ptr<const geometry::ClosureSystem> system_;
  geometry::DrivingChart chart_;
  Eigen::VectorXd driving_lower_, driving_upper_, focus_lower_, focus_upper_;
  double focus_share_ = 0.0;
  geometry::PassiveSolverOptions options_;
  std::vector<geometry::FoldState> anchors_;
  std::vector<Eigen::VectorXd> anchor_driving_;
  mutable std::mutex mutex_;  // guards pool_
  mutable std::vector<std::unique_ptr<Worker>> pool_;
};

/// Uniform driving angles within the driving bounds (within the focus box, with the space's
/// focus share: DrivingStateSpace::set_focus), the passives continued from the nearest anchor;
/// redrawn (up to kMaxTries) until the state closes within the bounds. Near and Gaussian
/// samples are continued from the state they are drawn about.
class DrivingSampler : public ompl::base::StateSampler {
 public:
  /// A sampler of `space`, which must outlive it.
  explicit DrivingSampler(const DrivingStateSpace* space);
  /// A uniform state; not closed when kMaxTries draws all fail.
  void sampleUniform(ompl::base::State* state) override;
  /// Driving angles within `distance` (per angle) of `near`'s, clamped to the bounds, continued
  /// from `near`; a copy of `near` when kMaxTries draws fail.
  void sampleUniformNear(ompl::base::State* state, const ompl::base::State* near, double distance) override;
  /// Driving angles drawn from normal distributions about `mean`'s, clamped, continued from
  /// `mean`; a copy of `mean` when kMaxTries draws fail.
  void sampleGaussian(ompl::base::State* state, const ompl::base::State* mean, double stdDev) override;
  /// Draws per sample before giving up (each costs a continuation).
  static constexpr int kMaxTries = 20;

 private:
  template <typename Draw>
  bool draw_about(ompl::base::State* state, const ompl::base::State* about, Draw draw);
  const DrivingStateSpace* space_;
};

/// The reader of DrivingStateSpace states: false for a state that is not closed.
StateReader driving_reader(std::shared_ptr<const DrivingStateSpace> space);

}  // namespace foldkit::statespaces
