#pragma once
#include <string>
#include <vector>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/simulation/simulate.hpp"

namespace foldkit::simulation::detail {

// The joints of one event on their way to their angles; joints the event does not name keep
// theirs.
class EventMotion {
 public:
  EventMotion(const geometry::CreasePattern& pattern, const geometry::FoldEvent& event,
              const geometry::FoldState& start, const SimulationOptions& options);

  bool done() const { return done_; }
  bool reached() const { return reached_; }
  const std::string& failure() const { return failure_; }
  // Moves `state` on by at most `dt` seconds; returns the time it moved.
  double advance(geometry::FoldState& state, double dt);
  // Time the motor and synchronised models take (the spring model: unknown, 0).
  double planned_duration() const { return duration_; }

 private:
  struct Drive {
    Eigen::Index joint;
    double start, target, speed;  // speed: radians per second (motor, synchronised)
    double spring, damping;
    double rate = 0.0;            // angular velocity (spring model)
  };
  void settle(geometry::FoldState& state);

  Actuation model_;
  const SimulationOptions* options_;
  std::vector<Drive> drives_;
  double duration_ = 0.0;
  double elapsed_ = 0.0;
  bool done_ = false;
  bool reached_ = true;
  std::string failure_;
};

}  // namespace foldkit::simulation::detail
