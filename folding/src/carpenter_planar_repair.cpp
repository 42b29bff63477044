// The carried field of CarpenterPlanarMethod::CarriedField (docs/CARPENTER.md, "Methods"): an
// open chain's joint speeds kept from step to step, checked on all pairs, and mended by a small
// LP over the joints near the pairs that it no longer expands.
#include <algorithm>
#include <array>
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
// Clp's status codes (ClpSimplex::Status) for a starting basis.
constexpr unsigned char kBasic = 1, kAtLower = 3;
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
// window at their carried speeds; solve() is false when the LP has no solution.
//
// A far pair's rate over the window joints between its ends, Σₖ θ̇ₖ·cross(p_b − pₖ, d), is
// written as cross(p_b − o, d)·ΔΩ − cross(ΔS, d) with ΔΩ = Σₖ θ̇ₖ and ΔS = Σₖ θ̇ₖ·(pₖ − o), o the
// window's mean: differences of running sums (Ω_j, S_j after the j-th window joint, three free
// columns tied by three rows per joint), so the row has at most 6 entries instead of two (θ̇⁺,
// θ̇⁻) per window joint. Written joint by joint, the
// rows of a 400-joint window held ~200 entries each, and Clp's factorisations of those dense
// rows were two thirds of the 2,000-link walk's time (48 of 75 s). Short-arc pairs keep their
// joint form (at most kShortArc entries). Only the LP sees the running sums; the field it gives
// is checked on all pairs from the joint speeds as before.
//
// Each LP starts afresh from a dual feasible basis (start_basis()). Starting a round from the
// last round's optimal basis instead, mapped by joint and by pair, was slower: the 2,000-link walk
// of seed 3 took 98 s and 2,463 LP solves instead of 40 s and 1,800 (about 40 ms per solve
// instead of 22; the mapped basis is not dual feasible once the window has grown).
class WindowLp {
 public:
  bool solve(const StrutModel& model, const std::vector<Vec>& p, const std::set<std::pair<int, int>>& rows,
             const std::vector<char>& in, std::vector<double>& speed) {
    const int m = model.vertices();
    build(model, p, rows, in, speed);
    IncrementalLp clp(lp_);
    clp.set_basis(start_basis());
    const LpSolution s = clp.solve();
    if (s.status != LpSolution::Status::Optimal) return false;
    for (int k = 0; k < m; ++k)
      if (column_[k] >= 0) speed[k] = s.x[column_[k]] - s.x[column_[k] + 1];
    return true;
  }

 private:
  // Window joint j (in chain order): columns θ̇⁺, θ̇⁻, Ω, Sx, Sy at 5j … 5j + 4, tie rows 3j … 3j + 2;
  // then one row per pair, in the set's order.
  void build(const StrutModel& model, const std::vector<Vec>& p, const std::set<std::pair<int, int>>& rows,
             const std::vector<char>& in, const std::vector<double>& speed) {
    const int m = model.vertices();
    lp_ = LinearProgram{};
    joints_ = 0;
    Vec origin = Vec::Zero();  // coordinates about the window's mean keep the running sums small
    for (int k = 0; k < m; ++k)
      if (in[k]) origin += p[k], ++joints_;
    if (joints_ > 0) origin /= joints_;
    column_.assign(static_cast<std::size_t>(m), -1);
    std::vector<int> before(static_cast<std::size_t>(m), -1);  // last window joint ≤ vertex i (-1: none)
    fixed_.assign(static_cast<std::size_t>(m), {0.0, 0.0, 0.0});
    int last = -1;
    for (int k = 0; k < m; ++k) {
      // The joints outside the window as running sums too, Σ_{k' ≤ k} θ̇ₖ'·(1, pₖ' − o), so that a
      // far row's fixed part costs O(1), not a pass over the joints between its ends.
      const Vec x = p[k] - origin;
      const double own = in[k] ? 0.0 : speed[k];
      for (int s = 0; s < 3; ++s) fixed_[k][s] = (k > 0 ? fixed_[k - 1][s] : 0.0) + own * (s == 0 ? 1.0 : x[s - 1]);
      if (in[k]) {
        const int c = lp_.add_column(0.0, kSpeedBox, 1.0);
        lp_.add_column(0.0, kSpeedBox, 1.0);
        for (int s = 0; s < 3; ++s) lp_.add_column(-kInf, kInf, 0.0);
        const double weight[3] = {1.0, x.x(), x.y()};
        for (int s = 0; s < 3; ++s) {  // running sum s after this joint = before + weight·θ̇
          std::vector<std::pair<int, double>> r{{c + 2 + s, 1.0}, {c, -weight[s]}, {c + 1, weight[s]}};
          if (last >= 0) r.emplace_back(last + 2 + s, -1.0);
          lp_.add_row(r, 0.0, 0.0);
        }
        column_[k] = last = c;
      }
      before[k] = last;
    }
    for (const auto& [a, b] : rows) add_pair(model, p, speed, before, origin, a, b);
  }

  void add_pair(const StrutModel& model, const std::vector<Vec>& p, const std::vector<double>& speed,
                const std::vector<int>& before, const Vec& origin, int a, int b) {
    std::vector<std::pair<int, double>> row;
    double fixed = 0.0;
    const StrutModel::Row r = model.row(a, b);
    if (!r.joints.empty()) {
      for (const auto& [k, c] : r.joints) {
        if (column_[k] < 0) {
          fixed += c * speed[k];
          continue;
        }
        row.emplace_back(column_[k], c);
        row.emplace_back(column_[k] + 1, -c);
      }
    } else {
      const double turn = struts::cross(p[b] - origin, r.d);
      const auto& f_hi = fixed_[b - 1];
      const auto& f_lo = fixed_[a];
      fixed = turn * (f_hi[0] - f_lo[0]) - ((f_hi[1] - f_lo[1]) * r.d.y() - (f_hi[2] - f_lo[2]) * r.d.x());
      const int hi = before[b - 1], lo = before[a];
      if (hi != lo) {
        row.insert(row.end(), {{hi + 2, turn}, {hi + 3, -r.d.y()}, {hi + 4, r.d.x()}});
        if (lo >= 0) row.insert(row.end(), {{lo + 2, -turn}, {lo + 3, r.d.y()}, {lo + 4, -r.d.x()}});
      }
    }
    lp_.add_row(row, 1.0 - fixed, kInf);
  }

  // The running sums basic and their tie rows at bound (a triangular, nonsingular basis), every
  // other row's slack basic and every speed at 0: the duals are 0 and each θ̇± prices at its cost
  // 1, so the basis is dual feasible and the dual simplex starts there. From the all-slack basis
  // the free columns had to enter first, and the window LPs took 2–3× longer than in joint form.
  IncrementalLp::Basis start_basis() const {
    IncrementalLp::Basis basis;
    basis.column.assign(lp_.cost.size(), kAtLower);
    basis.row.assign(lp_.row_lower.size(), kBasic);
    for (int j = 0; j < joints_; ++j)
      for (int s = 0; s < 3; ++s) {
        basis.column[5 * j + 2 + s] = kBasic;
        basis.row[3 * j + s] = kAtLower;
      }
    return basis;
  }

  LinearProgram lp_;
  int joints_ = 0;
  std::vector<int> column_;  // θ̇⁺ column of each window joint (-1: not in the window)
  std::vector<std::array<double, 3>> fixed_;  // running sums of the joints outside the window
};

}  // namespace

bool window_speeds(const std::vector<Vec>& p, const std::set<std::pair<int, int>>& rows, const std::vector<char>& in,
                   std::vector<double>& speed) {
  const StrutModel model(p, false);
  return WindowLp().solve(model, p, rows, in, speed);
}

CarriedVelocity carried_velocity(const std::vector<Vec>& p, std::vector<double> speed, const std::vector<int>& dropped,
                                 double floor, int max_window) {
  const StrutModel model(p, false);
  const int m = model.vertices();
  CarriedVelocity out;
  std::vector<Vec> v = open_chain_velocities(p, speed);
  Weak weak = weak_pairs(model, p, v, speed, floor);
  std::set<std::pair<int, int>> rows;
  WindowLp window_lp;
  int reach = kFirstReach;
  for (int round = 0; round < kRounds && !weak.pairs.empty(); ++round) {
    // At most the kRowShare·m weakest pairs join per round: when a fast joint has gone straight,
    // tens of thousands of pairs across it weaken at once (57,018 on the 2,000-link walk), and a
    // window LP with all of them (each far pair then a dense row over the window, before the
    // running sums) ran for minutes.
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
      if (window_lp.solve(model, p, rows, in, trial)) break;
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
