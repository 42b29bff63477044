#pragma once
/// @file
/// Fold sequences (CMML, paper Table 2): timed events that drive joints to target angles.
#include <optional>
#include <string>
#include <vector>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/diagnostics.hpp"
#include "foldkit/geometry/fold_state.hpp"

namespace foldkit::geometry {

/// A CMML fold (Table 2): drive joint `joint_id` to `angle` at `speed` (the file's
/// `<Velocity>`). CMML files hold degrees; here both are radians.
struct FoldCommand {
  int joint_id = 0;       ///< the joint's ID (not its index)
  double angle = 0.0;     ///< target fold angle, radians
  double speed = 0.0;     ///< how fast it turns towards it, radians per second (> 0); the CMML's Velocity
  int line = 0;           ///< source line; 0 when not read from a file
};

/// Folds that share an EventNumber: they run together.
struct FoldEvent {
  int number = 0;                  ///< the CMML EventNumber
  std::vector<FoldCommand> folds;  ///< in file order
};

/// Events in increasing EventNumber; every sequence starts from the flat state.
struct FoldSequence {
  std::string title;              ///< free text
  std::vector<FoldEvent> events;  ///< in increasing number
};

/// Groups folds into events by number, events in increasing number and folds in their given
/// order within an event.
/// @param title          the sequence's title
/// @param numbered_folds pairs (EventNumber, fold)
FoldSequence make_sequence(std::string title, std::vector<std::pair<int, FoldCommand>> numbered_folds);

/// Checks a sequence against its pattern: joint IDs the pattern lacks, a joint folded twice in
/// one event. Every finding is an error, located at the fold's line.
Diagnostics check_sequence(const CreasePattern& pattern, const FoldSequence& sequence);

/// The state after each event, angles carried through from the flat state: size = events + 1,
/// element 0 flat. Folds of unknown joints are skipped; run check_sequence() first.
std::vector<FoldState> event_states(const CreasePattern& pattern, const FoldSequence& sequence);

/// The state after the last event (the flat state for a sequence without events).
FoldState end_state(const CreasePattern& pattern, const FoldSequence& sequence);

/// A one-event sequence (event 1) that takes the flat sheet to `state`, every fold at
/// `speed` (radians per second); joints at 0 are left out, so a flat state gives no event.
/// @param pattern   the pattern `state` belongs to
/// @param state     one angle per joint, radians
/// @param speed     speed of every fold, radians per second
/// @param title     the sequence's title
FoldSequence sequence_to(const CreasePattern& pattern, const FoldState& state, double speed,
                         std::string title = {});

/// One event per waypoint (flat → waypoints[0] → waypoints[1] → …, events numbered from 1),
/// naming the joints that move; a waypoint equal to the one before adds no event. Within an
/// event the fastest joint turns at `max_speed` and every other one at the speed that makes
/// it arrive at the same moment (at least 1e-9 rad/s), so motor replay follows the straight line
/// between waypoints in angle space: close waypoints on the closure manifold then keep loops
/// closed.
/// @param pattern       the pattern the waypoints belong to
/// @param waypoints     states with one angle per joint, radians
/// @param max_speed     speed of the fastest joint in each event, radians per second
/// @param title         the sequence's title
/// @throws std::invalid_argument when `max_speed` is not positive and finite, or a waypoint
///         does not hold one angle per joint
FoldSequence path_sequence(const CreasePattern& pattern, const std::vector<FoldState>& waypoints, double max_speed,
                           std::string title = {});

/// path_sequence()'s event from `from` to `to` (the next waypoint), numbered `number`: for a
/// caller that makes the events one waypoint at a time (a plan replayed while it is computed).
/// @param pattern    the pattern the states belong to
/// @param from       the state the event starts from (flat for the first), radians
/// @param to         the waypoint it moves to, radians
/// @param max_speed  speed of the fastest joint, radians per second
/// @param number     the event's number
/// @return the event, or nothing when no joint moves (path_sequence() then adds none)
/// @throws std::invalid_argument as path_sequence()
std::optional<FoldEvent> path_event(const CreasePattern& pattern, const FoldState& from, const FoldState& to, double max_speed,
                                    int number);

}  // namespace foldkit::geometry
