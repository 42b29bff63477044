#pragma once
/// @file
/// Dynamic replay of a fold sequence on a physics engine (ODE, private to this library): each
/// actor a rigid lamina, each joint a hinge, events driven by torque-limited motors or torsion
/// springs, under gravity (docs/SIMULATION.md, "Dynamic simulation").
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/geometry/progress.hpp"
#include "foldkit/geometry/status.hpp"
#include "foldkit/simulation/simulate.hpp"

/// Dynamic fold simulation. Units: SI. Lengths in the pattern are multiplied by
/// DynamicOptions::scale to give metres; masses kilograms, times seconds, torques N·m, angles
/// radians (0 flat, positive mountain, as everywhere in foldkit).
namespace foldkit::dynamics {

/// The model's name as `foldkit simulate --model` and Python's `model=` spell it: "dynamic".
/// simulation::parse_actuation() knows only the kinematic models; callers test for this name
/// first (simulation does not depend on this library).
inline constexpr const char* kModelName = "dynamic";
/// Every model `foldkit simulate --model` (and Python's `model=`) takes, in the order help lists
/// them: simulation's actuation models (simulation::to_string()), then kModelName.
std::vector<std::string> model_names();

/// What drives the joints an event names.
enum class Drive {
  /// A velocity-controlled motor (the paper's Sec. 4.3): it turns its joint toward the CMML angle
  /// at the CMML speed with at most DynamicOptions::max_torque, and holds the angle afterwards.
  Motor,
  /// A torsion spring −k(θ−θ*) − cθ̇ with the PMML SpringConst k (N·m/rad) and DampConst c
  /// (N·m·s/rad), θ* the CMML angle; integrated implicitly (stable for every k).
  Spring,
};
/// "motor" or "spring".
const char* to_string(Drive drive);
/// The drive named "motor" or "spring".
/// @throws std::invalid_argument for any other name
Drive parse_drive(const std::string& name);

/// How the engine solves the joint constraints at each step.
enum class Solver {
  Iterative,  ///< ODE's dWorldQuickStep (projected Gauss–Seidel, DynamicOptions::iterations sweeps)
  Direct,     ///< ODE's dWorldStep (dense LCP: exact, cubic in the constraint rows)
};
/// "iterative" or "direct" (`foldkit simulate --solver`).
const char* to_string(Solver solver);
/// The solver named "iterative" or "direct".
/// @throws std::invalid_argument for any other name
Solver parse_solver(const std::string& name);

/// Coulomb coefficient μ of every contact when DynamicOptions::friction is empty.
inline constexpr double kDefaultFriction = 0.5;

/// Areal density of the sheet, kg/m², when neither DynamicOptions::density nor the pattern's
/// PMML `<Density>` gives one.
inline constexpr double kDefaultDensity = 1.0;

/// Options of simulate_dynamic(): every default of the dynamic model, once. Density, gravity and
/// the fixed actor may also come from the pattern's file (foldkit's PMML extensions,
/// geometry::CreasePattern::physics()): an option set here overrides the file, and the file
/// overrides the default named here (resolve_options()).
struct DynamicOptions {
  /// Areal density of the sheet, kg/m² (positive, finite); empty: the pattern's `<Density>`, else
  /// kDefaultDensity.
  std::optional<double> density;
  /// Torque limit of every motor without its own (PMML `<MaxTorque>`, joint_max_torque), N·m
  /// (positive, finite).
  double max_torque = 1.0;
  /// Torque limits of some motors, N·m (positive, finite), by joint ID (a joint the pattern
  /// has): over the pattern's `<MaxTorque>`; the others have that, else max_torque.
  std::map<int, double> joint_max_torque;
  /// m/s², world axes of the flat sheet (finite); empty: the pattern's `<Gravity>`, else none.
  std::optional<Eigen::Vector3d> gravity;
  /// Actor ID of the actor held in place (kinematic: it never moves); empty: the pattern's
  /// `<FixedActor>`, else the first actor.
  std::optional<int> fixed_actor;
  /// false: no actor is held (fixed_actor ignored): the whole sheet moves, e.g. on the ground.
  bool hold_fixed = true;
  /// Height of a ground plane z = ground (metres, world axes of the flat sheet, normal +z; tilt
  /// gravity for an incline); empty: none. The facets touching it get contacts with friction.
  std::optional<double> ground;
  /// Facet–facet contacts (with friction): facets not joined by a crease push each other apart
  /// instead of passing through. Off: no collision space is built (unless ground asks for one).
  bool contacts = false;
  /// Coulomb coefficient μ of every contact (≥ 0, finite); empty: kDefaultFriction. Given, it
  /// needs contacts or ground (else nothing would use it).
  std::optional<double> friction;
  /// Thickness of the sheet for contacts, metres: each facet is a prism this thick about its
  /// mid-surface (a zero-thickness sheet has no stable contact); empty: 1e-3 of the sheet's
  /// bounding-box diagonal times scale. Positive and finite; given, it needs contacts or ground.
  std::optional<double> thickness;
  double scale = 1.0;        ///< metres per pattern unit (positive, finite)
  /// The state the sheet starts from, at rest (one angle per joint, radians, closed: its loop
  /// error at most closure_tolerance); empty: flat. The flat sheet is a bifurcation point where
  /// one motor does not decide which way the other creases go; a state past it does.
  Eigen::VectorXd start;
  Drive drive = Drive::Motor;  ///< what drives the joints an event names
  double time_step = 1e-3;   ///< seconds per engine step (positive; at most approach_time and stall_time)
  Solver solver = Solver::Direct;  ///< how the engine solves the constraints
  int iterations = 100;      ///< Gauss–Seidel sweeps per step of Solver::Iterative (≥ 1)
  /// Share of the joints' position error the engine corrects per step (ODE's ERP, in (0, 1]):
  /// what keeps the hinges, and so the closed loops, from drifting.
  double erp = 0.2;
  double cfm = 1e-10;        ///< constraint force mixing (ODE's CFM, ≥ 0): softness of the hinges
  /// Seconds between post-stabilisations (≥ 0; 0: none): after such a step the angles read off
  /// the bodies are projected onto the closure manifold (geometry::project, the motor-driven
  /// joints held), the bodies placed there and their velocities set to the nearest joint rates
  /// that keep the loops closed. What lets Solver::Iterative's few sweeps keep the loops closed.
  /// The closure checks then see the corrected poses; DynamicReport::max_corrected_error is what
  /// the engine's steps left before the corrections.
  double projection_interval = 0.0;
  /// A motor commands speed min(CMML speed, |θ* − θ| / approach_time) toward its angle, seconds:
  /// it slows down exponentially over the last approach_time·speed radians and holds there.
  double approach_time = 0.02;
  double reach_tolerance = 1e-4;  ///< radians: a motor within this of its angle has reached it
  /// Spring drive: an event ends when every joint turns slower than this (rad/s) …
  double settle_speed = 1e-3;
  /// … for this long (seconds), and every spring's static torque k(θ* − θ) is what holding the
  /// sheet at rest there needs without the contacts on its moving side, within k·reach_tolerance,
  /// or the rest is carried by a contact pushing against the spring (else it is still on its way:
  /// a soft spring starts slowly).
  double settle_time = 0.1;
  /// A motor that is not within reach_tolerance, makes less than a hundredth of its speed of
  /// progress and uses its full torque for this long (seconds) has stalled when holding the sheet
  /// at rest where it is, without the contacts on its moving side, would need more than its
  /// torque; it is blocked when it would not, and a contact there pushes against it (else it was
  /// a transient, such as braking an overshoot, and it goes on). A motor that comes no closer to
  /// its angle for this long (swinging under gravity, say) has stalled when, where it came
  /// closest, it could not hold the sheet.
  double stall_time = 0.1;
  double max_event_time = 60.0;   ///< seconds an event may take before it fails (LimitReached)
  double closure_tolerance = 1e-3;  ///< radians; a larger loop error of the engine's poses fails the sequence
  double check_interval = 0.01;   ///< seconds between closure checks (and frames)
  bool record_frames = false;     ///< keep the state every check_interval (for FOLD file_frames)
  /// Called at every check: events done (before the current one) of all, unit "events", and the
  /// closure error of the state checked.
  geometry::ProgressFn progress;
};

/// A joint that did not reach its angle.
struct Stall {
  int joint = 0;               ///< joint ID
  int event = 0;               ///< EventNumber
  double time = 0.0;           ///< when it was found, seconds from the start
  double angle = 0.0;          ///< the joint's angle then, radians
  double target = 0.0;         ///< the angle it was driven to, radians
  /// Torque the joint needs to hold its current pose (N·m, absolute): the engine's answer with
  /// the joint's limit lifted, the sheet at rest, every other motor holding still and the
  /// contacts of the joint's moving side left out (their help not counted). For a motor that
  /// swung back and forth, where it came closest to its target (the message says so).
  double needed_torque = 0.0;
  double available_torque = 0.0;  ///< the motor's limit (spring drive: k·|θ* − θ|), N·m
  /// Actor IDs of the contact that blocks it (a collision: holding the sheet there needs no more
  /// than its torque, but the facets, or a facet and the ground, push back); empty: its torque
  /// was too small. A ground contact names one actor.
  std::vector<int> blocked_by;
};

/// Two facets (or a facet and the ground) that touched.
struct Contact {
  std::vector<int> actors;      ///< actor IDs: two facets, smaller index first; one for the ground
  bool ground = false;          ///< whether the second side is the ground plane
  int event = 0;                ///< EventNumber when they first touched
  double time = 0.0;            ///< seconds, when they first touched
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< where they first touched, world metres
  double max_penetration = 0.0;  ///< deepest overlap of their prisms over the run, metres
};

/// What happened in one event.
struct DynamicEventReport {
  int number = 0;               ///< its EventNumber
  double start = 0.0;           ///< seconds
  double end = 0.0;             ///< seconds
  bool reached = true;          ///< whether every joint it names reached its angle
  double max_closure_error = 0.0;  ///< largest loop error of the engine's poses checked in it, radians
  double energy = 0.0;          ///< kinetic + gravitational + spring energy at its end, joules
};

/// Per joint over the whole run.
struct JointReport {
  int id = 0;                   ///< joint ID
  double peak_torque = 0.0;     ///< largest |torque| its motor or spring exerted, N·m (0: free hinge)
  double angle = 0.0;           ///< final angle, radians
};

/// What simulate_dynamic() found.
struct DynamicReport {
  /// Success when every event reached its angles and the loops stayed closed within the
  /// tolerance; otherwise NoProgress (a stall), Collision (a motor or spring blocked by a
  /// contact, or two prisms overlapping by more than the thickness: passed through),
  /// LimitReached (max_event_time), ClosureViolated or Singular (the engine's state blew up, or
  /// the engine reported an error: the message names a smaller time step).
  geometry::Status status;
  double time_step = 0.0;          ///< seconds
  double duration = 0.0;           ///< simulated seconds
  double seconds = 0.0;            ///< wall-clock seconds the engine ran
  std::size_t steps = 0;           ///< engine steps
  double max_closure_error = 0.0;  ///< largest loop error of the engine's poses (ClosureSystem), radians
  /// Largest loop error of the engine's poses just before a post-stabilisation corrected them
  /// (DynamicOptions::projection_interval), radians: the drift the solver leaves in one interval.
  /// 0 without post-stabilisation.
  double max_corrected_error = 0.0;
  /// Post-stabilisations that found no closed state near the engine's (the loops then stay as the
  /// engine left them, and the closure checks judge them): 0 when every correction closed.
  std::size_t failed_corrections = 0;
  double closure_tolerance = 0.0;  ///< radians
  std::vector<DynamicEventReport> events;  ///< one per event run, in order
  std::vector<Stall> stalls;       ///< joints that stalled (the run stops at the first event with any)
  std::vector<JointReport> joints;  ///< one per joint, in pattern order
  double kinetic_energy = 0.0;     ///< at the end, joules
  double potential_energy = 0.0;   ///< gravitational, at the end, relative to the flat sheet, joules
  double spring_energy = 0.0;      ///< ½k(θ−θ*)² of the spring-driven joints at the end, joules
  double peak_kinetic_energy = 0.0;  ///< joules
  std::vector<std::string> problems;  ///< why the sequence failed, in words; empty on success
  /// Every pair that touched (DynamicOptions::contacts, ground), in the order they first did.
  std::vector<Contact> contacts;
  double max_penetration = 0.0;    ///< deepest overlap of any contact, metres (0 without contacts)
  double thickness = 0.0;          ///< the sheet's thickness for contacts, metres (0: no contacts)
  /// The flat state at time 0, then every check_interval when record_frames, else each event's end.
  std::vector<simulation::Frame> frames;
  /// Per frame, the torque each joint's motor or spring exerted in the step before it (N·m, signed
  /// like the fold angle; 0 for free hinges and at time 0): one vector per entry of frames.
  std::vector<Eigen::VectorXd> frame_torques;
  geometry::FoldState final_state;   ///< the engine's angles at the end
};

/// `options` with what they leave empty filled in as simulate_dynamic() runs them: density and
/// gravity from the pattern's file (geometry::CreasePattern::physics()) or the defaults
/// (kDefaultDensity, none), and fixed_actor, when an actor is held, from the file or the first
/// actor. What a report of the run should name as its settings.
DynamicOptions resolve_options(const geometry::CreasePattern& pattern, DynamicOptions options);

/// Runs `sequence` on `pattern` in the physics engine from the resting sheet at options.start,
/// with resolve_options(pattern, options).
/// @throws std::invalid_argument for options out of range (a density, torque, scale, time or
///         tolerance that is not positive and finite, a time step above approach_time or
///         stall_time, gravity, ground, friction or thickness not finite (friction negative,
///         thickness not positive), friction or thickness given with neither contacts nor
///         ground, an unknown fixed
///         actor, iterations < 1, erp outside (0, 1], a negative or non-finite
///         projection_interval, a start state of the wrong size, not finite
///         or not closed) or a sequence naming joints the pattern lacks
/// @throws simulation::SequenceError for a fold whose speed is not positive and finite, or (spring
///         drive) a joint with neither spring nor damping constant
DynamicReport simulate_dynamic(const geometry::CreasePattern& pattern, const geometry::FoldSequence& sequence,
                               const DynamicOptions& options = {});

}  // namespace foldkit::dynamics
