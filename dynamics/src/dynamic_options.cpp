#include "dynamic_options.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "foldkit/geometry/closure.hpp"

namespace foldkit::dynamics {

const char* to_string(Drive drive) { return drive == Drive::Motor ? "motor" : "spring"; }

Drive parse_drive(const std::string& name) {
  if (name == "motor") return Drive::Motor;
  if (name == "spring") return Drive::Spring;
  throw std::invalid_argument("unknown drive '" + name + "' (motor or spring)");
}

const char* to_string(Solver solver) { return solver == Solver::Direct ? "direct" : "iterative"; }

Solver parse_solver(const std::string& name) {
  if (name == "direct") return Solver::Direct;
  if (name == "iterative") return Solver::Iterative;
  throw std::invalid_argument("unknown solver '" + name + "' (direct or iterative)");
}

DynamicOptions resolve_options(const geometry::CreasePattern& pattern, DynamicOptions options) {
  const geometry::PhysicsSpec& file = pattern.physics();
  if (!options.density) options.density = file.density.value_or(kDefaultDensity);
  if (!options.gravity) options.gravity = file.gravity.value_or(Eigen::Vector3d::Zero());
  if (options.hold_fixed && !options.fixed_actor) {
    if (file.fixed_actor) options.fixed_actor = file.fixed_actor;
    else if (!pattern.actors().empty()) options.fixed_actor = pattern.actors().front().id;
  }
  return options;
}

namespace detail {

void check_options(const geometry::CreasePattern& pattern, const DynamicOptions& o) {
  auto positive = [](double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v)) throw std::invalid_argument(std::string(name) + " must be positive and finite");
  };
  positive(o.density.value_or(kDefaultDensity), "density");
  positive(o.max_torque, "max_torque");
  positive(o.scale, "scale");
  positive(o.time_step, "time_step");
  positive(o.approach_time, "approach_time");
  positive(o.reach_tolerance, "reach_tolerance");
  positive(o.settle_speed, "settle_speed");
  positive(o.settle_time, "settle_time");
  positive(o.stall_time, "stall_time");
  positive(o.max_event_time, "max_event_time");
  positive(o.closure_tolerance, "closure_tolerance");
  positive(o.check_interval, "check_interval");
  // A motor closes approach_time's worth of its error per second: a longer step overshoots and
  // oscillates, and a stall could be called on one step.
  if (o.time_step > std::min(o.approach_time, o.stall_time))
    throw std::invalid_argument("time_step " + std::to_string(o.time_step) + " s is too long for the motors: at most " +
                                std::to_string(std::min(o.approach_time, o.stall_time)) + " s (approach_time, stall_time)");
  if (o.gravity && !o.gravity->allFinite()) throw std::invalid_argument("gravity must be finite");
  if (o.iterations < 1) throw std::invalid_argument("iterations must be at least 1");
  if (!(o.erp > 0.0 && o.erp <= 1.0)) throw std::invalid_argument("erp must be in (0, 1]");
  if (!(o.cfm >= 0.0) || !std::isfinite(o.cfm)) throw std::invalid_argument("cfm must be non-negative and finite");
  if (!(o.projection_interval >= 0.0) || !std::isfinite(o.projection_interval))
    throw std::invalid_argument("projection_interval must be non-negative and finite");
  if (o.start.size() > 0) {
    if (o.start.size() != static_cast<Eigen::Index>(pattern.joints().size()) || !o.start.allFinite())
      throw std::invalid_argument("start must hold one finite angle per joint");
    const bool held = o.hold_fixed && o.fixed_actor && pattern.actor_index(*o.fixed_actor);
    const int root = held ? *pattern.actor_index(*o.fixed_actor) : 0;
    const geometry::ClosureSystem closure(pattern, root);
    if (closure.max_error(geometry::FoldState{o.start}) > o.closure_tolerance)
      throw std::invalid_argument("the start state does not close (loop error above closure_tolerance)");
  }
  for (const auto& [id, torque] : o.joint_max_torque) {
    if (!pattern.joint_index(id)) throw std::invalid_argument("joint_max_torque: no joint " + std::to_string(id));
    positive(torque, "joint_max_torque");
  }
  if (o.ground && !std::isfinite(*o.ground)) throw std::invalid_argument("ground must be finite");
  if (o.friction && (!(*o.friction >= 0.0) || !std::isfinite(*o.friction))) throw std::invalid_argument("friction must be non-negative and finite");
  if (o.thickness) positive(*o.thickness, "thickness");
  // Without anything to touch they would be ignored: refused, as one model's options are for the other.
  if (!o.contacts && !o.ground) {
    if (o.friction) throw std::invalid_argument("friction needs contacts or ground");
    if (o.thickness) throw std::invalid_argument("thickness needs contacts or ground");
  }
  if (o.fixed_actor && !pattern.actor_index(*o.fixed_actor))
    throw std::invalid_argument("no actor " + std::to_string(*o.fixed_actor) + " to hold fixed");
}

void check_sequence(const geometry::CreasePattern& pattern, const geometry::FoldSequence& sequence, Drive drive) {
  for (const auto& event : sequence.events)
    for (const auto& fold : event.folds) {
      const auto j = pattern.joint_index(fold.joint_id);
      if (!j) throw std::invalid_argument("event " + std::to_string(event.number) + ": no joint " + std::to_string(fold.joint_id));
      if (!std::isfinite(fold.angle)) throw simulation::SequenceError(fold.line, "fold angle is not finite");
      // A hinge reads its angle in (−π, π], and ODE ignores a spring's stop beyond ±π.
      if (std::abs(fold.angle) > M_PI) throw simulation::SequenceError(fold.line, "fold angle beyond ±180°");
      if (drive == Drive::Motor && (!(fold.speed > 0.0) || !std::isfinite(fold.speed)))
        throw simulation::SequenceError(fold.line, "speed must be positive and finite");
      const auto& joint = pattern.joints()[*j];
      // A damper alone (SpringConst 0) exerts nothing toward the angle: the event could only stall.
      if (drive == Drive::Spring && !(joint.spring > 0.0))
        throw simulation::SequenceError(fold.line, "joint " + std::to_string(joint.id) + " has no SpringConst: no spring drives it");
    }
}

}  // namespace detail
}  // namespace foldkit::dynamics
