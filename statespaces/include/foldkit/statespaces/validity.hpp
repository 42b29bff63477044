#pragma once
#include <functional>
#include <memory>
#include <optional>

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
// `closure_tolerance` (the simulator's, 1e-3 rad), and — when a collision world is given — no
// crossing facets, judged by the simulator's own CollisionWorld (same pairs, same tolerance).
struct FoldValidity {
  const geometry::CreasePattern* pattern = nullptr;
  AngleBounds bounds;
  double closure_tolerance = 1e-3;
  std::shared_ptr<simulation::CollisionWorld> collisions;  // null: collisions are not checked

  FoldValidity(const geometry::CreasePattern& pattern, AngleBounds bounds, bool check_collisions,
               double closure_tolerance = 1e-3, const simulation::CollisionOptions& collision = {});
  // An isolated state (the collision world's memory is reset first).
  bool valid(const geometry::FoldState& state) const;
  // The next state along a motion (stacked facets are judged against the previous call).
  bool valid_next(const geometry::FoldState& state) const;

 private:
  std::shared_ptr<geometry::ClosureSystem> system_;
  geometry::KinematicTree tree_;
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
