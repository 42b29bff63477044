#include "carpenter_planar_velocity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <unordered_map>
#include <unordered_set>

#include "carpenter_planar_struts.hpp"
#include "linear_program.hpp"

namespace foldkit::folding::detail {
namespace {

using Vec = Eigen::Vector2d;
using struts::cross;
using struts::for_each_low_rate;
using struts::kRateCap;
using struts::StrutModel;

constexpr double kInf = std::numeric_limits<double>::infinity();
// Velocities are boxed although the objective already bounds them: Clp's dual simplex has
// reported feasible LPs of this shape infeasible when the columns were free.
constexpr double kSpeedBox = 1e12;
// near_pairs() keeps the pairs closer than this many median nearest-vertex distances where that
// is less than the caller's radius. On random_star(n, seed), method lp, against the radius alone
// (this 2-core machine, wall): the 1,000-gon of seed 1, first 100 steps, 100 s instead of
// 1,048 s; the 400-gons of seeds 1–3, 138 s instead of 154 s; the 200-gons, 15.1 s instead of
// 13.5 s (step counts move as ties among optimal fields do). A factor 1.5 took 106 s on both the
// 1,000-gon and the 400-gons, but 2 keeps lattice walks clear of the rule: their nearest
// distance is ≈ 1.36 mean bars (2.7 scaled), beyond both radii the planner passes (1 and 2 mean
// bars; 1.5 would clear 2 by 2 %), so their runs are unchanged.
constexpr double kNearScale = 2.0;

std::int64_t pair_key(int a, int b, int m) { return static_cast<std::int64_t>(a) * m + b; }

struct Solved {
  std::vector<Vec> v;
  std::vector<double> joint_speed;  // per vertex, 0 where no joint
  LpSolution::Status status = LpSolution::Status::Failed;
};

// Minimise Σ |θ̇| subject to bars and weighted struts ≥ 1. The expansive motions form a cone, so
// asking for unit expansion only fixes the scale, and the smallest joint motion achieving it
// bends the chain least, so the step that integrates it can be long. (Maximising a common rate
// t under |v|∞ ≤ 1 lands on a vertex that moves every joint at full speed, and the integration
// error then swamps the small t.)
//
// Struts found violated are added to the same Clp model, which re-solves from its last basis.
class StepLp {
 public:
  StepLp(const StrutModel& model, const std::vector<Vec>& p, const std::vector<StrutModel::Row>& rows,
         const RigidEnds& rigid)
      : m_(model.vertices()),
        joint_column_(static_cast<std::size_t>(model.vertices()), -1),
        rigid_(rigid),
        lp_(build(model, p, rows)) {}

  void add_strut(const StrutModel::Row& r) { lp_.add_row(strut_row(r), 1.0, kInf); }
  int size() const { return lp_.rows() + lp_.columns(); }  // rows + columns

  // Rows: bars, then joints in vertex order, then struts in the order given.
  void warm(const BasisMemo& memo, const std::vector<int>& key, const std::vector<StrutModel::Row>& rows, bool closed) {
    IncrementalLp::Basis basis = lp_.basis();  // all slack: kept where the memo knows nothing
    auto put = [](unsigned char& slot, unsigned char remembered) {
      if (remembered != 0) slot = remembered;
    };
    const std::size_t n = memo.vx.size();
    for (int k : key)
      if (k < 0 || static_cast<std::size_t>(k) >= n) return;  // not the chain the memo saw
    const int bars = closed ? m_ : m_ - 1;
    int row = 0;
    for (int a = 0; a < bars; ++a, ++row) put(basis.row[row], memo.bar_row[key[a]]);
    for (int a = 0; a < m_; ++a) {
      put(basis.column[2 * a], memo.vx[key[a]]);
      put(basis.column[2 * a + 1], memo.vy[key[a]]);
      if (joint_column_[a] < 0) continue;
      put(basis.column[joint_column_[a]], memo.plus[key[a]]);
      put(basis.column[joint_column_[a] + 1], memo.minus[key[a]]);
      put(basis.row[row++], memo.joint_row[key[a]]);
    }
    for (const StrutModel::Row& r : rows) {
      const auto it = memo.strut_row.find(static_cast<std::int64_t>(key[r.a]) * static_cast<std::int64_t>(n) + key[r.b]);
      put(basis.row[row++], it == memo.strut_row.end() ? 1 : it->second);
    }
    lp_.set_basis(basis);
  }

  void remember(BasisMemo& memo, const std::vector<int>& key, const std::vector<StrutModel::Row>& rows, bool closed) const {
    const IncrementalLp::Basis basis = lp_.basis();
    if (basis.column.empty()) return;
    std::size_t n = memo.vx.size();
    for (int k : key) n = std::max(n, static_cast<std::size_t>(k) + 1);
    for (auto* v : {&memo.vx, &memo.vy, &memo.plus, &memo.minus, &memo.bar_row, &memo.joint_row}) v->assign(n, 0);
    memo.strut_row.clear();
    const int bars = closed ? m_ : m_ - 1;
    int row = 0;
    for (int a = 0; a < bars; ++a) memo.bar_row[key[a]] = basis.row[row++];
    for (int a = 0; a < m_; ++a) {
      memo.vx[key[a]] = basis.column[2 * a];
      memo.vy[key[a]] = basis.column[2 * a + 1];
      if (joint_column_[a] < 0) continue;
      memo.plus[key[a]] = basis.column[joint_column_[a]];
      memo.minus[key[a]] = basis.column[joint_column_[a] + 1];
      memo.joint_row[key[a]] = basis.row[row++];
    }
    for (const StrutModel::Row& r : rows)
      memo.strut_row[static_cast<std::int64_t>(key[r.a]) * static_cast<std::int64_t>(n) + key[r.b]] = basis.row[row++];
    memo.valid = true;
  }

  Solved solve(IncrementalLp::Method method = IncrementalLp::Method::Dual, int max_iterations = 0) {
    const LpSolution s = lp_.solve(method, max_iterations);
    Solved out;
    out.status = s.status;
    if (s.status != LpSolution::Status::Optimal) return out;
    out.v.resize(m_);
    out.joint_speed.assign(static_cast<std::size_t>(m_), 0.0);
    for (int a = 0; a < m_; ++a) {
      out.v[a] = Vec(s.x[2 * a], s.x[2 * a + 1]);
      if (joint_column_[a] >= 0) out.joint_speed[a] = s.x[joint_column_[a]] - s.x[joint_column_[a] + 1];
    }
    return out;
  }

 private:
  std::vector<std::pair<int, double>> strut_row(const StrutModel::Row& r) const {
    if (r.joints.empty())
      return {{2 * r.a, -r.d.x()}, {2 * r.a + 1, -r.d.y()}, {2 * r.b, r.d.x()}, {2 * r.b + 1, r.d.y()}};
    std::vector<std::pair<int, double>> row;
    for (const auto& [k, c] : r.joints) {
      row.emplace_back(joint_column_[k], c);
      row.emplace_back(joint_column_[k] + 1, -c);
    }
    return row;
  }

  LinearProgram build(const StrutModel& model, const std::vector<Vec>& p, const std::vector<StrutModel::Row>& rows) {
  const int m = model.vertices();
  LinearProgram lp;
  for (int a = 0; a < m; ++a) {
    const double bound = a < 2 ? 0.0 : kSpeedBox;  // bar 0 pinned kills the rigid motions
    lp.add_column(-bound, bound, 0.0);
    lp.add_column(-bound, bound, 0.0);
  }
  // θ̇_k = θ⁺_k − θ⁻_k with θ± ≥ 0 at unit cost, so Σ|θ̇| needs no rows of its own (an optimum
  // never makes both positive): half the rows of a bound column with two inequalities.
  std::vector<int>& joint_column = joint_column_;
  for (int k = 0; k < m; ++k)
    if (model.is_joint(k)) {
      const double bound = rigid_.holds_joint(k, m) ? 0.0 : kSpeedBox;  // a held joint keeps its angle
      joint_column[k] = lp.add_column(0.0, bound, 1.0);
      lp.add_column(0.0, bound, 1.0);
    }
  const int bars = model.closed() ? m : m - 1;
  for (int a = 0; a < bars; ++a) {
    const int b = (a + 1) % m;
    const Vec d = p[b] - p[a];
    lp.add_row({{2 * a, -d.x()}, {2 * a + 1, -d.y()}, {2 * b, d.x()}, {2 * b + 1, d.y()}}, 0.0, 0.0);
  }
  // ω of bar a = cross(d, v_{a+1} − v_a) / |d|², as coefficients on the v columns.
  auto add_omega = [&](std::vector<std::pair<int, double>>& row, int bar, double sign) {
    const int a = bar, b = (bar + 1) % m;
    const Vec d = p[b] - p[a];
    const double scale = sign / d.squaredNorm();
    row.push_back({2 * b, -d.y() * scale});
    row.push_back({2 * b + 1, d.x() * scale});
    row.push_back({2 * a, d.y() * scale});
    row.push_back({2 * a + 1, -d.x() * scale});
  };
  for (int k = 0; k < m; ++k) {
    if (joint_column[k] < 0) continue;
    // θ̇_k = ω_k − ω_{k−1}
    std::vector<std::pair<int, double>> row = {{joint_column[k], 1.0}, {joint_column[k] + 1, -1.0}};
    add_omega(row, k, -1.0);
    add_omega(row, (k + m - 1) % m, 1.0);
    lp.add_row(row, 0.0, 0.0);
  }
  for (const StrutModel::Row& r : rows) lp.add_row(strut_row(r), 1.0, kInf);
  return lp;
  }

  int m_;
  std::vector<int> joint_column_;
  RigidEnds rigid_;
  IncrementalLp lp_;
};

}  // namespace

std::vector<std::pair<int, int>> near_pairs(const StrutModel& model, const std::vector<Vec>& p, double radius) {
  const int m = model.vertices();
  std::unordered_map<std::int64_t, std::vector<int>> cells;
  auto cell_of = [&](const Vec& x) {
    return std::pair<std::int64_t, std::int64_t>{static_cast<std::int64_t>(std::floor(x.x() / radius)),
                                                 static_cast<std::int64_t>(std::floor(x.y() / radius))};
  };
  auto key = [](std::int64_t cx, std::int64_t cy) { return cx * 73'856'093 ^ cy * 19'349'663; };
  for (int a = 0; a < m; ++a) {
    const auto [cx, cy] = cell_of(p[a]);
    cells[key(cx, cy)].push_back(a);
  }
  std::vector<std::pair<int, int>> out;
  std::vector<double> nearest(static_cast<std::size_t>(m), kInf);  // squared
  const double r2 = radius * radius;
  for (int a = 0; a < m; ++a) {
    const auto [cx, cy] = cell_of(p[a]);
    for (std::int64_t dx = -1; dx <= 1; ++dx)
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const auto it = cells.find(key(cx + dx, cy + dy));
        if (it == cells.end()) continue;
        for (int b : it->second) {
          if (b <= a || model.is_bar(a, b)) continue;
          const double d2 = (p[b] - p[a]).squaredNorm();
          if (!(d2 < r2)) continue;  // NaN too
          out.emplace_back(a, b);
          nearest[a] = std::min(nearest[a], d2);
          nearest[b] = std::min(nearest[b], d2);
        }
      }
  }
  if (out.empty()) return out;
  auto mid = nearest.begin() + m / 2;
  std::nth_element(nearest.begin(), mid, nearest.end());
  // ∞ when at least half the vertices have none nearer than radius; 0 when half of them sit on
  // another vertex (the radius is kept in both cases).
  const double scaled2 = kNearScale * kNearScale * *mid;
  if (scaled2 > 0.0 && scaled2 < r2) {
    auto far = [&](const std::pair<int, int>& ab) { return !((p[ab.second] - p[ab.first]).squaredNorm() < scaled2); };
    out.erase(std::remove_if(out.begin(), out.end(), far), out.end());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<Vec> open_chain_velocities(const std::vector<Vec>& p, const std::vector<double>& speed) {
  const int m = static_cast<int>(p.size());
  std::vector<Vec> v(p.size(), Vec::Zero());
  double omega = 0.0;
  for (int a = 0; a + 1 < m; ++a) {
    if (a > 0) omega += speed[a];
    const Vec d = p[a + 1] - p[a];
    v[a + 1] = v[a] + omega * Vec(-d.y(), d.x());
  }
  return v;
}

ExpansiveVelocity expansive_velocity(const std::vector<Vec>& p, bool closed, const std::vector<std::pair<int, int>>& seed,
                                     double near_radius, bool all_struts, const std::vector<int>* key,
                                     BasisMemo* memo, const RigidEnds& rigid) {
  const StrutModel model(p, closed);
  const int m = model.vertices();
  std::vector<StrutModel::Row> rows;
  std::unordered_set<std::int64_t> present;
  auto add = [&](int a, int b) {
    if (a > b) std::swap(a, b);
    if (a < 0 || b >= m || a == b || model.is_bar(a, b) || rigid.holds_pair(a, b, m)) return;
    if (present.insert(pair_key(a, b, m)).second) rows.push_back(model.row(a, b));
  };
  if (all_struts) {
    for (int a = 0; a < m; ++a)
      for (int b = a + 2; b < m; ++b) add(a, b);
  } else {
    for (const auto& [a, b] : seed) add(a, b);
    for (const auto& [a, b] : near_pairs(model, p, near_radius)) add(a, b);
  }

  ExpansiveVelocity out;
  auto lp = std::make_unique<StepLp>(model, p, rows, rigid);
  // Last step's optimal basis, on points moved a little, is nearly primal feasible and nearly
  // dual feasible; the primal simplex repairs it in fewer iterations than the dual (29 against
  // 37 per LP, 3.3 → 2.3 ms, on a 400-link chain). Rows added by constraint generation leave a
  // basis dual feasible, so later rounds use the dual simplex.
  // The warm primal simplex can stall: on a star-shaped 400-gon one ran for minutes (Clp's primal
  // cycling on a degenerate basis) where a fresh dual took 2,135 iterations. Past twice the LP's
  // size in iterations it gives up, and the fresh solves below decide.
  IncrementalLp::Method round_method = IncrementalLp::Method::Dual;
  int round_cap = 0;
  if (key != nullptr && memo != nullptr && memo->valid) {
    lp->warm(*memo, *key, rows, closed);
    round_method = IncrementalLp::Method::Primal;
    round_cap = 2 * lp->size();
  }
  for (;;) {
    // A probe's every round is capped too: its failure only means another hold is tried.
    Solved s = lp->solve(round_method, rigid.probe ? 2 * lp->size() : round_cap);
    round_method = IncrementalLp::Method::Dual;
    round_cap = 0;
    if (s.status != LpSolution::Status::Optimal && !rigid.probe) {
      // Clp has called LPs of this shape infeasible or unbounded from a warm basis, and now and
      // then from scratch too: a fresh dual, then a fresh primal simplex decide. The model that
      // solved carries on (later struts, the basis remembered for the next step). The fresh
      // primal stops, as the warm one, after twice the LP's size in iterations: on a double
      // spiral of 2 × 90 points (issue 36) it cycled for over ten minutes after the dual had
      // called the LP infeasible in 999 iterations.
      for (const auto method : {IncrementalLp::Method::Dual, IncrementalLp::Method::Primal}) {
        auto fresh = std::make_unique<StepLp>(model, p, rows, rigid);
        s = fresh->solve(method, method == IncrementalLp::Method::Primal ? 2 * fresh->size() : 0);
        if (s.status == LpSolution::Status::Optimal) {
          lp = std::move(fresh);
          break;
        }
      }
    }
    ++out.lp_solves;
    out.struts = rows.size();
    if (s.status != LpSolution::Status::Optimal) {
      out.status = to_string(s.status);
      return out;
    }
    // Held ends: the field is rebuilt from the joint speeds, so that a held body moves exactly
    // rigidly (the LP's own velocities carry its tolerances).
    if (rigid.any()) {
      for (int k = 0; k < m; ++k)
        if (rigid.holds_joint(k, m)) s.joint_speed[k] = 0.0;
      s.v = open_chain_velocities(p, s.joint_speed);
    }
    // Every pair's weighted rate, from the solution itself: a strut the LP has not seen, or one
    // its tolerances let slip, shows here.
    double rate_min = kRateCap;
    std::vector<std::pair<double, std::pair<int, int>>> violated;
    auto check = [&](int a, int b, double g) {
      if (rigid.holds_pair(a, b, m)) return;  // distance fixed by construction
      rate_min = std::min(rate_min, g);
      if (g < 1.0 - 1e-6 && !present.count(pair_key(a, b, m))) violated.push_back({g, {a, b}});
    };
    for_each_low_rate(model, p, s.v, s.joint_speed, check);
    if (violated.empty()) {
      out.v = s.v;
      out.t = rate_min;
      out.solved = true;
      for (const StrutModel::Row& r : rows)
        if (model.weighted_rate(r, s.v, s.joint_speed) <= 2.0) out.binding.emplace_back(r.a, r.b);
      if (key != nullptr && memo != nullptr) lp->remember(*memo, *key, rows, closed);
      return out;
    }
    const std::size_t cap = std::max<std::size_t>(64, static_cast<std::size_t>(m));
    if (violated.size() > cap) {
      std::nth_element(violated.begin(), violated.begin() + static_cast<std::ptrdiff_t>(cap), violated.end());
      violated.resize(cap);
    }
    for (const auto& entry : violated) {
      const std::size_t before = rows.size();
      add(entry.second.first, entry.second.second);
      if (rows.size() > before) lp->add_strut(rows.back());
    }
  }
}

}  // namespace foldkit::folding::detail
