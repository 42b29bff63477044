#pragma once
// The sheet as ODE bodies and hinges (private: no header outside this library sees ODE).
#include <memory>
#include <stdexcept>
#include <vector>

#include <Eigen/Geometry>

#include "foldkit/dynamics/dynamic_simulate.hpp"
#include "foldkit/dynamics/mass_properties.hpp"
#include "ode_contacts.hpp"

namespace foldkit::dynamics::detail {

// ODE reported an internal error (its error and debug handlers throw this instead of aborting, on a
// thread inside one of OdeSheet's engine calls; the constructor, set_drive(), step(), place(),
// set_rates() and the probes hold_torque*() and released_rate() throw it).
struct EngineError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// How one joint is driven at the moment.
struct JointDrive {
  enum Kind { Free, Motor, Spring } kind = Free;
  double target = 0.0;      // radians
  double speed = 0.0;       // motor: rad/s
  double max_torque = 0.0;  // motor: N·m
  double spring = 0.0;      // N·m/rad
  double damping = 0.0;     // N·m·s/rad
};

// One ODE world holding the sheet: a body per actor (the fixed one kinematic), a hinge per joint,
// attached so that ODE's hinge angle is foldkit's fold angle (right actor relative to left), and
// the contacts when the options ask for them. `fixed` is the held actor's index, −1 for none.
// Keeps a pointer to `pattern`, which must outlive it.
class OdeSheet {
 public:
  OdeSheet(const geometry::CreasePattern& pattern, const DynamicOptions& options, int fixed);
  ~OdeSheet();
  OdeSheet(const OdeSheet&) = delete;
  OdeSheet& operator=(const OdeSheet&) = delete;

  // Sets joint index `j`'s drive (applied from the next step).
  void set_drive(int j, const JointDrive& drive);
  const JointDrive& drive(int j) const { return drives_[j]; }
  // One engine step: motor speeds from the current errors, then the solver.
  // Throws EngineError when ODE reports an internal error (a NaN, a singular body).
  void step();
  // Fold angle and its rate of joint index j, from the bodies' poses (radians, rad/s).
  double angle(int j) const;
  // The signed angle from joint j's angle to `target` the short way round, in [−π, π] (radians).
  double angle_to(int j, double target) const;
  double rate(int j) const;
  geometry::FoldState state() const;
  // Moves every body but the root (the fixed actor, or actor 0 when none is held) to its pose in
  // `state` (one angle per joint, radians) relative to the root's current pose; velocities are
  // kept. What the start state and post-stabilisation (post_stabilise.hpp) place the sheet with.
  void place(const geometry::FoldState& state);
  // Sets every body's velocity but the root's from joint rates (rad/s, one per joint, as rate()
  // reads them) down the kinematic tree: consistent with the hinges, and with the loops when the
  // rates are.
  void set_rates(const Eigen::VectorXd& rates);
  // Torque the joint's motor or spring exerted in the last step, about its axis, N·m.
  double torque(int j) const;
  // Torque joint j needs to hold the current pose with the sheet at rest and every motor holding
  // still (a probe step with its limit lifted; every body's state is restored afterwards), N·m,
  // absolute. The contacts of j's moving side are left out (what the joint must carry without
  // their help: a ground under a flap would carry its weight), and the others push no penetration
  // apart (a probe holding still against that would read any torque).
  double hold_torque(int j);
  // The same, signed as torque() reads it.
  double hold_torque_signed(int j);
  // Joint j's rate after one probe step from rest with its drive replaced by the constant torque
  // `applied` (N·m, signed as torque()), every motor holding still and every contact in (pushing
  // no penetration apart); every body's state is restored afterwards. rad/s: what the contacts
  // let that torque start, where hold_torque() cannot tell how much of it they carry.
  double released_rate(int j, double applied);
  // Actors on joint j's moving side (per actor index, 1 on it): those beyond j from the root in
  // the kinematic tree (for a joint closing a loop, the right actor's subtree, or the left's when
  // the right is the root).
  std::vector<char> moving_side(int j) const;
  // The moment about joint j's axis with which contact c pushes j's moving side, per newton of
  // its normal force, signed as the fold angle: positive turns j toward larger angles, metres.
  // 0 when neither of c's actors is on that side or both are.
  double contact_moment(int j, const ContactPoint& c) const;
  // The contact points of the last step (empty without contacts).
  const std::vector<ContactPoint>& contact_points() const;
  // The sheet's thickness for contacts, metres (0 without contacts).
  double thickness() const;
  // Pose of each actor from its flat position (metres).
  std::vector<Eigen::Isometry3d> poses() const;
  double kinetic_energy() const;
  double potential_energy() const;  // relative to the flat sheet
  double spring_energy() const;
  // Whether every body's state is finite and slower than a blow-up.
  bool sane() const;
  // Largest |rate| over all joints.
  double max_rate() const;

 private:
  // One probe step from rest with joint j's drive replaced by `drive` and `applied` N·m added at
  // it, the other motors holding still, the contacts of the actors `leave_out` marks left out;
  // returns j's drive torque in it (and its rate after it in *rate, when given) and restores
  // every body's state, the drive and the joints' feedback.
  double probe(int j, const JointDrive& drive, double applied, const std::vector<char>& leave_out, double* rate);

  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<JointDrive> drives_;
};

}  // namespace foldkit::dynamics::detail
