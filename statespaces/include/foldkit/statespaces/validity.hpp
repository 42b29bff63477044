#pragma once
/// @file
/// What a valid fold state and a valid motion are, for OMPL's planners: angle bounds, closed
/// loops, and no crossing facets.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <limits>
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

#include <ompl/base/MotionValidator.h>
#include <ompl/base/StateValidityChecker.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/simulation/collision_world.hpp"
#include "foldkit/statespaces/angle_bounds.hpp"
#include "foldkit/statespaces/state_reader.hpp"

namespace foldkit::statespaces {

/// What a valid state is: finite angles, every angle within its bounds (to 1e-9 rad), every loop
/// closed within `closure_tolerance` (the simulator's, 1e-3 rad), and — when collisions are
/// checked — no crossing facets, judged by the simulator's own CollisionWorld (same pairs, same
/// tolerance).
///
/// Safe to use from several threads at once (OMPL's PRM and PRM* check states in parallel): a
/// collision world remembers the previous state of a motion, so each check or motion takes a world
/// of its own from a pool (one per thread at most, built on first need) and gives it back after.
class FoldValidity {
 public:
  /// The validity of `pattern`'s states, which keeps a reference to `pattern`: the pattern must
  /// outlive it. Collision worlds are built on first need, so invalid `collision` options throw
  /// (std::invalid_argument) from the first check, not here.
  /// @param pattern            the pattern
  /// @param bounds             per-joint angle bounds
  /// @param check_collisions   whether crossing facets make a state invalid
  /// @param closure_tolerance  largest loop error accepted, radians (geometry::ClosureSystem::max_error)
  /// @param collision          options of the collision worlds
  FoldValidity(const geometry::CreasePattern& pattern, AngleBounds bounds, bool check_collisions,
               double closure_tolerance = 1e-3, const simulation::CollisionOptions& collision = {});
  ~FoldValidity();  ///< Frees the pooled collision worlds; no Motion may outlive it.
  FoldValidity(const FoldValidity&) = delete;             ///< Not copyable.
  FoldValidity& operator=(const FoldValidity&) = delete;  ///< Not copyable.

  /// Whether an isolated state (one angle per joint, radians) is valid.
  bool valid(const geometry::FoldState& state) const;

  /// The states of one motion, checked in order by one thread: stacked facets are judged against
  /// the motion's previous state. Holds a collision world until it is destroyed.
  class Motion {
   public:
    /// Takes a collision world from `validity`'s pool (none when collisions are not checked).
    explicit Motion(const FoldValidity& validity);
    ~Motion();  ///< Gives the collision world back to the pool.
    Motion(const Motion&) = delete;             ///< Not copyable.
    Motion& operator=(const Motion&) = delete;  ///< Not copyable.
    /// Whether the motion's first state is valid (its collision memory is cleared first).
    bool valid_first(const geometry::FoldState& state);
    /// Whether the next state along the motion is valid.
    bool valid_next(const geometry::FoldState& state);

   private:
    const FoldValidity& validity_;
    std::unique_ptr<simulation::CollisionWorld> world_;  // null: collisions are not checked
  };

  /// While it lives, FoldMotionValidator calls every motion invalid once its deadline has
  /// passed; destroying it restores the limit it replaced. States keep their verdicts
  /// (FoldValidityChecker, valid() and Motion are not affected): a planner may recheck a state it
  /// holds, and OMPL's SPARStwo asserts that the answer has not changed.
  class TimeLimit {
   public:
    /// Sets `validity`'s deadline, remembering the one it replaces.
    TimeLimit(const FoldValidity& validity, std::chrono::steady_clock::time_point deadline);
    /// The same with the deadline `seconds` from now.
    TimeLimit(const FoldValidity& validity, double seconds);
    ~TimeLimit();  ///< Restores the deadline replaced.
    TimeLimit(const TimeLimit&) = delete;             ///< Not copyable.
    TimeLimit& operator=(const TimeLimit&) = delete;  ///< Not copyable.

   private:
    const FoldValidity& validity_;
    std::int64_t previous_;
  };
  /// Whether a TimeLimit's deadline has passed. OMPL's planners stop at their termination
  /// condition, but some loops never consult it (RRTConnect connects to the other tree until it
  /// is trapped: with a tiny `range`, for hours); once every motion is invalid they end at once.
  bool expired() const;

  /// The pattern whose states are checked.
  const geometry::CreasePattern& pattern() const { return *pattern_; }
  /// The per-joint angle bounds.
  const AngleBounds& bounds() const { return bounds_; }
  /// Largest loop error accepted, radians.
  double closure_tolerance() const { return closure_tolerance_; }
  /// Whether crossing facets make a state invalid.
  bool checks_collisions() const { return check_collisions_; }
  /// Collision worlds built so far (at most the number of threads that checked at once; tests).
  std::size_t worlds_built() const;

 private:
  bool valid_with(const geometry::FoldState& state, simulation::CollisionWorld* world) const;
  std::unique_ptr<simulation::CollisionWorld> take() const;
  void give(std::unique_ptr<simulation::CollisionWorld> world) const;

  const geometry::CreasePattern* pattern_;
  AngleBounds bounds_;
  double closure_tolerance_;
  bool check_collisions_;
  simulation::CollisionOptions collision_;
  geometry::ClosureSystem system_;
  geometry::KinematicTree tree_;
  mutable std::atomic<std::int64_t> deadline_{std::numeric_limits<std::int64_t>::max()};  // steady_clock ticks
  mutable std::mutex mutex_;  // guards pool_ and built_
  mutable std::vector<std::unique_ptr<simulation::CollisionWorld>> pool_;
  mutable std::size_t built_ = 0;
};

/// OMPL's state validity checker on a FoldValidity: a state is valid when `reader` gets fold
/// angles from it and they are valid.
class FoldValidityChecker : public ompl::base::StateValidityChecker {
 public:
  /// A checker for the states of `si`'s space, read by `reader`.
  FoldValidityChecker(const ompl::base::SpaceInformationPtr& si, std::shared_ptr<const FoldValidity> validity,
                      StateReader reader);
  /// Whether `state` holds fold angles and they pass FoldValidity::valid.
  bool isValid(const ompl::base::State* state) const override;

 private:
  std::shared_ptr<const FoldValidity> validity_;
  StateReader reader_;
};

/// Checks a motion by the space's interpolation at `resolution` (radians of the largest joint
/// change per check). Between two checks no joint may move more than `max_jump`: a larger change
/// is bisected (up to 12 times) and, if it does not shrink, is a jump — a branch switch away from
/// where the roots meet, or a passive angle wrapping round ±π — and the motion is invalid. The
/// states of a motion are checked in order, the collision world remembering stacked facets.
class FoldMotionValidator : public ompl::base::MotionValidator {
 public:
  /// A validator for motions in `si`'s space, whose states `reader` reads.
  /// @param si          the space information (its space interpolates)
  /// @param validity    what a valid state is
  /// @param reader      reads fold angles from a state of the space
  /// @param resolution  largest joint change between two checked states, radians
  /// @param max_jump    largest joint change allowed between two checked states before
  ///                    bisection, radians
  FoldMotionValidator(const ompl::base::SpaceInformationPtr& si, std::shared_ptr<const FoldValidity> validity,
                      StateReader reader, double resolution = 0.02, double max_jump = 0.05);
  /// Whether the motion from `s1` to `s2` is valid, `s1` included.
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2) const override;
  /// As the other overload; on failure `lastValid` gets the fraction of the motion last found
  /// valid and, when its state is not null, that state.
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2,
                   std::pair<ompl::base::State*, double>& lastValid) const override;

  /// Largest joint change between two checked states, radians.
  double resolution() const { return resolution_; }

 private:
  bool check(const ompl::base::State* s1, const ompl::base::State* s2, std::pair<ompl::base::State*, double>* lastValid) const;

  std::shared_ptr<const FoldValidity> validity_;
  StateReader reader_;
  double resolution_, max_jump_;
};

}  // namespace foldkit::statespaces
