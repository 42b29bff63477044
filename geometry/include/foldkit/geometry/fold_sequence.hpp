#pragma once
#include <string>
#include <vector>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/diagnostics.hpp"
#include "foldkit/geometry/fold_state.hpp"

namespace foldkit::geometry {

// A CMML fold (Table 2): drive joint `joint_id` to `angle` at `velocity` (both in radians).
struct FoldCommand {
  int joint_id = 0;
  double angle = 0.0;
  double velocity = 0.0;
  int line = 0;
};

// Folds that share an EventNumber run together.
struct FoldEvent {
  int number = 0;
  std::vector<FoldCommand> folds;
};

// Events in increasing EventNumber; every sequence starts from the flat state.
struct FoldSequence {
  std::string title;
  std::vector<FoldEvent> events;
};

// Groups folds into events by number (stable within an event).
FoldSequence make_sequence(std::string title, std::vector<std::pair<int, FoldCommand>> numbered_folds);

// Checks a sequence against its pattern: unknown joint IDs, a joint twice in one event.
Diagnostics check_sequence(const CreasePattern& pattern, const FoldSequence& sequence);

// The state after each event, angles carried through from the flat state (size = events + 1,
// element 0 flat). Unknown joints are skipped; run check_sequence() first.
std::vector<FoldState> event_states(const CreasePattern& pattern, const FoldSequence& sequence);

FoldState end_state(const CreasePattern& pattern, const FoldSequence& sequence);

// A one-event sequence that takes the flat sheet to `state` (joints at 0 left out).
FoldSequence sequence_to(const CreasePattern& pattern, const FoldState& state, double velocity,
                         std::string title = {});

// One event per waypoint (flat → waypoints[0] → waypoints[1] → …), naming the joints that move.
// Within an event the fastest joint turns at `max_velocity` and every other one at the speed
// that makes it arrive at the same moment, so motor replay follows the straight line between
// waypoints in angle space: close waypoints on the closure manifold then keep loops closed.
FoldSequence path_sequence(const CreasePattern& pattern, const std::vector<FoldState>& waypoints, double max_velocity,
                           std::string title = {});

}  // namespace foldkit::geometry
