#pragma once
// The scene of issue 33's checks and targets: a Miura-ori n × n folded by one motor, gravity off.
// The kinematic fold to half way (folding::fold_projected, what `foldkit fold` runs: closure only,
// no replay) is the oracle; the motor drives the fixed actor's most folded crease to its angle
// there. The dynamic run starts from the kinematic path's first state folded 0.2 rad or more: the
// flat sheet is a bifurcation, where one motor does not decide which way the other creases go.
// Shared by the dynamics spike (measure_dynamics*), bench_dynamics and test/dynamics.
#include <cmath>
#include <stdexcept>

#include <Eigen/Core>

#include "foldkit/folding/projected_folding.hpp"
#include "foldkit/geometry/generators.hpp"

namespace foldkit::microbench {

struct OneMotorMiura {
  geometry::CreasePattern pattern;
  folding::ProjectedFoldingResult kinematic;  ///< the oracle; kinematic.states.back() its end
  int drive = -1;                             ///< index of the driven joint
  Eigen::VectorXd start;                      ///< where the dynamic run starts, radians
  geometry::FoldSequence sequence;            ///< one event: the driven joint to its end angle
};

/// The scene at size n, the motor turning at `speed` rad/s; `drive` ≥ 0 picks another joint (index).
inline OneMotorMiura one_motor_miura(int n, double speed = 0.5, int drive = -1) {
  OneMotorMiura s{geometry::build_or_throw(geometry::generators::miura(n, n)), {}, drive, {}, {}};
  folding::ProjectedFoldingOptions fo;
  fo.target_fraction = 0.5;
  fo.replay = false;
  fo.collisions = false;
  fo.speed = speed;
  s.kinematic = folding::fold_projected(s.pattern, fo);
  if (!s.kinematic.status.ok()) throw std::runtime_error("one_motor_miura: " + s.kinematic.status.message);
  const geometry::FoldState& end = s.kinematic.states.back();
  int best = -1;
  for (int j = 0; j < static_cast<int>(s.pattern.joints().size()); ++j) {
    const auto& a = s.pattern.joints()[j].actors;
    if ((a[0] == 0 || a[1] == 0) && (best < 0 || std::abs(end.angles[j]) > std::abs(end.angles[best]))) best = j;
  }
  if (s.drive < 0) s.drive = best;
  for (const auto& st : s.kinematic.states)
    if (st.angles.cwiseAbs().maxCoeff() >= 0.2) {
      s.start = st.angles;
      break;
    }
  s.sequence.events.push_back({1, {{s.pattern.joints()[s.drive].id, end.angles[s.drive], speed, 0}}});
  return s;
}

}  // namespace foldkit::microbench
