// The carried field of CarpenterPlanarMethod::CarriedField (docs/CARPENTER.md, "Methods"): an
// open chain's joint speeds kept from step to step, checked on all pairs, and mended by a small
// LP over the joints near the pairs that it no longer expands.
#include <algorithm>
#include <limits>
#include <set>
#include <utility>
#include <vector>

#include "carpenter_planar_struts.hpp"
#include "carpenter_planar_velocity.hpp"
#include "linear_program.hpp"

namespace foldkit::folding::detail {
namespace {

using Vec = Eigen::Vector2d;
using struts::StrutModel;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kSpeedBox = 1e12;  // as the global LP's columns
// Constraint-generation rounds of one repair, and the first window's reach in joints (doubled
// whenever the window LP is infeasible).
constexpr int kRounds = 30;
constexpr int kFirstReach = 2;
// Weak pairs added to the window LP per round: the weakest max(kMinRows, kRowShare·m).
constexpr int kMinRows = 64;
constexpr double kRowShare = 1.0;

// The smallest weighted rate over all pairs and the pairs below `floor`.
struct Weak {
  double rate_min = struts::kRateCap;
  std::vector<std::pair<double, std::pair<int, int>>> pairs;  // (weighted rate, pair)
};

Weak weak_pairs(const StrutModel& model, const std::vector<Vec>& p, const std::vector<Vec>& v,
                const std::vector<double>& speed, double floor) {
  Weak w;
  struts::for_each_low_rate(model, p, v, speed, [&](int a, int b, double g) {
    w.rate_min = std::min(w.rate_min, g);
    if (g < floor) w.pairs.push_back({g, {a, b}});
  });
  return w;
}

// Weighted rate of pair (a < b) per unit speed of each joint k strictly between them (open
// chain): the joint form of StrutModel::row() for a short arc, cross(p_b − p_k, w·(p_b − p_a))
// otherwise (v_b − v_a = Σ_k θ̇_k·J(p_b − p_k) plus a rotation of p_b − p_a, which adds nothing).
std::vector<std::pair<int, double>> coefficients(const StrutModel& model, const std::vector<Vec>& p, int a, int b) {
  const StrutModel::Row r = model.row(a, b);
  if (!r.joints.empty()) return r.joints;
  std::vector<std::pair<int, double>> c;
  for (int k = a + 1; k < b; ++k) c.emplace_back(k, struts::cross(p[b] - p[k], r.d));
  return c;
}

// The joints allowed to change: those within `reach` of a bar that lost a joint since the field
// was solved (sorted), and, for a weak pair that spans no such bar, those within `reach` of either
// of its ends, inside it. A pair across a lost joint is weak for want of that joint's share of its
// rate, which joints next to it make up for: when a fast joint goes straight, thousands of far
// pairs across it weaken at once, and the windows at all their ends would hold most of the chain.
std::vector<char> window_of(const std::set<std::pair<int, int>>& rows, const std::vector<int>& dropped, int m, int reach) {
  std::vector<char> in(static_cast<std::size_t>(m), 0);
  for (int a : dropped)
    for (int k = std::max(0, a + 1 - reach); k <= std::min(m - 1, a + reach); ++k) in[k] = 1;
  for (const auto& [a, b] : rows) {
    const auto first = std::lower_bound(dropped.begin(), dropped.end(), a);
    if (first != dropped.end() && *first < b) continue;
    for (int k = a + 1; k < std::min(b, a + 1 + reach); ++k) in[k] = 1;
    for (int k = std::max(a + 1, b - reach); k < b; ++k) in[k] = 1;
  }
  in[0] = in[m - 1] = 0;  // the chain's ends are no joints
  return in;
}

// min Σ_{k in window} |θ̇_k| subject to every row's weighted rate ≥ 1, the joints outside the
// window at their carried speeds. False when the LP has no solution.
bool solve_window(const StrutModel& model, const std::vector<Vec>& p, const std::set<std::pair<int, int>>& rows,
                  const std::vector<char>& in, std::vector<double>& speed) {
  const int m = model.vertices();
  LinearProgram lp;
  std::vector<int> column(static_cast<std::size_t>(m), -1);
  for (int k = 0; k < m; ++k)
    if (in[k]) {
      column[k] = lp.add_column(0.0, kSpeedBox, 1.0);  // θ̇⁺, then θ̇⁻
      lp.add_column(0.0, kSpeedBox, 1.0);
    }
  for (const auto& [a, b] : rows) {
    std::vector<std::pair<int, double>> row;
    double fixed = 0.0;
    for (const auto& [k, c] : coefficients(model, p, a, b)) {
      if (column[k] < 0) {
        fixed += c * speed[k];
        continue;
      }
      row.emplace_back(column[k], c);
      row.emplace_back(column[k] + 1, -c);
    }
    lp.add_row(row, 1.0 - fixed, kInf);
  }
  const LpSolution s = solve(lp);
  if (s.status != LpSolution::Status::Optimal) return false;
  for (int k = 0; k < m; ++k)
    if (column[k] >= 0) speed[k] = s.x[column[k]] - s.x[column[k] + 1];
  return true;
}

}  // namespace

CarriedVelocity carried_velocity(const std::vector<Vec>& p, std::vector<double> speed, const std::vector<int>& dropped,
                                 double floor, int max_window) {
  const StrutModel model(p, false);
  const int m = model.vertices();
  CarriedVelocity out;
  std::vector<Vec> v = open_chain_velocities(p, speed);
  Weak weak = weak_pairs(model, p, v, speed, floor);
  std::set<std::pair<int, int>> rows;
  int reach = kFirstReach;
  for (int round = 0; round < kRounds && !weak.pairs.empty(); ++round) {
    // At most the kRowShare·m weakest pairs join per round: when a fast joint has gone straight,
    // tens of thousands of pairs across it weaken at once (57,018 on the 2,000-link walk), and a
    // window LP with all of them (each far pair a dense row over the window) ran for minutes.
    // Mending the weakest mends most of the others. (m/8 instead of m: 795 instead of 424 steps on
    // the 1,000-link walk, 6× slower; the fields mended from fewer rows were weaker.)
    const auto cap = static_cast<std::size_t>(std::max(kMinRows, static_cast<int>(kRowShare * m)));
    if (weak.pairs.size() > cap) {
      std::nth_element(weak.pairs.begin(), weak.pairs.begin() + static_cast<std::ptrdiff_t>(cap), weak.pairs.end());
      weak.pairs.resize(cap);
    }
    // A pair already in the LP that is still weak is held back by the window, not by a missing
    // row: the window grows.
    bool grow = false;
    for (const auto& entry : weak.pairs) grow = !rows.insert(entry.second).second || grow;
    if (grow) reach = std::min(2 * reach, m);  // the whole chain at most (and no int overflow)
    std::vector<char> in = window_of(rows, dropped, m, reach);
    std::vector<double> trial = speed;
    for (;;) {
      const auto joints = std::count(in.begin(), in.end(), 1);
      if (joints > max_window) return out;
      ++out.lp_solves;
      if (solve_window(model, p, rows, in, trial)) break;
      // Infeasible: more joints, unless the window already holds every joint the rows span.
      reach *= 2;
      in = window_of(rows, dropped, m, reach);
      if (std::count(in.begin(), in.end(), 1) == joints) return out;
    }
    speed = std::move(trial);
    v = open_chain_velocities(p, speed);
    weak = weak_pairs(model, p, v, speed, floor);
  }
  if (!weak.pairs.empty()) return out;
  out.v = std::move(v);
  out.speed = std::move(speed);
  out.t = weak.rate_min;
  out.struts = rows.size();
  out.solved = true;
  return out;
}

}  // namespace foldkit::folding::detail
