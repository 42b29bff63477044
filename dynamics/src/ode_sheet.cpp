#include "ode_sheet.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <mutex>

#include <ode/ode.h>

#include "foldkit/geometry/kinematics.hpp"
#include "ode_threading.hpp"

namespace foldkit::dynamics::detail {
namespace {

Eigen::Vector3d vec(const dReal* v) { return {v[0], v[1], v[2]}; }
Eigen::Quaterniond quat(const dReal* q) { return {q[0], q[1], q[2], q[3]}; }  // ODE: w, x, y, z
// The options are resolved (resolve_options()) before a sheet is built: empty means none.
Eigen::Vector3d gravity_of(const DynamicOptions& o) { return o.gravity.value_or(Eigen::Vector3d::Zero()); }

// A rigid motion seen by every body: what hold_torque() restores after its probe step.
struct BodyState {
  Eigen::Vector3d position, linear, angular;
  Eigen::Quaterniond orientation;
};

// ODE's error, debug and message handlers are process-wide. They are installed once (thread-safe)
// and act for foldkit only on a thread inside one of OdeSheet's engine calls (EngineScope): there an
// error or a failed debug check throws EngineError instead of aborting, and messages are dropped
// (inside a world step the throw stops at the call that raised it: ode_threading.hpp). Elsewhere
// — another part of the process using ODE — they do what was there before: the handler installed
// earlier, or ODE's own default (print; ODE then exits on an error, aborts on a failed debug
// check). Another library that replaces them later takes that choice from foldkit too: an
// engine error then ends the process as ODE's default does.
thread_local int engine_depth = 0;
dMessageFunction* previous_error = nullptr;
dMessageFunction* previous_debug = nullptr;
dMessageFunction* previous_message = nullptr;

// What ODE does with no handler set (it exits or aborts itself after an error's handler returns).
void pass_on(dMessageFunction* previous, const char* kind, int number, const char* format, va_list args) {
  if (previous) return previous(number, format, args);
  std::fprintf(stderr, "\n%s %d: ", kind, number);
  std::vfprintf(stderr, format, args);
  std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

[[noreturn]] void throw_engine_error(int number, const char* format, va_list args) {
  char text[512];
  std::vsnprintf(text, sizeof text, format, args);
  throw EngineError("ODE error " + std::to_string(number) + ": " + text);
}

void on_error(int number, const char* format, va_list args) {
  if (engine_depth > 0) throw_engine_error(number, format, args);
  pass_on(previous_error, "ODE Error", number, format, args);
}
void on_debug(int number, const char* format, va_list args) {
  if (engine_depth > 0) throw_engine_error(number, format, args);
  pass_on(previous_debug, "ODE INTERNAL ERROR", number, format, args);
}
void on_message(int number, const char* format, va_list args) {
  if (engine_depth == 0) pass_on(previous_message, "ODE Message", number, format, args);
}

// Marks this thread as inside foldkit's use of ODE for its lifetime (nests).
struct EngineScope {
  EngineScope() {
    static std::once_flag init;
    std::call_once(init, [] {
      dInitODE2(0);
      previous_error = dGetErrorHandler();
      previous_debug = dGetDebugHandler();
      previous_message = dGetMessageHandler();
      dSetErrorHandler(on_error);
      dSetDebugHandler(on_debug);
      dSetMessageHandler(on_message);
    });
    dAllocateODEDataForThread(dAllocateMaskAll);  // ODE's per-thread scratch; a no-op once done
    ++engine_depth;
  }
  ~EngineScope() { --engine_depth; }
  EngineScope(const EngineScope&) = delete;
  EngineScope& operator=(const EngineScope&) = delete;
};

}  // namespace

struct OdeSheet::Impl {
  const geometry::CreasePattern* pattern = nullptr;
  DynamicOptions options;
  int fixed = 0;  // −1: none
  std::unique_ptr<StepThreading> threading;  // before the world: freed after it
  World world;    // freed after the contacts that point into it
  std::vector<dBodyID> bodies;
  std::vector<MassProperties> mass;
  std::vector<dJointID> hinges;
  std::vector<dJointFeedback> feedback;
  std::vector<int> left, right;          // per joint: actor indices on either side of its axis
  std::vector<Eigen::Vector3d> axis;     // per joint: flat unit direction v[0] → v[1]
  std::vector<Eigen::Vector3d> anchor;   // per joint: flat point on its axis, metres
  std::unique_ptr<OdeContacts> contacts;  // only when the options ask for contacts or a ground
  geometry::KinematicTree tree;           // rooted at the fixed actor (actor 0 when none is held)

  // One engine step: this pose's contacts (a probe's leaving out those `leave_out` marks), the
  // solver, the contacts removed.
  void advance(const std::vector<char>* leave_out = nullptr) {
    if (contacts) contacts->collide(leave_out);
    threading->step(world.get(), options.solver == Solver::Direct ? &dWorldStep : &dWorldQuickStep, options.time_step);
    if (contacts) contacts->clear();
  }

  Eigen::Quaterniond orientation(int actor) const {
    return actor == fixed ? Eigen::Quaterniond::Identity() : quat(dBodyGetQuaternion(bodies[actor]));
  }
  Eigen::Vector3d spin(int actor) const {
    return actor == fixed ? Eigen::Vector3d::Zero() : vec(dBodyGetAngularVel(bodies[actor]));
  }
};

OdeSheet::OdeSheet(const geometry::CreasePattern& pattern, const DynamicOptions& options, int fixed)
    : impl_(std::make_unique<Impl>()), drives_(pattern.joints().size()) {
  const EngineScope engine;
  Impl& s = *impl_;
  s.pattern = &pattern;
  s.options = options;
  s.fixed = fixed;
  s.threading = std::make_unique<StepThreading>();
  s.world.reset(dWorldCreate());
  dWorldID world = s.world.get();
  s.threading->attach(world);
  const Eigen::Vector3d gravity = gravity_of(options);
  dWorldSetGravity(world, gravity.x(), gravity.y(), gravity.z());
  dWorldSetERP(world, options.erp);
  dWorldSetCFM(world, options.cfm);
  dWorldSetQuickStepNumIterations(world, options.iterations);
  dWorldSetAutoDisableFlag(world, 0);
  const int actors = static_cast<int>(pattern.actors().size());
  for (int a = 0; a < actors; ++a) {
    const MassProperties m = mass_properties(pattern, a, options.density.value_or(kDefaultDensity), options.scale);
    dBodyID b = dBodyCreate(world);
    dBodySetPosition(b, m.centroid.x(), m.centroid.y(), m.centroid.z());
    dMass dm;
    const Eigen::Matrix3d& I = m.inertia;
    dMassSetParameters(&dm, m.mass, 0, 0, 0, I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2));
    dBodySetMass(b, &dm);
    if (a == fixed) dBodySetKinematic(b);
    s.bodies.push_back(b);
    s.mass.push_back(m);
  }
  const int joints = static_cast<int>(pattern.joints().size());
  s.feedback.resize(joints);
  for (int j = 0; j < joints; ++j) {
    const auto& joint = pattern.joints()[j];
    const geometry::JointAxis ax = geometry::joint_axis(pattern, j);
    const bool first_right = geometry::side_of(pattern, j, joint.actors[0]) > 0;
    s.right.push_back(first_right ? joint.actors[0] : joint.actors[1]);
    s.left.push_back(first_right ? joint.actors[1] : joint.actors[0]);
    s.axis.push_back(ax.direction);
    s.anchor.push_back(options.scale * ax.point);
    // ODE's hinge angle is body 1's turn relative to body 2 about the axis: the right actor's
    // about +direction, or (when the right actor is the fixed one, which must not be body 1 for
    // its feedback) the left actor's about −direction, the same angle.
    const bool swap = s.right[j] == fixed;
    dJointID h = dJointCreateHinge(world, nullptr);
    dJointAttach(h, s.bodies[swap ? s.left[j] : s.right[j]], s.bodies[swap ? s.right[j] : s.left[j]]);
    const Eigen::Vector3d p = options.scale * ax.point, d = swap ? Eigen::Vector3d(-ax.direction) : ax.direction;
    dJointSetHingeAnchor(h, p.x(), p.y(), p.z());
    dJointSetHingeAxis(h, d.x(), d.y(), d.z());
    dJointSetFeedback(h, &s.feedback[j]);
    s.hinges.push_back(h);
  }
  // Hinges are attached on the flat sheet (ODE measures hinge angles from the pose they were
  // attached at), then the bodies move to the start state.
  s.tree = geometry::make_tree(pattern, std::max(fixed, 0));
  if (options.start.size() > 0) place(geometry::FoldState{options.start});
  if (options.contacts || options.ground)
    s.contacts = std::make_unique<OdeContacts>(world, s.bodies, fixed, pattern, s.options, s.mass);
}

OdeSheet::~OdeSheet() = default;

void OdeSheet::set_rates(const Eigen::VectorXd& rates) {
  const EngineScope engine;
  Impl& s = *impl_;
  const std::vector<Eigen::Isometry3d> pose = poses();
  // Down the tree: a child turns as its parent plus its joint's rate about the (common) axis, and
  // its centre of mass moves with the parent's motion plus that turn about a point on the axis.
  for (int a : s.tree.order) {
    const int p = s.tree.parent[a], j = s.tree.parent_joint[a];
    if (p < 0 || a == s.fixed) continue;
    const Eigen::Vector3d axis = pose[p].linear() * s.axis[j], on_axis = pose[p] * s.anchor[j];
    // rate() is the right actor's spin relative to the left's about +axis.
    const Eigen::Vector3d turn = (s.right[j] == a ? 1.0 : -1.0) * rates[j] * axis;
    const Eigen::Vector3d cp = vec(dBodyGetPosition(s.bodies[p])), ca = vec(dBodyGetPosition(s.bodies[a]));
    const Eigen::Vector3d w = s.spin(p) + turn;
    const Eigen::Vector3d v = (p == s.fixed ? Eigen::Vector3d::Zero() : vec(dBodyGetLinearVel(s.bodies[p]))) +
                              s.spin(p).cross(ca - cp) + turn.cross(ca - on_axis);
    dBodySetAngularVel(s.bodies[a], w.x(), w.y(), w.z());
    dBodySetLinearVel(s.bodies[a], v.x(), v.y(), v.z());
  }
}

void OdeSheet::place(const geometry::FoldState& state) {
  const EngineScope engine;
  Impl& s = *impl_;
  const int root = std::max(s.fixed, 0);
  // The root stays where it is (a held root at its flat pose; a free one where the engine has it).
  const Eigen::Isometry3d at = poses()[root];
  const auto pose = geometry::facet_poses(*s.pattern, s.tree, state);
  for (std::size_t a = 0; a < s.bodies.size(); ++a) {
    if (static_cast<int>(a) == s.fixed) continue;
    Eigen::Isometry3d m = pose[a];
    m.translation() *= s.options.scale;
    m = at * m;
    const Eigen::Vector3d c = m * s.mass[a].centroid;
    const Eigen::Quaterniond q(m.linear());
    const dQuaternion dq = {q.w(), q.x(), q.y(), q.z()};
    dBodySetPosition(s.bodies[a], c.x(), c.y(), c.z());
    dBodySetQuaternion(s.bodies[a], dq);
  }
}

void OdeSheet::set_drive(int j, const JointDrive& drive) {
  const EngineScope engine;
  drives_[j] = drive;
  dJointID h = impl_->hinges[j];
  // Stops first opened wide (ODE ignores a low stop above the high one). ODE tests a hinge's
  // stops, and clears a stop it found active, only while one of them lies within [−π, π]: a low
  // stop at −π (never passed, the hinge angle being in [−π, π]) keeps that test, so that a
  // spring's stop, once removed, does not stay active.
  dJointSetHingeParam(h, dParamLoStop, -M_PI);
  dJointSetHingeParam(h, dParamHiStop, dInfinity);
  dJointSetHingeParam(h, dParamFMax, drive.kind == JointDrive::Motor ? drive.max_torque : 0.0);
  dJointSetHingeParam(h, dParamVel, 0.0);
  if (drive.kind == JointDrive::Spring) {
    // A stop with equal low and high ends is a two-sided soft constraint: with these ERP and CFM
    // ODE integrates −k(θ−θ*) − cθ̇ implicitly (its manual, "Joint parameters"), stable for any k.
    const double h_k = impl_->options.time_step * drive.spring;
    dJointSetHingeParam(h, dParamLoStop, drive.target);
    dJointSetHingeParam(h, dParamHiStop, drive.target);
    dJointSetHingeParam(h, dParamStopERP, h_k / (h_k + drive.damping));
    dJointSetHingeParam(h, dParamStopCFM, 1.0 / (h_k + drive.damping));
    dJointSetHingeParam(h, dParamBounce, 0.0);
  }
}

void OdeSheet::step() {
  const EngineScope engine;
  const DynamicOptions& o = impl_->options;
  for (std::size_t j = 0; j < drives_.size(); ++j) {
    const JointDrive& d = drives_[j];
    if (d.kind != JointDrive::Motor) continue;
    const double error = angle_to(static_cast<int>(j), d.target);
    const double command = std::clamp(error / o.approach_time, -d.speed, d.speed);
    dJointSetHingeParam(impl_->hinges[j], dParamVel, command);
  }
  impl_->advance();
}

double OdeSheet::angle(int j) const {
  const Impl& s = *impl_;
  const Eigen::Quaterniond q = s.orientation(s.left[j]).conjugate() * s.orientation(s.right[j]);
  // The twist of the relative rotation about the flat axis (the swing is the hinge's error).
  double a = 2.0 * std::atan2(q.vec().dot(s.axis[j]), q.w());
  if (a > M_PI) a -= 2.0 * M_PI;
  if (a <= -M_PI) a += 2.0 * M_PI;
  return a;
}

double OdeSheet::angle_to(int j, double target) const {
  // The angle reads in (−π, π]: the way to ±π (a complete fold) is the short one around, not
  // back through flat, once the joint has passed π and reads −π + ε.
  return std::remainder(target - angle(j), 2.0 * M_PI);
}

double OdeSheet::rate(int j) const {
  const Impl& s = *impl_;
  const Eigen::Vector3d axis = s.orientation(s.left[j]) * s.axis[j];
  return (s.spin(s.right[j]) - s.spin(s.left[j])).dot(axis);
}

geometry::FoldState OdeSheet::state() const {
  geometry::FoldState st = geometry::FoldState::flat(*impl_->pattern);
  for (Eigen::Index j = 0; j < st.angles.size(); ++j) st.angles[j] = angle(static_cast<int>(j));
  return st;
}

double OdeSheet::torque(int j) const {
  const Impl& s = *impl_;
  if (drives_[j].kind == JointDrive::Free) return 0.0;
  dJointID h = s.hinges[j];
  const dJointFeedback& f = s.feedback[j];
  dVector3 p, a;
  dJointGetHingeAnchor(h, p);
  dJointGetHingeAxis(h, a);
  // The joint's wrench on body 1 moved from its centre of mass to the axis: what is left about
  // the axis is the motor's (or the stop's) torque, the hinge itself transmitting none.
  const Eigen::Vector3d c1 = vec(dBodyGetPosition(dJointGetBody(h, 0)));
  const Eigen::Vector3d moment = vec(f.t1) + (c1 - vec(p)).cross(vec(f.f1));
  return moment.dot(vec(a));
}

double OdeSheet::probe(int j, const JointDrive& drive, double applied, const std::vector<char>& leave_out, double* rate) {
  const EngineScope engine;
  Impl& s = *impl_;
  std::vector<BodyState> saved;
  for (dBodyID b : s.bodies) {
    saved.push_back({vec(dBodyGetPosition(b)), vec(dBodyGetLinearVel(b)), vec(dBodyGetAngularVel(b)),
                     quat(dBodyGetQuaternion(b))});
    dBodySetLinearVel(b, 0, 0, 0);
    dBodySetAngularVel(b, 0, 0, 0);
  }
  // Every other motor holds still too (step() sets their speeds again before the next step).
  for (std::size_t k = 0; k < drives_.size(); ++k)
    if (drives_[k].kind == JointDrive::Motor) dJointSetHingeParam(s.hinges[k], dParamVel, 0.0);
  // The probe step writes every joint's feedback: kept, so that the torques read after the probe
  // (frames, --series, the other motors' stall tests) are the real step's.
  const std::vector<dJointFeedback> feedback(s.feedback.begin(), s.feedback.end());
  const JointDrive kept = drives_[j];
  set_drive(j, drive);
  dJointSetHingeParam(s.hinges[j], dParamVel, 0.0);
  // ODE's hinge torque turns body 1 about the hinge axis: the fold angle up, either way attached.
  if (applied != 0.0) dJointAddHingeTorque(s.hinges[j], applied);
  s.advance(&leave_out);
  const double exerted = torque(j);
  if (rate) *rate = this->rate(j);
  for (std::size_t a = 0; a < s.bodies.size(); ++a) {
    const BodyState& b = saved[a];
    const dQuaternion q = {b.orientation.w(), b.orientation.x(), b.orientation.y(), b.orientation.z()};
    dBodySetPosition(s.bodies[a], b.position.x(), b.position.y(), b.position.z());
    dBodySetQuaternion(s.bodies[a], q);
    dBodySetLinearVel(s.bodies[a], b.linear.x(), b.linear.y(), b.linear.z());
    dBodySetAngularVel(s.bodies[a], b.angular.x(), b.angular.y(), b.angular.z());
  }
  set_drive(j, kept);
  std::copy(feedback.begin(), feedback.end(), s.feedback.begin());
  return exerted;
}

double OdeSheet::hold_torque_signed(int j) {
  const JointDrive hold{JointDrive::Motor, angle(j), 1.0, dInfinity};  // an equality row: no limit
  return probe(j, hold, 0.0, moving_side(j), nullptr);
}

double OdeSheet::released_rate(int j, double applied) {
  double rate = 0.0;
  probe(j, JointDrive{}, applied, std::vector<char>(impl_->bodies.size(), 0), &rate);
  return rate;
}

double OdeSheet::hold_torque(int j) { return std::abs(hold_torque_signed(j)); }

std::vector<char> OdeSheet::moving_side(int j) const {
  const Impl& s = *impl_;
  const int n = static_cast<int>(s.bodies.size()), root = std::max(s.fixed, 0);
  int child = s.right[j] == root ? s.left[j] : s.right[j];
  for (int a = 0; a < n; ++a)
    if (s.tree.parent_joint[a] == j) child = a;
  std::vector<char> side(n, 0);
  for (int a = 0; a < n; ++a)
    for (int x = a; x >= 0 && !side[a]; x = s.tree.parent[x]) side[a] = x == child;
  return side;
}

double OdeSheet::contact_moment(int j, const ContactPoint& c) const {
  const Impl& s = *impl_;
  const std::vector<char> side = moving_side(j);
  const bool on_a = side[c.a], on_b = c.b >= 0 && side[c.b];
  if (on_a == on_b) return 0.0;  // both on it push each other: no moment about j
  const Eigen::Vector3d axis = s.orientation(s.left[j]) * s.axis[j], on_axis = poses()[s.left[j]] * s.anchor[j];
  const Eigen::Vector3d push = on_a ? c.normal : Eigen::Vector3d(-c.normal);
  // A torque about +axis on the right actor's side turns the fold angle up; on the left's, down.
  return (side[s.right[j]] ? 1.0 : -1.0) * (c.point - on_axis).cross(push).dot(axis);
}

const std::vector<ContactPoint>& OdeSheet::contact_points() const {
  static const std::vector<ContactPoint> none;
  return impl_->contacts ? impl_->contacts->points() : none;
}

double OdeSheet::thickness() const { return impl_->contacts ? impl_->contacts->thickness() : 0.0; }

std::vector<Eigen::Isometry3d> OdeSheet::poses() const {
  const Impl& s = *impl_;
  std::vector<Eigen::Isometry3d> out;
  for (std::size_t a = 0; a < s.bodies.size(); ++a) {
    const Eigen::Vector3d c = vec(dBodyGetPosition(s.bodies[a]));
    Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
    m.linear() = s.orientation(static_cast<int>(a)).toRotationMatrix();
    m.translation() = c - m.linear() * s.mass[a].centroid;
    out.push_back(m);
  }
  return out;
}

double OdeSheet::kinetic_energy() const {
  const Impl& s = *impl_;
  double e = 0.0;
  for (std::size_t a = 0; a < s.bodies.size(); ++a) {
    if (static_cast<int>(a) == s.fixed) continue;
    const Eigen::Vector3d v = vec(dBodyGetLinearVel(s.bodies[a])), w = s.spin(static_cast<int>(a));
    const Eigen::Matrix3d R = s.orientation(static_cast<int>(a)).toRotationMatrix();
    e += 0.5 * s.mass[a].mass * v.squaredNorm() + 0.5 * w.dot(R * s.mass[a].inertia * R.transpose() * w);
  }
  return e;
}

double OdeSheet::potential_energy() const {
  const Impl& s = *impl_;
  double e = 0.0;
  for (std::size_t a = 0; a < s.bodies.size(); ++a)
    e -= s.mass[a].mass * gravity_of(s.options).dot(vec(dBodyGetPosition(s.bodies[a])) - s.mass[a].centroid);
  return e;
}

double OdeSheet::spring_energy() const {
  double e = 0.0;
  for (std::size_t j = 0; j < drives_.size(); ++j)
    if (drives_[j].kind == JointDrive::Spring) e += 0.5 * drives_[j].spring * std::pow(angle(static_cast<int>(j)) - drives_[j].target, 2);
  return e;
}

bool OdeSheet::sane() const {
  constexpr double limit = 1e6;  // m/s or rad/s: far beyond anything a folding sheet does
  for (dBodyID b : impl_->bodies) {
    const Eigen::Vector3d p = vec(dBodyGetPosition(b)), v = vec(dBodyGetLinearVel(b)), w = vec(dBodyGetAngularVel(b));
    if (!p.allFinite() || !(v.norm() < limit) || !(w.norm() < limit)) return false;
  }
  return true;
}

double OdeSheet::max_rate() const {
  double m = 0.0;
  for (std::size_t j = 0; j < drives_.size(); ++j) m = std::max(m, std::abs(rate(static_cast<int>(j))));
  return m;
}

}  // namespace foldkit::dynamics::detail
