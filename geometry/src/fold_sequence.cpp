#include "foldkit/geometry/fold_sequence.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <map>
#include <optional>
#include <unordered_map>

namespace foldkit::geometry {

FoldSequence make_sequence(std::string title, std::vector<std::pair<int, FoldCommand>> numbered_folds) {
  std::map<int, FoldEvent> events;
  for (auto& [number, fold] : numbered_folds) {
    FoldEvent& e = events[number];
    e.number = number;
    e.folds.push_back(fold);
  }
  FoldSequence seq{std::move(title), {}};
  for (auto& [number, e] : events) seq.events.push_back(std::move(e));
  return seq;
}

Diagnostics check_sequence(const CreasePattern& pattern, const FoldSequence& sequence) {
  Diagnostics out;
  for (const FoldEvent& e : sequence.events) {
    std::unordered_map<int, int> seen;
    for (const FoldCommand& f : e.folds) {
      if (!pattern.joint_index(f.joint_id))
        out.push_back({Severity::Error, f.line, "fold names joint " + std::to_string(f.joint_id) + ", which the pattern does not have"});
      auto [it, fresh] = seen.emplace(f.joint_id, f.line);
      if (!fresh)
        out.push_back({Severity::Error, f.line,
                       "joint " + std::to_string(f.joint_id) + " is folded twice in event " + std::to_string(e.number) +
                           " (also at line " + std::to_string(it->second) + ")"});
    }
  }
  return out;
}

std::vector<FoldState> event_states(const CreasePattern& pattern, const FoldSequence& sequence) {
  std::vector<FoldState> states{FoldState::flat(pattern)};
  for (const FoldEvent& e : sequence.events) {
    FoldState next = states.back();
    for (const FoldCommand& f : e.folds)
      if (auto j = pattern.joint_index(f.joint_id)) next.angles[*j] = f.angle;
    states.push_back(std::move(next));
  }
  return states;
}

FoldState end_state(const CreasePattern& pattern, const FoldSequence& sequence) {
  return event_states(pattern, sequence).back();
}

FoldSequence sequence_to(const CreasePattern& pattern, const FoldState& state, double speed, std::string title) {
  FoldSequence seq{std::move(title), {}};
  FoldEvent event{1, {}};
  for (std::size_t j = 0; j < pattern.joints().size(); ++j) {
    const double angle = state.angles[static_cast<Eigen::Index>(j)];
    if (angle != 0.0) event.folds.push_back({pattern.joints()[j].id, angle, speed, 0});
  }
  if (!event.folds.empty()) seq.events.push_back(std::move(event));
  return seq;
}

std::optional<FoldEvent> path_event(const CreasePattern& pattern, const FoldState& from, const FoldState& to, double max_speed,
                                    int number) {
  if (!(max_speed > 0.0) || !std::isfinite(max_speed))
    throw std::invalid_argument("path_sequence: the speed must be positive and finite");
  if (to.angles.size() != from.angles.size() || to.angles.size() != static_cast<Eigen::Index>(pattern.joints().size()))
    throw std::invalid_argument("path_sequence: a waypoint does not hold one angle per joint");
  const double longest = (to.angles - from.angles).cwiseAbs().maxCoeff();
  if (!(longest > 0.0)) return std::nullopt;
  const double duration = longest / max_speed;
  FoldEvent event{number, {}};
  for (std::size_t j = 0; j < pattern.joints().size(); ++j) {
    const auto k = static_cast<Eigen::Index>(j);
    const double change = std::abs(to.angles[k] - from.angles[k]);
    // A joint that barely moves still needs a speed a CMML can hold (positive in degrees).
    if (change > 0.0) event.folds.push_back({pattern.joints()[j].id, to.angles[k], std::max(change / duration, 1e-9), 0});
  }
  return event;
}

FoldSequence path_sequence(const CreasePattern& pattern, const std::vector<FoldState>& waypoints, double max_speed,
                           std::string title) {
  if (!(max_speed > 0.0) || !std::isfinite(max_speed))
    throw std::invalid_argument("path_sequence: the speed must be positive and finite");
  FoldSequence seq{std::move(title), {}};
  FoldState at = FoldState::flat(pattern);
  for (const FoldState& next : waypoints) {
    auto event = path_event(pattern, at, next, max_speed, static_cast<int>(seq.events.size()) + 1);
    if (!event) continue;
    seq.events.push_back(std::move(*event));
    at = next;
  }
  return seq;
}

}  // namespace foldkit::geometry
