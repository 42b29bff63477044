#include "foldkit/dynamics/dynamic_simulate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "foldkit/geometry/closure.hpp"
#include "dynamic_options.hpp"
#include "ode_sheet.hpp"
#include "post_stabilise.hpp"

namespace foldkit::dynamics {

std::vector<std::string> model_names() {
  using simulation::Actuation;
  return {simulation::to_string(Actuation::Motor), simulation::to_string(Actuation::Spring),
          simulation::to_string(Actuation::Synchronised), kModelName};
}

namespace {

// One run of a sequence: the engine, the closure measure and the report being filled.
class Runner {
 public:
  // `fixed`: the held actor's index, −1 for none (the closure is then measured from actor 0).
  Runner(const geometry::CreasePattern& pattern, const DynamicOptions& options, int fixed)
      : pattern_(pattern), o_(options), sheet_(pattern, options, fixed), closure_(pattern, std::max(fixed, 0)),
        stabilise_(closure_, detail::kProjectionTolerance),
        stalled_for_(pattern.joints().size(), 0.0), since_best_(pattern.joints().size(), 0.0),
        best_(pattern.joints().size(), 0.0), best_need_(pattern.joints().size(), 0.0) {
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
    DynamicEventReport er{event.number, time_, time_, true, 0.0, 0.0};
    try {
      const std::vector<int> named = drive_event(event);  // setting a drive calls the engine too
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
        // The run's own limit for this joint, else the pattern's (PMML <MaxTorque>), else the default.
        const auto own = o_.joint_max_torque.find(fold.joint_id);
        d.max_torque = own != o_.joint_max_torque.end() ? own->second : joint.max_torque.value_or(o_.max_torque);
      } else {
        d.kind = detail::JointDrive::Spring;
        d.spring = joint.spring;
        d.damping = joint.damping;
      }
      sheet_.set_drive(j, d);
      stalled_for_[j] = since_best_[j] = best_need_[j] = 0.0;
      best_[j] = std::numeric_limits<double>::infinity();
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
        const auto c = stabilise_(sheet_);
        report_.max_corrected_error = std::max(report_.max_corrected_error, c.before);
        if (!c.moved && c.before > detail::kProjectionTolerance) ++report_.failed_corrections;
        next_projection += o_.projection_interval;
      }
      record_torques();
      if (!record_contacts(er.number)) return false;
      if (time_ >= next_check - 0.5 * o_.time_step) {  // the same slack: a frame every check_interval
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
  // (a probe step with the spring replaced by a holding motor, the contacts of its moving side
  // left out), within the torque of the spring at the reach tolerance, or what is left over is
  // pushed back by a contact: the spring is within reach_tolerance of where it balances. A soft
  // spring starts so slowly that it stays below settle_speed for settle_time far from its angle,
  // and a damped one creeps in the end with its damper cancelling its spring: neither is settled
  // while its static torque is unbalanced. A contact elsewhere (the root facet on the ground)
  // carries none of that torque; one that pushes back against the spring may carry the rest.
  bool balanced() {
    for (std::size_t j = 0; j < report_.joints.size(); ++j) {
      const int ji = static_cast<int>(j);
      const auto& d = sheet_.drive(ji);
      if (d.kind != detail::JointDrive::Spring) continue;
      const double exerted = d.spring * sheet_.angle_to(ji, d.target);
      if (std::abs(exerted - sheet_.hold_torque_signed(ji)) <= d.spring * o_.reach_tolerance) continue;
      // What is left may be carried by a contact pushing back: then, released from rest with the
      // spring's static torque, the sheet stays still (it would not pass settle_speed within
      // settle_time); a contact that gives way (a free sheet's facet lifting off) carries nothing.
      if (!opposing_contact(ji, exerted) ||
          std::abs(sheet_.released_rate(ji, exerted)) * o_.settle_time / o_.time_step > o_.settle_speed)
        return false;
    }
    return true;
  }

  // The deepest contact of the last step that pushes joint j's moving side against a torque of
  // sign `toward` (toward > 0: one turning j toward larger angles), if any.
  const detail::ContactPoint* opposing_contact(int j, double toward) const {
    // Metres of lever per newton: a contact on the axis itself resists no turn.
    constexpr double kLever = 1e-9;
    const detail::ContactPoint* deepest = nullptr;
    for (const auto& c : sheet_.contact_points())
      if (std::copysign(1.0, toward) * sheet_.contact_moment(j, c) < -kLever && (!deepest || c.depth > deepest->depth))
        deepest = &c;
    return deepest;
  }

  // Motors only (a spring drive settles, and close_event() judges where). A motor short of its
  // angle, at its torque limit and making no progress for stall_time has stalled when it could not
  // hold the sheet there without the contacts of its moving side, and is blocked when it could and
  // a contact pushes against it; else it was a transient (an overshoot braked, the sheet
  // accelerated) and goes on. One that swings under gravity is never at rest for stall_time: it
  // has stalled when it came no closer to its angle for stall_time and, where it turned back
  // closest, could not hold the sheet.
  bool find_stalls(const std::vector<int>& named, int event) {
    if (o_.drive != Drive::Motor) return false;
    bool any = false;
    for (int j : named) {
      const auto& d = sheet_.drive(j);
      const double error = sheet_.angle_to(j, d.target);
      if (std::abs(error) <= o_.reach_tolerance) {
        stalled_for_[j] = since_best_[j] = 0.0;
        continue;
      }
      const bool stuck = std::copysign(1.0, error) * sheet_.rate(j) < 0.01 * d.speed &&
                         std::abs(sheet_.torque(j)) >= 0.999 * d.max_torque;
      const bool closer = std::abs(error) < best_[j] - o_.reach_tolerance;
      if (closer) best_[j] = std::abs(error), best_need_[j] = 0.0;
      since_best_[j] = closer ? 0.0 : since_best_[j] + o_.time_step;
      // Turning back where it came closest: what holding the sheet there would need.
      if (stuck && stalled_for_[j] == 0.0 && std::abs(error) <= best_[j] + o_.reach_tolerance) best_need_[j] = sheet_.hold_torque(j);
      stalled_for_[j] = stuck ? stalled_for_[j] + o_.time_step : 0.0;
      if (since_best_[j] >= o_.stall_time && best_need_[j] > d.max_torque) {
        add_stall(j, event, d.max_torque, best_need_[j], nullptr, "where it came closest, ");
        any = true;
        continue;
      }
      if (stalled_for_[j] < o_.stall_time) continue;
      stalled_for_[j] = 0.0;
      const double needed = sheet_.hold_torque(j);
      // Blocked: strong enough, but at rest against a contact (not turning away from its angle,
      // as when braking an overshoot while some facet happens to touch).
      const detail::ContactPoint* against =
          needed <= d.max_torque && std::abs(sheet_.rate(j)) < 0.01 * d.speed ? opposing_contact(j, error) : nullptr;
      if (needed > d.max_torque || against) {
        add_stall(j, event, d.max_torque, needed, against, "");
        any = true;
      }
    }
    return any;
  }

  // A stall of joint index j: blocked (a collision) by `blocker` when one is given, else too weak
  // (`where` qualifies the needed torque).
  void add_stall(int j, int event, double available, double needed, const detail::ContactPoint* blocker, const char* where) {
    const auto& d = sheet_.drive(j);
    Stall st{pattern_.joints()[j].id, event, time_, sheet_.angle(j), d.target, needed, available, {}};
    std::ostringstream msg;
    msg << "joint " << st.joint << (blocker ? " blocked" : " stalled") << " in event " << event << " at "
        << st.angle * 180.0 / M_PI << " deg (t = " << time_ << " s): ";
    if (blocker) {
      st.blocked_by.push_back(pattern_.actors()[blocker->a].id);
      if (blocker->b >= 0) st.blocked_by.push_back(pattern_.actors()[blocker->b].id);
      msg << contact_words(*blocker) << " touch (penetration " << blocker->depth << " m)";
    } else {
      msg << where << "it needs " << st.needed_torque << " N·m, has " << st.available_torque << " N·m";
    }
    report_.stalls.push_back(st);
    fail(st.blocked_by.empty() ? geometry::StatusCode::NoProgress : geometry::StatusCode::Collision, msg.str());
  }

  // Closes the event's report. A spring short of its angle when the event settled fails it here
  // (not after a time-out or another failure: the status already says why it stopped).
  void close_event(DynamicEventReport& er) {
    er.end = time_;
    const geometry::FoldState end = sheet_.state();
    const double e = closure_.max_error(end);
    er.max_closure_error = std::max(er.max_closure_error, e);
    report_.max_closure_error = std::max(report_.max_closure_error, e);
    er.energy = sheet_.kinetic_energy() + sheet_.potential_energy() + sheet_.spring_energy();
    if (o_.drive == Drive::Spring && report_.status.ok()) {
      for (std::size_t j = 0; j < report_.joints.size(); ++j) {
        const int ji = static_cast<int>(j);
        const auto& d = sheet_.drive(ji);
        const double short_by = sheet_.angle_to(ji, d.target);
        if (d.kind != detail::JointDrive::Spring || std::abs(short_by) <= o_.reach_tolerance) continue;
        er.reached = false;
        const double available = d.spring * std::abs(short_by), needed = sheet_.hold_torque(ji);
        add_stall(ji, er.number, available, needed, needed <= available ? opposing_contact(ji, short_by) : nullptr, "");
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
  // Per joint, for find_stalls(): seconds stuck; seconds since it last came closer to its angle;
  // its closest |error| in this event, radians; the torque holding the sheet there needs, N·m (0:
  // not probed).
  std::vector<double> stalled_for_, since_best_, best_, best_need_;
  DynamicReport report_;
  std::unordered_map<long long, std::size_t> contact_index_;  // into report_.contacts, by pair
  double time_ = 0.0;
};

}  // namespace

DynamicReport simulate_dynamic(const geometry::CreasePattern& pattern, const geometry::FoldSequence& sequence,
                               const DynamicOptions& given) {
  // From here on density, gravity and (when one is held) fixed_actor are set.
  const DynamicOptions options = resolve_options(pattern, given);
  detail::check_options(pattern, options);
  detail::check_sequence(pattern, sequence, options.drive);
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
