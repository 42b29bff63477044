// A planar chain's frames as CMML: each joint's turning angle, one event per frame.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "foldkit/folding/carpenter.hpp"

namespace foldkit::folding {

geometry::FoldSequence turning_angle_sequence(const std::vector<Frame2>& frames, bool closed, std::string title) {
  // Within an event every joint arrives together, the fastest turning at 1 rad/s; CMML needs a
  // positive speed even for a joint that does not move.
  constexpr double kFastest = 1.0, kSlowest = 1e-6;
  geometry::FoldSequence sequence;
  sequence.title = std::move(title);
  std::vector<double> previous;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const std::vector<double> angles = turning_angles(frames[f], closed);
    if (previous.empty()) previous.assign(angles.size(), 0.0);  // CMML starts from flat
    double largest = 0.0;
    for (std::size_t j = 0; j < angles.size(); ++j) largest = std::max(largest, std::abs(angles[j] - previous[j]));
    geometry::FoldEvent event;
    event.number = static_cast<int>(f);
    const int first_joint = closed ? 0 : 1;
    for (std::size_t j = 0; j < angles.size(); ++j) {
      geometry::FoldCommand c;
      c.joint_id = first_joint + static_cast<int>(j);
      c.angle = angles[j];
      const double share = largest > 0.0 ? std::abs(angles[j] - previous[j]) / largest : 1.0;
      c.speed = std::max(kFastest * share, kSlowest);
      event.folds.push_back(c);
    }
    sequence.events.push_back(std::move(event));
    previous = angles;
  }
  return sequence;
}

}  // namespace foldkit::folding
