#pragma once
/// @file
/// Replaying a fold sequence (CMML) on a crease pattern: joint motion under an actuation model,
/// loop-closure and collision checks along the way, and a report of what happened
/// (docs/SIMULATION.md).
#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/geometry/progress.hpp"
#include "foldkit/geometry/status.hpp"
#include "foldkit/simulation/collision_world.hpp"

/// Replaying fold sequences: actuation models, collision detection between facets, clearance,
/// and snapshots of the folding sheet. Angles are radians, times seconds, lengths pattern units.
namespace foldkit::simulation {

/// How the joints of an event move (docs/SIMULATION.md). Joints an event does not name keep
/// their angles.
enum class Actuation {
  Motor,         ///< each joint at its CMML speed until it reaches its angle (the default)
  /// Torsion spring (PMML SpringConst, DampConst, unit inertia) pulling toward the angle; the CMML
  /// speed is not used. A joint with spring constant 0 cannot move: an event that must move
  /// it fails.
  Spring,
  /// All joints of an event arrive together, each moving linearly in time: the event lasts as
  /// long as the joint that needs longest at its own speed.
  Synchronised,
};
/// The model's name: "motor", "spring" or "sync".
const char* to_string(Actuation model);
/// The model named "motor", "spring" or "sync".
/// @throws std::invalid_argument for any other name
Actuation parse_actuation(const std::string& name);

/// Options of simulate(). Every time, angle, sweep and settle value must be positive and finite.
struct SimulationOptions {
  Actuation model = Actuation::Motor;  ///< how joints move
  /// Seconds between steps; the last step of a motor or synchronised event is shorter, so that it
  /// ends exactly when the event does.
  double time_step = 0.01;
  double closure_tolerance = 1e-3;   ///< radians; a larger loop error makes the sequence invalid
  bool collisions = true;            ///< whether crossing facets are looked for (and make the sequence invalid)
  /// Options of the collision world; its margin is replaced by the sweep bound (see max_sweep).
  CollisionOptions collision;
  /// Largest motion of any facet corner between two checks, relative to the smallest triangle
  /// height of the sheet (smallest_feature(), but never less than a thousandth of the pattern's
  /// diagonal); a step that moves more is split into sub-steps.
  double max_sweep = 0.25;
  double max_step_angle = 0.05;      ///< radians per check, at most, for any joint (more: sub-steps)
  /// Spring model: an event ends when its joints are within settle_angle (radians) of their
  /// angles and slower than settle_speed (then they are set to them), or fails after
  /// max_event_time.
  double settle_angle = 1e-5;
  double settle_speed = 1e-4;        ///< spring model: radians per second (see settle_angle)
  double max_event_time = 600.0;     ///< spring model: seconds an event may take before it fails
  bool record_frames = false;        ///< keep the state at every step (for FOLD file_frames)
  /// Steps one motor or synchronised event may take, judged from its planned duration before it
  /// starts (a guard against 1e-9 deg/s; SequenceError beyond it). Positive.
  std::size_t max_steps = 10'000'000;
  std::size_t max_collisions = 1000; ///< collisions (and numerical crossings) listed; the counts go on
  /// Called at every time step: events done (before the current one) of all, unit "events", and
  /// the largest loop error of the last state checked.
  geometry::ProgressFn progress;
};

/// Two actors crossing during the replay.
struct CollisionEvent {
  double time = 0.0;                 ///< when, seconds from the start of the sequence
  int event = 0;                     ///< EventNumber (the first event's for the flat start state)
  std::array<int, 2> actors{};       ///< actor IDs (not indices), in the order of their indices
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< where, in world coordinates (pattern units)
  CrossingKind kind = CrossingKind::Mesh;           ///< how they cross
  double depth = 0.0;                ///< mesh crossings: interpenetration (sheet units), as Crossing::depth
  double closure_error = 0.0;        ///< largest loop error (radians) of the state when it happened
  /// Mesh crossings at a state that does not close (loop error above 1e-9 rad): the depth once
  /// that state is projected onto closure (0 when the crossing is gone there, which makes it
  /// numerical). −1: not rechecked (another kind, a closed state, or the projection failed).
  double closed_depth = -1.0;
  geometry::FoldState state;         ///< the sheet when it happened (for snapshots), one angle per joint
};

/// What happened in one event of the sequence.
struct EventReport {
  int number = 0;                    ///< its EventNumber
  double start = 0.0;                ///< when it started, seconds
  double end = 0.0;                  ///< when it ended, seconds
  double max_closure_error = 0.0;    ///< largest loop error of the states checked in it, radians
  /// False when the spring model did not settle (out of time, or a spring constant of 0).
  bool reached = true;
};

/// The sheet at one moment of the replay.
struct Frame {
  double time = 0.0;                 ///< seconds from the start
  int event = 0;                     ///< EventNumber; −1 for the flat state at time 0
  geometry::FoldState state;         ///< one angle per joint, radians
};

/// What simulate() found.
struct SimulationReport {
  /// StatusCode::Success (valid: closed within the tolerance, no collision, every event
  /// reached), else the code of the first problem: StatusCode::ClosureViolated,
  /// StatusCode::Collision or StatusCode::LimitReached (an event the spring model did not
  /// finish); its message is that problem. ok() is what exit code 3 reports.
  geometry::Status status;
  Actuation model = Actuation::Motor;  ///< the model used
  double time_step = 0.0;              ///< the time step used, seconds
  double duration = 0.0;               ///< time the whole sequence took, seconds
  double max_closure_error = 0.0;      ///< largest loop error of every state checked, radians
  double closure_tolerance = 0.0;      ///< the tolerance used, radians
  std::size_t steps = 0;             ///< time steps
  std::size_t checks = 0;            ///< states checked (steps and their sub-steps, and the flat start)
  std::vector<EventReport> events;   ///< one per event of the sequence, in order
  std::vector<CollisionEvent> collisions;   ///< the first time each pair crossed in each event, up to max_collisions
  std::size_t collision_count = 0;          ///< all of them, also those beyond max_collisions
  /// Mesh crossings that vanish when their state is projected onto closure: artefacts of a state
  /// that does not close (e.g. between two events), not crossings; they do not make the sequence
  /// invalid. The first per pair and event, up to max_collisions (their count: numerical_count).
  std::vector<CollisionEvent> numerical;
  std::size_t numerical_count = 0;          ///< all numerical crossings, also those beyond max_collisions
  std::vector<std::string> problems;        ///< why the sequence is invalid, in words; empty when valid
  /// The flat state at time 0 first, then every step when record_frames, else each event's end.
  std::vector<Frame> frames;
  geometry::FoldState final_state;          ///< the state after the last event
};

/// A fold the simulator cannot replay as given (motor and synchronised models: a speed that is
/// not positive and finite, or an event that would take more than max_steps).
struct SequenceError : std::invalid_argument {
  /// An error at CMML line `line_` (0 when unknown), with message `what`.
  SequenceError(int line_, const std::string& what) : std::invalid_argument(what), line(line_) {}
  int line;  ///< the fold's CMML line (for max_steps: the event's first fold); 0 when unknown
};

/// Replays `sequence` on `pattern` from the flat state, checking every state on the way (closure,
/// and collisions when asked); problems are reported in the result, not thrown.
/// @param pattern   the crease pattern
/// @param sequence  its fold sequence (angles in radians, velocities in radians per second)
/// @param options   actuation model, step sizes, tolerances and limits
/// @throws std::invalid_argument for options out of range (a time, tolerance, sweep, step angle or
///         settle value that is not positive and finite; max_steps 0; an invalid collision
///         tolerance when collisions are checked) or a sequence that names joints the pattern
///         lacks (run geometry::check_sequence first)
/// @throws SequenceError as above, when the replay reaches that event
SimulationReport simulate(const geometry::CreasePattern& pattern, const geometry::FoldSequence& sequence,
                          const SimulationOptions& options = {});

/// simulate() fed one event at a time, for a caller that makes the sequence while it is replayed
/// (planners: the replay of a plan runs on another thread while its waypoints are computed). The
/// same events in the same order give the same report as simulate() of the whole sequence.
/// Not safe for several threads at once; it may be used from any one thread at a time.
class SequenceReplay {
 public:
  /// A replay of `pattern` (kept by reference: it must outlive the replay) with `options` (copied),
  /// from the flat state.
  /// @throws std::invalid_argument for options out of range (as simulate())
  SequenceReplay(const geometry::CreasePattern& pattern, const SimulationOptions& options = {});
  ~SequenceReplay();  ///< Frees the replay.
  SequenceReplay(const SequenceReplay&) = delete;             ///< Not copyable.
  SequenceReplay& operator=(const SequenceReplay&) = delete;  ///< Not copyable.

  /// Replays the next event from the state the events before it left (the first from flat).
  /// @param event  the event (angles in radians, velocities in radians per second)
  /// @param known  how many events the progress reports as the whole sequence (options.progress)
  /// @throws SequenceError as simulate(), and the replay is then spent; std::logic_error after
  ///         finish() or such an error
  void add(const geometry::FoldEvent& event, std::size_t known);
  /// The report of every event added, as simulate() of their sequence returns it; the replay is
  /// then spent.
  /// @throws std::logic_error when called a second time
  SimulationReport finish();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Smallest height over the sheet's triangles (pattern units): the length the sweep bound is
/// relative to. Infinity for a pattern without triangles.
double smallest_feature(const geometry::CreasePattern& pattern);

}  // namespace foldkit::simulation
