#pragma once
#include <array>
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

namespace foldkit::simulation {

// How the joints of an event move (docs/SIMULATION.md).
enum class Actuation {
  Motor,         // each joint at its CMML velocity until it reaches its angle (the default)
  Spring,        // torsion spring (PMML SpringConst, DampConst) pulling toward the angle
  Synchronised,  // all joints of an event arrive together, the slowest at its own velocity
};
const char* to_string(Actuation model);
// "motor", "spring", "sync"; throws std::invalid_argument for anything else.
Actuation parse_actuation(const std::string& name);

struct SimulationOptions {
  Actuation model = Actuation::Motor;
  double time_step = 0.01;           // seconds between steps
  double closure_tolerance = 1e-3;   // radians; a larger loop error makes the sequence invalid
  bool collisions = true;
  CollisionOptions collision;        // its margin is set from max_sweep
  // Largest motion of any facet corner between two checks, relative to the smallest triangle
  // height of the sheet; a step that moves more is split into sub-steps.
  double max_sweep = 0.25;
  double max_step_angle = 0.05;      // radians per check, at most, for any joint
  // Spring model: an event ends when its joints are within settle_angle of their angles and
  // slower than settle_speed (then they are set to them), or fails after max_event_time.
  double settle_angle = 1e-5;
  double settle_speed = 1e-4;
  double max_event_time = 600.0;
  bool record_frames = false;        // keep the state at every step (for FOLD file_frames)
  std::size_t max_steps = 10'000'000; // steps one event may take (a guard against 1e-9 deg/s)
  std::size_t max_collisions = 1000; // collisions listed; the count goes on
  geometry::ProgressFn progress;     // per step: events done of all, closure error of the state
};

struct CollisionEvent {
  double time = 0.0;
  int event = 0;                     // EventNumber
  std::array<int, 2> actors{};       // actor IDs
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  CrossingKind kind = CrossingKind::Mesh;
  double depth = 0.0;                // mesh crossings: interpenetration (sheet units), as Crossing::depth
  double closure_error = 0.0;        // largest loop error (radians) of the state when it happened
  // Mesh crossings at a state that does not close: the depth once that state is projected onto
  // closure (0 when the crossing is gone there, which makes it numerical). −1: not rechecked.
  double closed_depth = -1.0;
  geometry::FoldState state;         // the sheet when it happened (for snapshots)
};

struct EventReport {
  int number = 0;
  double start = 0.0;
  double end = 0.0;
  double max_closure_error = 0.0;
  bool reached = true;               // false when the spring model ran out of time
};

struct Frame {
  double time = 0.0;
  int event = 0;
  geometry::FoldState state;
};

struct SimulationReport {
  // Success (valid: closed within the tolerance, no collision, every event reached), else the
  // code of the first problem: ClosureViolated, Collision or LimitReached (an event the spring
  // model did not finish); its message is that problem. ok() is what exit code 3 reports.
  geometry::Status status;
  Actuation model = Actuation::Motor;
  double time_step = 0.0;
  double duration = 0.0;
  double max_closure_error = 0.0;
  double closure_tolerance = 0.0;
  std::size_t steps = 0;             // time steps
  std::size_t checks = 0;            // states checked (steps and their sub-steps)
  std::vector<EventReport> events;
  std::vector<CollisionEvent> collisions;   // the first time each pair crossed in each event
  std::size_t collision_count = 0;          // all of them, also those beyond max_collisions
  // Mesh crossings that vanish when their state is projected onto closure: artefacts of a state
  // that does not close (e.g. between two events), not crossings; they do not make the sequence
  // invalid. The first per pair and event, up to max_collisions, and their count.
  std::vector<CollisionEvent> numerical;
  std::size_t numerical_count = 0;
  std::vector<std::string> problems;        // why the sequence is invalid, in words
  std::vector<Frame> frames;                // every step when record_frames, else each event's end
  geometry::FoldState final_state;
};

// A fold the simulator cannot replay as given (a velocity that is not positive and finite, or an
// event that would take more than max_steps); `line` is its CMML line (0 when unknown).
struct SequenceError : std::invalid_argument {
  SequenceError(int line_, const std::string& what) : std::invalid_argument(what), line(line_) {}
  int line;
};

// Replays `sequence` on `pattern` from the flat state. Throws std::invalid_argument for options
// out of range or a sequence that names joints the pattern lacks (check_sequence first), and
// SequenceError as above.
SimulationReport simulate(const geometry::CreasePattern& pattern, const geometry::FoldSequence& sequence,
                          const SimulationOptions& options = {});

// Smallest height over the sheet's triangles: the length the sweep bound is relative to.
double smallest_feature(const geometry::CreasePattern& pattern);

}  // namespace foldkit::simulation
