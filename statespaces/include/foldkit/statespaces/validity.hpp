#pragma once
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

#include <ompl/base/MotionValidator.h>
#include <ompl/base/StateValidityChecker.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/simulation/collision_world.hpp"
#include "foldkit/statespaces/single_vertex_space.hpp"

namespace foldkit::statespaces {

// Reads the fold angles of an OMPL state of some space; false when the state holds none (a
// single-vertex state without a root).
using StateReader = std::function<bool(const ompl::base::State*, geometry::FoldState&)>;
StateReader single_vertex_reader(std::shared_ptr<const SingleVertexStateSpace> space);
StateReader constrained_reader();

// What a valid state is: every angle within its bounds, every loop closed within
// `closure_tolerance` (the simulator's, 1e-3 rad), and — when collisions are checked — no
// crossing facets, judged by the simulator's own CollisionWorld (same pairs, same tolerance).
//
// Safe to use from several threads at once (OMPL's PRM and PRM* check states in parallel): a
// collision world remembers the previous state of a motion, so each check or motion takes a world
// of its own from a pool (one per thread at most, built on first need) and gives it back after.
class FoldValidity {
 public:
  FoldValidity(const geometry::CreasePattern& pattern, AngleBounds bounds, bool check_collisions,
               double closure_tolerance = 1e-3, const simulation::CollisionOptions& collision = {});
  ~FoldValidity();
  FoldValidity(const FoldValidity&) = delete;
  FoldValidity& operator=(const FoldValidity&) = delete;

  // An isolated state.
  bool valid(const geometry::FoldState& state) const;

  // The states of one motion, checked in order by one thread: stacked facets are judged against
  // the motion's previous state. Holds a collision world until it is destroyed.
  class Motion {
   public:
    explicit Motion(const FoldValidity& validity);
    ~Motion();
    Motion(const Motion&) = delete;
    Motion& operator=(const Motion&) = delete;
    // The motion's first state (its collision memory is cleared first).
    bool valid_first(const geometry::FoldState& state);
    // The next state along the motion.
    bool valid_next(const geometry::FoldState& state);

   private:
    const FoldValidity& validity_;
    std::unique_ptr<simulation::CollisionWorld> world_;  // null: collisions are not checked
  };

  const geometry::CreasePattern& pattern() const { return *pattern_; }
  const AngleBounds& bounds() const { return bounds_; }
  double closure_tolerance() const { return closure_tolerance_; }
  bool checks_collisions() const { return check_collisions_; }
  // Collision worlds built so far (at most the number of threads that checked at once; tests).
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
  mutable std::mutex mutex_;  // guards pool_ and built_
  mutable std::vector<std::unique_ptr<simulation::CollisionWorld>> pool_;
  mutable std::size_t built_ = 0;
};

class FoldValidityChecker : public ompl::base::StateValidityChecker {
 public:
  FoldValidityChecker(const ompl::base::SpaceInformationPtr& si, std::shared_ptr<const FoldValidity> validity,
                      StateReader reader);
  bool isValid(const ompl::base::State* state) const override;

 private:
  std::shared_ptr<const FoldValidity> validity_;
  StateReader reader_;
};

// Checks a motion by the space's interpolation at `resolution` (radians of the largest joint
// change per check). Between two checks no joint may move more than `max_jump`: a larger change
// is bisected (up to 12 times) and, if it does not shrink, is a jump — a branch switch away from
// where the roots meet, or a passive angle wrapping round ±π — and the motion is invalid. The
// states of a motion are checked in order, the collision world remembering stacked facets.
class FoldMotionValidator : public ompl::base::MotionValidator {
 public:
  FoldMotionValidator(const ompl::base::SpaceInformationPtr& si, std::shared_ptr<const FoldValidity> validity,
                      StateReader reader, double resolution = 0.02, double max_jump = 0.05);
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2) const override;
  bool checkMotion(const ompl::base::State* s1, const ompl::base::State* s2,
                   std::pair<ompl::base::State*, double>& lastValid) const override;

  double resolution() const { return resolution_; }

 private:
  bool check(const ompl::base::State* s1, const ompl::base::State* s2, std::pair<ompl::base::State*, double>* lastValid) const;

  std::shared_ptr<const FoldValidity> validity_;
  StateReader reader_;
  double resolution_, max_jump_;
};

}  // namespace foldkit::statespaces
