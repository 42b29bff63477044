#pragma once
// The spherical polygon of one vertex (crease directions on the unit sphere, sector angles as
// arc lengths) and one expansive step of it. Private to carpenter_spherical.cpp; split out so
// that the geometry reads apart from the bookkeeping of frames.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace foldkit::folding::detail::spherical {

// The first pair of sectors (by the index of their first crease) whose arcs cross; sectors that
// only touch (at an end, or lying on each other) do not count.
std::optional<std::array<int, 2>> find_crossing(const std::vector<Eigen::Vector3d>& u, double tolerance = 1e-9);

// Smallest after[i] − before[i].
double min_difference(const std::vector<double>& before, const std::vector<double>& after);

// Spherical distance, accurate at both ends of [0, π].
double distance(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

struct Velocity {
  enum class Status { Ok, Failed } status = Status::Failed;
  std::vector<Eigen::Vector3d> du;  // per unlocked crease (Polygon::active order)
  double rate = 0.0;                // every strut's distance grows at least this fast
  std::string message;
};

struct StepOutcome {
  bool ok = false;
  std::string message;
  std::vector<double> folds;  // fold angles after the step, one per crease
  double min_growth = 0.0;    // smallest change of a pairwise distance over the step
};

class Polygon {
 public:
  Polygon(std::vector<Eigen::Vector3d> u, std::vector<double> sectors);

  // Moves the unlocked creases to the nearest positions (minimum-norm Gauss–Newton) with unit
  // length and exact bar arc lengths, and puts each locked crease back on its bar. False when
  // the constraints are not met to 1e-13.
  bool restore();
  // Signed fold angles (project convention: positive = mountain), each the representative
  // nearest to `reference` (so that ±π do not wrap); locked creases are exactly 0.
  std::vector<double> fold_angles(const std::vector<double>& reference) const;
  // Locks unlocked creases whose |fold angle| is below `tolerance` while the merged bar stays
  // below π; restores when any was locked. Returns how many.
  int lock_straight(const std::vector<double>& folds, double tolerance);
  double sector_error() const;
  // Pairwise distances of all creases, pairs (i < j) in row order.
  std::vector<double> all_distances() const;
  void set_flat();

  // The LP of Streinu–Whiteley: maximise t subject to u̇ᵢ·uᵢ = 0, bars u̇ᵢ·uⱼ + uᵢ·u̇ⱼ = 0,
  // struts u̇ᵢ·uⱼ + uᵢ·u̇ⱼ ≤ −t·wᵢⱼ·sin dᵢⱼ (every other pair's distance grows at rate ≥ t·wᵢⱼ,
  // wᵢⱼ = min(1, √gap / 0.1), gap = the room left to its distance in the flat state), the first
  // two unlocked creases pinned, |u̇| ≤ 1 per coordinate.
  Velocity expansive_velocity() const;
  // Integrates `velocity` with the largest step ≤ `step` (arc) that keeps every pairwise distance
  // from shrinking and every fold angle within `frame_step` of `folds`; a crease about to go
  // straight is met by bisection and locked. Moves the polygon only when it succeeds.
  StepOutcome advance(const Velocity& velocity, double step, double frame_step, const std::vector<double>& folds,
                      double straight_tolerance);

  const std::vector<Eigen::Vector3d>& directions() const { return u_; }
  const std::vector<int>& active() const { return active_; }

 private:
  void place_locked();
  double constraint_error() const;

  std::vector<Eigen::Vector3d> u_;
  std::vector<double> s_;
  std::vector<int> active_;    // unlocked creases, counter-clockwise
  std::vector<double> bars_;   // arc from active_[k] to active_[k + 1]
  std::vector<bool> locked_;
};

}  // namespace foldkit::folding::detail::spherical
