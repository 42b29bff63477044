#include "foldkit/statespaces/validity.hpp"

#include <cmath>
#include <utility>

#include <ompl/base/SpaceInformation.h>


namespace foldkit::statespaces {

namespace ob = ompl::base;

FoldValidity::FoldValidity(const geometry::CreasePattern& p, AngleBounds b, bool check_collisions,
                           double tolerance, const simulation::CollisionOptions& collision)
    : pattern_(&p),
      bounds_(std::move(b)),
      closure_tolerance_(tolerance),
      check_collisions_(check_collisions),
      collision_(collision),
      system_(p),
      tree_(geometry::make_tree(p)) {}

FoldValidity::~FoldValidity() = default;

std::unique_ptr<simulation::CollisionWorld> FoldValidity::take() const {
  if (!check_collisions_) return nullptr;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!pool_.empty()) {
      auto world = std::move(pool_.back());
      pool_.pop_back();
      return world;
    }
    ++built_;
  }
  // Built outside the lock: a large sheet's world takes a while, and other threads may go on.
  return std::make_unique<simulation::CollisionWorld>(*pattern_, collision_);
}

void FoldValidity::give(std::unique_ptr<simulation::CollisionWorld> world) const {
  if (!world) return;
  std::lock_guard<std::mutex> lock(mutex_);
  pool_.push_back(std::move(world));
}

std::size_t FoldValidity::worlds_built() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return built_;
}

bool FoldValidity::valid_with(const geometry::FoldState& state, simulation::CollisionWorld* world) const {
  if (!state.angles.allFinite() || !bounds_.contains(state, 1e-9)) return false;
  if (system_.max_error(state) > closure_tolerance_) return false;
  if (!world) return true;
  return world->check(geometry::facet_poses(*pattern_, tree_, state), state).empty();
}

bool FoldValidity::valid(const geometry::FoldState& state) const {
  Motion motion(*this);
  return motion.valid_first(state);
}

FoldValidity::Motion::Motion(const FoldValidity& validity) : validity_(validity), world_(validity.take()) {}

FoldValidity::Motion::~Motion() { validity_.give(std::move(world_)); }

bool FoldValidity::Motion::valid_first(const geometry::FoldState& state) {
  if (world_) world_->reset();
  return validity_.valid_with(state, world_.get());
}

bool FoldValidity::Motion::valid_next(const geometry::FoldState& state) {
  return validity_.valid_with(state, world_.get());
}

FoldValidityChecker::FoldValidityChecker(const ob::SpaceInformationPtr& si, std::shared_ptr<const FoldValidity> validity,
                                         StateReader reader)
    : ob::StateValidityChecker(si), validity_(std::move(validity)), reader_(std::move(reader)) {}

FoldValidity::TimeLimit::TimeLimit(const FoldValidity& validity, std::chrono::steady_clock::time_point deadline)
    : validity_(validity), previous_(validity.deadline_.exchange(deadline.time_since_epoch().count())) {}

FoldValidity::TimeLimit::TimeLimit(const FoldValidity& validity, double seconds)
    : TimeLimit(validity, std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                                  std::chrono::duration<double>(seconds))) {}

FoldValidity::TimeLimit::~TimeLimit() { validity_.deadline_.store(previous_); }

bool FoldValidity::expired() const {
  const std::int64_t deadline = deadline_.load(std::memory_order_relaxed);
  return deadline != std::numeric_limits<std::int64_t>::max() &&
         std::chrono::steady_clock::now().time_since_epoch().count() > deadline;
}

bool FoldValidityChecker::isValid(const ob::State* state) const {
  // Not ended by a TimeLimit: a state's verdict must not change while a planner holds it
  // (SPARStwo asserts that a state it found valid still is, and aborted when the limit passed in
  // between); the motions' verdicts end the loops the limit is for.
  thread_local geometry::FoldState f;
  return reader_(state, f) && validity_->valid(f);
}

FoldMotionValidator::FoldMotionValidator(const ob::SpaceInformationPtr& si, std::shared_ptr<const FoldValidity> validity,
                                         StateReader reader, double resolution, double max_jump)
    : ob::MotionValidator(si),
      validity_(std::move(validity)),
      reader_(std::move(reader)),
      resolution_(resolution),
      max_jump_(max_jump) {}

bool FoldMotionValidator::checkMotion(const ob::State* s1, const ob::State* s2) const { return check(s1, s2, nullptr); }

bool FoldMotionValidator::checkMotion(const ob::State* s1, const ob::State* s2,
                                      std::pair<ob::State*, double>& lastValid) const {
  return check(s1, s2, &lastValid);
}

bool FoldMotionValidator::check(const ob::State* s1, const ob::State* s2, std::pair<ob::State*, double>* lastValid) const {
  const ob::StateSpace& space = *si_->getStateSpace();
  geometry::FoldState f1, f2;
  double last_t = 0.0;
  auto fail = [&] {
    if (lastValid) {
      if (lastValid->first) space.interpolate(s1, s2, last_t, lastValid->first);
      lastValid->second = last_t;
    }
    ++invalid_;
    return false;
  };
  if (validity_->expired()) return fail();
  FoldValidity::Motion motion(*validity_);
  if (!reader_(s1, f1) || !motion.valid_first(f1)) return fail();
  if (!reader_(s2, f2)) return fail();
  ob::State* tmp = space.allocState();
  struct Guard {
    const ob::StateSpace& space;
    ob::State* s;
    ~Guard() { space.freeState(s); }
  } guard{space, tmp};

  // Walks from (ta, fa), already checked, to tb with state fb; bisects changes above max_jump.
  std::function<bool(double, const geometry::FoldState&, double, const geometry::FoldState&, int)> advance =
      [&](double ta, const geometry::FoldState& fa, double tb, const geometry::FoldState& fb, int depth) -> bool {
    if ((fb.angles - fa.angles).cwiseAbs().maxCoeff() <= max_jump_) {
      if (!motion.valid_next(fb)) return false;
      last_t = tb;
      return true;
    }
    if (depth == 0) return false;
    const double tm = 0.5 * (ta + tb);
    space.interpolate(s1, s2, tm, tmp);
    geometry::FoldState fm;
    if (!reader_(tmp, fm)) return false;
    return advance(ta, fa, tm, fm, depth - 1) && advance(tm, fm, tb, fb, depth - 1);
  };

  const double longest = (f2.angles - f1.angles).cwiseAbs().maxCoeff();
  const int steps = std::max(1, static_cast<int>(std::ceil(longest / resolution_)));
  geometry::FoldState prev = f1, next;
  double prev_t = 0.0;
  for (int i = 1; i <= steps; ++i) {
    const double t = static_cast<double>(i) / steps;
    if (i == steps) {
      next = f2;
    } else {
      space.interpolate(s1, s2, t, tmp);
      if (!reader_(tmp, next)) return fail();
    }
    if (!advance(prev_t, prev, t, next, 12)) return fail();
    prev = next;
    prev_t = t;
  }
  ++valid_;
  return true;
}

}  // namespace foldkit::statespaces
