#include "actuation.hpp"

#include <algorithm>
#include <cmath>

namespace foldkit::simulation::detail {

EventMotion::EventMotion(const geometry::CreasePattern& pattern, const geometry::FoldEvent& event,
                         const geometry::FoldState& start, const SimulationOptions& options)
    : model_(options.model), options_(&options) {
  for (const auto& fold : event.folds) {
    const auto j = pattern.joint_index(fold.joint_id);
    if (!j) throw std::invalid_argument("event " + std::to_string(event.number) + ": no joint " + std::to_string(fold.joint_id));
    const auto& joint = pattern.joints()[*j];
    const Eigen::Index index = *j;
    Drive d{index, start.angles[index], fold.angle, fold.speed, joint.spring, joint.damping};
    if (d.start == d.target) continue;
    if (model_ == Actuation::Spring) {
      if (!(d.spring > 0.0)) {
        failure_ = "joint " + std::to_string(joint.id) + " has spring constant 0: the spring model cannot move it";
        reached_ = false;
      }
    } else {
      duration_ = std::max(duration_, std::abs(d.target - d.start) / d.speed);
    }
    drives_.push_back(d);
  }
  done_ = drives_.empty() || !reached_;
}

double EventMotion::advance(geometry::FoldState& state, double dt) {
  if (done_) return 0.0;
  if (model_ != Actuation::Spring) {
    const double h = std::min(dt, duration_ - elapsed_);
    elapsed_ += h;
    // The last step lands on the event's end exactly, so each joint ends at its angle.
    const bool last = !(elapsed_ < duration_);
    for (const Drive& d : drives_) {
      double& angle = state.angles[d.joint];
      if (last) {
        angle = d.target;
      } else if (model_ == Actuation::Motor) {
        const double travel = std::min(d.speed * elapsed_, std::abs(d.target - d.start));
        angle = d.start + std::copysign(travel, d.target - d.start);
      } else {
        angle = d.start + (d.target - d.start) * (elapsed_ / duration_);
      }
    }
    done_ = last;
    return h;
  }
  // Unit inertia: θ̈ = −k(θ − θ*) − c θ̇, by backward Euler, which is stable for every step size
  // and stiffness (it damps a little, never amplifies).
  for (Drive& d : drives_) {
    double& angle = state.angles[d.joint];
    d.rate = (d.rate - dt * d.spring * (angle - d.target)) / (1.0 + dt * d.damping + dt * dt * d.spring);
    angle += dt * d.rate;
  }
  elapsed_ += dt;
  settle(state);
  return dt;
}

void EventMotion::settle(geometry::FoldState& state) {
  const bool still = std::all_of(drives_.begin(), drives_.end(), [&](const Drive& d) {
    return std::abs(state.angles[d.joint] - d.target) <= options_->settle_angle && std::abs(d.rate) <= options_->settle_speed;
  });
  if (still) {
    for (const Drive& d : drives_) state.angles[d.joint] = d.target;
    done_ = true;
  } else if (elapsed_ >= options_->max_event_time) {
    done_ = true;
    reached_ = false;
    failure_ = "the springs did not settle within " + std::to_string(options_->max_event_time) + " s";
  }
}

}  // namespace foldkit::simulation::detail
