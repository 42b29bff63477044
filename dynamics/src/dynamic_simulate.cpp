#include "foldkit/dynamics/dynamic_simulate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "foldkit/geometry/closure.hpp"
#include "ode_sheet.hpp"
#include "post_stabilise.hpp"

namespace foldkit::dynamics {

std::vector<std::string> model_names() {
  using simulation::Actuation;
  return {simulation::to_string(Actuation::Motor), simulation::to_string(Actuation::Spring),
          simulation::to_string(Actuation::Synchronised), kModelName};
}

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

namespace {

// Radians: the loop error a post-stabilisation leaves, far below any closure tolerance.
constexpr double kProjectionTolerance = 1e-9;

void check_options(const geometry::CreasePattern& pattern, const DynamicOptions& o) {
  auto positive = [](double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v)) throw std::invalid_argument(std::string(name) + " must be positive and finite");
  };
  positive(o.density, "density");
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
  if (!o.gravity.allFinite()) throw std::invalid_argument("gravity must be finite");
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
  if (!(o.friction >= 0.0) || !std::isfinite(o.friction)) throw std::invalid_argument("friction must be non-negative and finite");
  if (o.thickness) positive(*o.thickness, "thickness");
  if (o.fixed_actor && !pattern.actor_index(*o.fixed_actor))
    throw std::invalid_argument("no actor " + std::to_string(*o.fixed_actor) + " to hold fixed");
}

// One run of a sequence: the engine, the closure measure and the report being filled.
class Runner {
 public:
  // `fixed`: the held actor's index, −1 for none (the closure is then measured from actor 0).
  Runner(const geometry::CreasePattern& pattern, const DynamicOptions& options, int fixed)
      : pattern_(pattern), o_(options), sheet_(pattern, options, fixed), closure_(pattern, std::max(fixed, 0)),
        stabilise_(closure_, kProjectionTolerance),
        stalled_for_(pattern.joints().size(), 0.0) {
    report_.status = {geometry::StatusCode::Success, "every event reached its angles"};
    report_.time_step = o_.time_step;
    report_.closure_tolerance = o_.closure_tolerance;
    report_.thickness = sheet_.thickness();
    for (const auto& j : pattern.joints()) report_.joints.push_back({j.id, 0.0, 0.0});
    report_.frames.push_back({0.0, -1, sheet_.state()});
    report_.frame_torques.push_back(Eigen::VectorXd::Zero(static_cast<Eigen::Index>(pattern.joints().size())));
  }

  // Runs one event; false when the sequence must stop (a stall, a collision, a time-out, a
  // blow-up, an error the engine reported).
  bool run(const geometry::FoldEvent& event, std::size_t done, std::size_t total) {
    std::vector<int> named = drive_event(event);
    DynamicEventReport er{event.number, time_, time_, true, 0.0, 0.0};
    try {
      if (!advance(named, er, done, total)) er.reached = false;
      close_event(er);  // a spring that settled short of its angle fails the event here
    } catch (const detail::EngineError& e) {
      return blow_up(er, e.what());
    }
    return er.reached;
  }

  DynamicReport finish(double seconds) {
    const geometry::FoldState s = sheet_.state();
    report_.duration = time_;
    report_.seconds = seconds;
    report_.final_state = s;
    for (std::size_t j = 0; j < report_.joints.size(); ++j) report_.joints[j].angle = s.angles[static_cast<Eigen::Index>(j)];
    report_.kinetic_energy = sheet_.kinetic_energy();
    report_.potential_energy = sheet_.potential_energy();
    report_.spring_energy = sheet_.spring_energy();
    if (report_.status.ok() && report_.max_closure_error > o_.closure_tolerance)
      fail(geometry::StatusCode::ClosureViolated, "the engine's loops opened by " + std::to_string(report_.max_closure_error) +
                                                      " rad, beyond the tolerance " + std::to_string(o_.closure_tolerance));
    return std::move(report_);
  }

 private:
  // Gives each joint the event names its drive; joints of earlier events keep theirs (a motor
  // holds its angle, a spring pulls toward it), joints never named stay free hinges.
  std::vector<int> drive_event(const geometry::FoldEvent& event) {
    std::vector<int> named;
    for (const auto& fold : event.folds) {
      const int j = *pattern_.joint_index(fold.joint_id);
      const auto& joint = pattern_.joints()[j];
      detail::JointDrive d;
      d.target = fold.angle;
      if (o_.drive == Drive::Motor) {
        d.kind = detail::JointDrive::Motor;
        d.speed = fold.speed;
        const auto own = o_.joint_max_torque.find(fold.joint_id);
        d.max_torque = own != o_.joint_max_torque.end() ? own->second : o_.max_torque;
      } else {
        d.kind = detail::JointDrive::Spring;
        d.spring = joint.spring;
        d.damping = joint.damping;
      }
      sheet_.set_drive(j, d);
      stalled_for_[j] = 0.0;
      named.push_back(j);
    }
    return named;
  }

  // Steps until the event's joints reach their angles (true) or the run must stop (false).
  bool advance(const std::vector<int>& named, DynamicEventReport& er, std::size_t done, std::size_t total) {
    double quiet = 0.0, next_check = time_ + o_.check_interval, next_projection = time_ + o_.projection_interval;
    for (;;) {
      sheet_.step();
      ++report_.steps;
      time_ = static_cast<double>(report_.steps) * o_.time_step;  // no rounding drift over many steps
      if (!sheet_.sane()) throw detail::EngineError("a body moved faster than 1e6 m/s or rad/s");
      // Half a step's slack: an interval of whole steps must not slip a step to rounding.
      if (o_.projection_interval > 0.0 && time_ >= next_projection - 0.5 * o_.time_step) {
        const double corrected = stabilise_(sheet_).first;
        report_.max_corrected_error = std::max(report_.max_corrected_error, corrected);
        next_projection += o_.projection_interval;
      }
      record_torques();
      if (!record_contacts(er.number)) return false;
      if (time_ >= next_check) {
        check(er, er.number, done, total);
        next_check += o_.check_interval;
      }
      if (finished(named, quiet)) return true;
      if (find_stalls(named, er.number)) return false;
      if (time_ - er.start >= o_.max_event_time) {
        fail(geometry::StatusCode::LimitReached,
             "event " + std::to_string(er.number) + " did not finish within " + std::to_string(o_.max_event_time) + " s");
        return false;
      }
    }
  }

  // Adds this step's contacts to the report; false when two facets' prisms overlap by more than
  // the thickness (they passed through each other; the ground, a half-space, cannot be passed).
  bool record_contacts(int event) {
    const double t = sheet_.thickness();
    for (const detail::ContactPoint& c : sheet_.contact_points()) {
      const long long key = static_cast<long long>(c.a) * static_cast<long long>(pattern_.actors().size() + 1) + (c.b + 1);
      const auto [it, fresh] = contact_index_.try_emplace(key, report_.contacts.size());
      if (fresh) {
        Contact first{{pattern_.actors()[c.a].id}, c.b < 0, event, time_, c.point, 0.0};
        if (c.b >= 0) first.actors.push_back(pattern_.actors()[c.b].id);
        report_.contacts.push_back(first);
      }
      Contact& rc = report_.contacts[it->second];
      rc.max_penetration = std::max(rc.max_penetration, c.depth);
      report_.max_penetration = std::max(report_.max_penetration, c.depth);
      if (c.b >= 0 && c.depth > t) {
        std::ostringstream msg;
        msg << contact_words(c) << " overlap by " << c.depth << " m at t = " << time_ << " s in event " << event
            << ", more than the sheet's thickness " << t << " m: they passed through each other (try a time step below "
            << o_.time_step * t / (2.0 * c.depth) << " s, or a larger --thickness)";
        fail(geometry::StatusCode::Collision, msg.str());
        return false;
      }
    }
    return true;
  }

  // "actors 3 and 5" or "actor 3 and the ground".
  std::string contact_words(const detail::ContactPoint& c) const {
    const std::string a = std::to_string(pattern_.actors()[c.a].id);
    return c.b < 0 ? "actor " + a + " and the ground" : "actors " + a + " and " + std::to_string(pattern_.actors()[c.b].id);
  }

  // The deepest contact of the last step, if any touches.
  const detail::ContactPoint* deepest_contact() const {
    const detail::ContactPoint* deepest = nullptr;
    for (const auto& c : sheet_.contact_points())
      if (!deepest || c.depth > deepest->depth) deepest = &c;
    return deepest;
  }

  void add_frame(int event, const geometry::FoldState& state) {
    report_.frames.push_back({time_, event, state});
    Eigen::VectorXd torques(state.angles.size());
    for (Eigen::Index j = 0; j < torques.size(); ++j) torques[j] = sheet_.torque(static_cast<int>(j));
    report_.frame_torques.push_back(std::move(torques));
  }

  void record_torques() {
    for (std::size_t j = 0; j < report_.joints.size(); ++j)
      report_.joints[j].peak_torque = std::max(report_.joints[j].peak_torque, std::abs(sheet_.torque(static_cast<int>(j))));
    report_.peak_kinetic_energy = std::max(report_.peak_kinetic_energy, sheet_.kinetic_energy());
  }

  void check(DynamicEventReport& er, int event, std::size_t done, std::size_t total) {
    const geometry::FoldState s = sheet_.state();
    const double e = closure_.max_error(s);
    er.max_closure_error = std::max(er.max_closure_error, e);
    report_.max_closure_error = std::max(report_.max_closure_error, e);
    if (o_.record_frames) add_frame(event, s);
    if (o_.progress) o_.progress({static_cast<double>(done), static_cast<double>(total), "events", e});
  }

  // Motors: every named joint within reach_tolerance. Springs: the whole sheet still for
  // settle_time, and at rest there for good (balanced()).
  bool finished(const std::vector<int>& named, double& quiet) {
    if (o_.drive == Drive::Motor)
      return std::all_of(named.begin(), named.end(), [&](int j) {
        return std::abs(sheet_.angle_to(j, sheet_.drive(j).target)) <= o_.reach_tolerance;
      });
    quiet = sheet_.max_rate() <= o_.settle_speed ? quiet + o_.time_step : 0.0;
    if (quiet < o_.settle_time) return false;
    if (balanced()) return true;
    quiet = 0.0;  // slow, but still accelerating: look again after another settle_time
    return false;
  }

  // Whether every spring's static torque k(θ* − θ) is what holding the sheet at rest there needs
  // (a probe step with the spring replaced by a holding motor), within the torque of the spring
  // at the reach tolerance: the spring is within reach_tolerance of where it balances. A soft
  // spring starts so slowly that it stays below settle_speed for settle_time far from its angle,
  // and a damped one creeps in the end with its damper cancelling its spring: neither is settled
  // while its static torque is unbalanced. Touching facets share the load with the springs in
  // ways a probe does not split: a sheet at rest in contact is settled.
  bool balanced() {
    if (!sheet_.contact_points().empty()) return true;
    for (std::size_t j = 0; j < report_.joints.size(); ++j) {
      const int ji = static_cast<int>(j);
      const auto& d = sheet_.drive(ji);
      if (d.kind != detail::JointDrive::Spring) continue;
      const double exerted = d.spring * sheet_.angle_to(ji, d.target), needed = sheet_.hold_torque_signed(ji);
      if (std::abs(exerted - needed) > d.spring * o_.reach_tolerance) return false;
    }
    return true;
  }

  // A motor short of its angle, at its torque limit, making no progress for stall_time, and too
  // weak to hold the sheet where it is (a stall), or strong enough but held back by a contact (a
  // collision); a spring drive never stalls here (it settles, and close_event() judges where).
  bool find_stalls(const std::vector<int>& named, int event) {
    if (o_.drive != Drive::Motor) return false;
    bool any = false;
    for (int j : named) {
      const auto& d = sheet_.drive(j);
      const double error = sheet_.angle_to(j, d.target);
      const bool stuck = std::abs(error) > o_.reach_tolerance && std::copysign(1.0, error) * sheet_.rate(j) < 0.01 * d.speed &&
                         std::abs(sheet_.torque(j)) >= 0.999 * d.max_torque;
      stalled_for_[j] = stuck ? stalled_for_[j] + o_.time_step : 0.0;
      if (stalled_for_[j] < o_.stall_time) continue;
      // Saturated and losing for stall_time may be a transient (an overshoot braked, the sheet
      // accelerated): it is a stall only when the motor could not even hold the sheet here at rest.
      stalled_for_[j] = 0.0;
      // Blocked: strong enough, but at rest against something (not turning away from its angle,
      // as when braking an overshoot while some other facet happens to touch).
      const bool weak = sheet_.hold_torque(j) > d.max_torque;
      if (weak || (deepest_contact() && std::abs(sheet_.rate(j)) < 0.01 * d.speed)) {
        add_stall(j, event, d.max_torque);
        any = true;
      }
    }
    return any;
  }

  // A stall of joint index j; blocked (a collision) when something touches and holding the sheet
  // there needs no more than `available`.
  void add_stall(int j, int event, double available) {
    const auto& d = sheet_.drive(j);
    Stall st{pattern_.joints()[j].id, event, time_, sheet_.angle(j), d.target, 0.0, available, {}};
    st.needed_torque = sheet_.hold_torque(j);
    const detail::ContactPoint* touch = deepest_contact();
    std::ostringstream msg;
    msg << "joint " << st.joint << (touch && st.needed_torque <= available ? " blocked" : " stalled") << " in event " << event
        << " at " << st.angle * 180.0 / M_PI << " deg (t = " << time_ << " s): ";
    if (touch && st.needed_torque <= available) {
      st.blocked_by.push_back(pattern_.actors()[touch->a].id);
      if (touch->b >= 0) st.blocked_by.push_back(pattern_.actors()[touch->b].id);
      msg << contact_words(*touch) << " touch (penetration " << touch->depth << " m)";
    } else {
      msg << "it needs " << st.needed_torque << " N·m, has " << st.available_torque << " N·m";
    }
    report_.stalls.push_back(st);
    fail(st.blocked_by.empty() ? geometry::StatusCode::NoProgress : geometry::StatusCode::Collision, msg.str());
  }

  void close_event(DynamicEventReport& er) {
    er.end = time_;
    const geometry::FoldState end = sheet_.state();
    const double e = closure_.max_error(end);
    er.max_closure_error = std::max(er.max_closure_error, e);
    report_.max_closure_error = std::max(report_.max_closure_error, e);
    er.energy = sheet_.kinetic_energy() + sheet_.potential_energy() + sheet_.spring_energy();
    if (o_.drive == Drive::Spring && report_.stalls.empty()) {
      for (std::size_t j = 0; j < report_.joints.size(); ++j) {
        const int ji = static_cast<int>(j);
        const auto& d = sheet_.drive(ji);
        if (d.kind != detail::JointDrive::Spring || std::abs(sheet_.angle_to(ji, d.target)) <= o_.reach_tolerance) continue;
        er.reached = false;
        add_stall(ji, er.number, d.spring * std::abs(sheet_.angle_to(ji, d.target)));
      }
    }
    if (report_.frames.back().time < time_) add_frame(er.number, end);
    report_.events.push_back(er);
  }

  bool blow_up(DynamicEventReport& er, const std::string& why) {
    std::ostringstream msg;
    msg << "the engine's state blew up at t = " << time_ << " s in event " << er.number << " (" << why << "): time step "
        << o_.time_step << " s is too large for this sheet; try " << o_.time_step / 10.0 << " s";
    fail(geometry::StatusCode::Singular, msg.str());
    er.reached = false;
    er.end = time_;
    report_.events.push_back(er);
    return false;
  }

  void fail(geometry::StatusCode code, const std::string& message) {
    if (report_.status.ok()) report_.status = {code, message};
    report_.problems.push_back(message);
  }

  const geometry::CreasePattern& pattern_;
  const DynamicOptions& o_;
  detail::OdeSheet sheet_;
  geometry::ClosureSystem closure_;
  detail::PostStabiliser stabilise_;  // used when options ask for post-stabilisation
  std::vector<double> stalled_for_;
  DynamicReport report_;
  std::unordered_map<long long, std::size_t> contact_index_;  // into report_.contacts, by pair
  double time_ = 0.0;
};

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

}  // namespace

DynamicReport simulate_dynamic(const geometry::CreasePattern& pattern, const geometry::FoldSequence& sequence,
                               const DynamicOptions& options) {
  check_options(pattern, options);
  check_sequence(pattern, sequence, options.drive);
  const int fixed = !options.hold_fixed ? -1 : options.fixed_actor ? *pattern.actor_index(*options.fixed_actor) : 0;
  const auto start = std::chrono::steady_clock::now();
  std::optional<Runner> runner;
  try {
    runner.emplace(pattern, options, fixed);
  } catch (const detail::EngineError& e) {
    // The engine refused the sheet itself (a body it cannot take): a status, not an exception.
    DynamicReport r;
    r.status = {geometry::StatusCode::Singular, std::string("the engine refused the sheet: ") + e.what()};
    r.problems.push_back(r.status.message);
    r.time_step = options.time_step;
    r.closure_tolerance = options.closure_tolerance;
    r.final_state = options.start.size() > 0 ? geometry::FoldState{options.start} : geometry::FoldState::flat(pattern);
    for (std::size_t j = 0; j < pattern.joints().size(); ++j)
      r.joints.push_back({pattern.joints()[j].id, 0.0, r.final_state.angles[static_cast<Eigen::Index>(j)]});
    return r;
  }
  for (std::size_t e = 0; e < sequence.events.size(); ++e)
    if (!runner->run(sequence.events[e], e, sequence.events.size())) break;
  return runner->finish(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

}  // namespace foldkit::dynamics
