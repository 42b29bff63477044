#include "carpenter_spherical_polygon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <Eigen/Geometry>
#include <Eigen/QR>

#include "linear_program.hpp"

namespace foldkit::folding::detail::spherical {

using Eigen::Vector3d;

double distance(const Vector3d& a, const Vector3d& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

double min_difference(const std::vector<double>& before, const std::vector<double>& after) {
  double m = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < before.size() && i < after.size(); ++i) m = std::min(m, after[i] - before[i]);
  return m;
}

namespace {

constexpr double kGapScale = 0.1;  // radians^(1/2): pairs within 0.01 rad of their largest distance are weighted down
constexpr double kGapFloor = 1e-12;  // radians
// Constraint generation of the expansion LP: struts per crease in the first LP, the largest value
// of a strut row (radians per unit of motion) that counts as kept, and rounds before every strut
// is added at once.
constexpr std::size_t kSeedStruts = 4;
constexpr double kStrutSlack = 1e-12;
constexpr int kMaxRounds = 50;
// A generated LP whose optimum t is at most this is solved again whole, from scratch.
constexpr double kRetryRate = 1e-9;

// One strut of the expansion LP: unlocked creases k < l (Polygon::active order), their distance,
// and the coefficient of t in its row.
struct Strut {
  std::size_t k, l;
  double d, t_coefficient;
};

// Every strut of the polygon whose unlocked creases are `points`, `bars` apart.
std::vector<Strut> strut_list(const std::vector<Vector3d>& points, const std::vector<double>& bars) {
  const std::size_t m = points.size();
  // Arc from the first unlocked crease to each one, along the polygon.
  std::vector<double> along(m, 0.0);
  for (std::size_t k = 1; k < m; ++k) along[k] = along[k - 1] + bars[k - 1];
  std::vector<Strut> struts;
  for (std::size_t k = 0; k < m; ++k)
    for (std::size_t l = k + 2; l < m; ++l) {
      if (k == 0 && l == m - 1) continue;
      // No distance can exceed its value in the flat state, min(arc, 2π − arc); near it a pair
      // can only grow as fast as the square root of its gap (gap ~ fold angle²). Asking each pair
      // for growth ≥ t·min(1, √gap / kGapScale) lets creases straighten and the sheet reach flat
      // in finite time instead of slowing down exponentially.
      const double d = distance(points[k], points[l]);
      const double a = along[l] - along[k];
      const double gap = std::max(0.0, std::min(a, 2.0 * M_PI - a) - d);
      // Below kGapFloor the gap is rounding: the pair is at its largest (across a straight crease
      // that cannot be merged) and may only keep its distance.
      const double weight = gap < kGapFloor ? 0.0 : std::min(1.0, std::sqrt(gap) / kGapScale);
      // −d(cos d)/dt = sin d · ḋ ≥ t · weight · sin d.
      struts.push_back({k, l, d, weight * std::sin(d)});
    }
  return struts;
}

// The struts of the first LP: each crease's kSeedStruts nearest (the pairs that bind), or all of
// them when there are at most twice as many (the rounds would cost more than they save).
std::vector<bool> seed_struts(const std::vector<Strut>& struts, std::size_t m) {
  const bool whole = struts.size() <= 2 * kSeedStruts * m;
  std::vector<bool> in(struts.size(), whole);
  if (whole) return in;
  std::vector<std::vector<std::pair<double, std::size_t>>> near(m);
  for (std::size_t i = 0; i < struts.size(); ++i) {
    near[struts[i].k].emplace_back(struts[i].d, i);
    near[struts[i].l].emplace_back(struts[i].d, i);
  }
  for (auto& list : near) {
    const std::size_t keep = std::min(list.size(), kSeedStruts);
    std::partial_sort(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(keep), list.end());
    for (std::size_t j = 0; j < keep; ++j) in[list[j].second] = true;
  }
  return in;
}

// The optimum of `base` with every strut's row (`strut_row`), by constraint generation, as the
// planar rule does: the LP starts with the struts `in` holds, then takes the struts the solution
// breaks and re-solves from the last basis, until none is broken. An optimum of the relaxation
// that keeps every strut is the optimum of the whole LP. On the degree-32 goals of
// bench_vertex_fallback the LPs with 30+ creases kept 114 of their 432 struts on average, after
// 0.85 extra rounds; flattening took 1.5x less time (docs/CARPENTER.md).
template <class Row>
LpSolution solve_with_struts(const LinearProgram& base, const std::vector<Strut>& struts, std::vector<bool> in, int t,
                             Row strut_row) {
  constexpr double free_below = -std::numeric_limits<double>::infinity();
  LinearProgram lp = base;
  for (std::size_t i = 0; i < struts.size(); ++i)
    if (in[i]) lp.add_row(strut_row(struts[i]), free_below, 0.0);
  IncrementalLp model(lp);
  LpSolution sol;
  for (int round = 0;; ++round) {
    sol = model.solve();
    if (sol.status != LpSolution::Status::Optimal) break;
    bool added = false;
    for (std::size_t i = 0; i < struts.size(); ++i) {
      if (in[i]) continue;
      double value = 0.0;
      for (const auto& [c, a] : strut_row(struts[i])) value += a * sol.x[static_cast<std::size_t>(c)];
      if (value <= kStrutSlack) continue;
      model.add_row(strut_row(struts[i]), free_below, 0.0);
      in[i] = true;
      added = true;
    }
    if (!added) break;
    if (round == kMaxRounds) {  // never seen; the whole LP settles it
      for (std::size_t i = 0; i < struts.size(); ++i)
        if (!in[i]) model.add_row(strut_row(struts[i]), free_below, 0.0);
      sol = model.solve();
      break;
    }
  }
  if (sol.status == LpSolution::Status::Optimal && sol.x[static_cast<std::size_t>(t)] > kRetryRate) return sol;
  // Clp's dual simplex, warm-started after rows were added, has answered t = 0 where the whole LP
  // has t > 0 (a degenerate basis: u̇ = 0 is always feasible). Only the whole LP, solved from
  // scratch, may say that no strictly expansive motion exists.
  LinearProgram full = base;
  for (const Strut& st : struts) full.add_row(strut_row(st), free_below, 0.0);
  return solve(full);
}
// Rounding in a distance: a crease locked on a bar close to π is placed by dividing by sin(bar),
// which puts a few 1e-13 of noise into its distances.
constexpr double kShrinkTolerance = 1e-11;

// s strictly inside the arc a → b (shorter than π), by more than `tol` from both ends.
bool strictly_inside(const Vector3d& s, const Vector3d& a, const Vector3d& b, double tol) {
  const Vector3d normal = a.cross(b).normalized();
  if (std::abs(s.dot(normal)) > tol) return false;
  return distance(a, s) > tol && distance(s, b) > tol && std::abs(distance(a, s) + distance(s, b) - distance(a, b)) < tol;
}

}  // namespace

std::optional<std::array<int, 2>> find_crossing(const std::vector<Vector3d>& u, double tolerance) {
  const int n = static_cast<int>(u.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours through crease 0
      const Vector3d &a = u[static_cast<std::size_t>(i)], &b = u[static_cast<std::size_t>((i + 1) % n)];
      const Vector3d &c = u[static_cast<std::size_t>(j)], &d = u[static_cast<std::size_t>((j + 1) % n)];
      const Vector3d line = a.cross(b).cross(c.cross(d));
      if (line.norm() < 1e-12) continue;  // on one great circle: lying on each other, not crossing
      const Vector3d s = line.normalized();
      for (const Vector3d& p : {s, Vector3d(-s)})
        if (strictly_inside(p, a, b, tolerance) && strictly_inside(p, c, d, tolerance)) return std::array<int, 2>{i, j};
    }
  return std::nullopt;
}

Polygon::Polygon(std::vector<Vector3d> u, std::vector<double> sectors)
    : u_(std::move(u)), s_(std::move(sectors)), locked_(u_.size(), false) {
  for (std::size_t i = 0; i < u_.size(); ++i) {
    active_.push_back(static_cast<int>(i));
    bars_.push_back(s_[i]);
  }
}

void Polygon::place_locked() {
  // A locked crease lies on the great-circle arc of its bar, at its arc length from the bar's start.
  const std::size_t m = active_.size(), n = u_.size();
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t a = static_cast<std::size_t>(active_[k]), b = static_cast<std::size_t>(active_[(k + 1) % m]);
    const double len = bars_[k];
    double along = 0.0;
    for (std::size_t i = (a + 1) % n; i != b; i = (i + 1) % n) {
      along += s_[(i + n - 1) % n];
      u_[i] = ((std::sin(len - along) * u_[a] + std::sin(along) * u_[b]) / std::sin(len)).normalized();
    }
  }
}

double Polygon::constraint_error() const {
  const std::size_t m = active_.size();
  double e = 0.0;
  for (std::size_t k = 0; k < m; ++k) {
    const Vector3d& a = u_[static_cast<std::size_t>(active_[k])];
    const Vector3d& b = u_[static_cast<std::size_t>(active_[(k + 1) % m])];
    e = std::max({e, std::abs(a.squaredNorm() - 1.0), std::abs(distance(a, b) - bars_[k])});
  }
  return e;
}

bool Polygon::restore() {
  const std::size_t m = active_.size();
  const Eigen::Index rows = static_cast<Eigen::Index>(2 * m), cols = static_cast<Eigen::Index>(3 * m);
  for (int iteration = 0; iteration < 30 && constraint_error() > 1e-15; ++iteration) {
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(rows, cols);
    Eigen::VectorXd c(rows);
    for (std::size_t k = 0; k < m; ++k) {
      const std::size_t next = (k + 1) % m;
      const Vector3d& a = u_[static_cast<std::size_t>(active_[k])];
      const Vector3d& b = u_[static_cast<std::size_t>(active_[next])];
      const Eigen::Index r = static_cast<Eigen::Index>(2 * k);
      c[r] = a.squaredNorm() - 1.0;
      J.block<1, 3>(r, static_cast<Eigen::Index>(3 * k)) = 2.0 * a.transpose();
      // Bars as arc lengths, not dot products: a bar close to π has a dot product that hardly
      // moves, and a rounding-sized error in it would ask for a large correction.
      const double arc = distance(a, b);
      c[r + 1] = arc - bars_[k];
      const double s = std::max(std::sin(arc), 1e-12);
      J.block<1, 3>(r + 1, static_cast<Eigen::Index>(3 * k)) += -(b - a.dot(b) * a).transpose() / s;
      J.block<1, 3>(r + 1, static_cast<Eigen::Index>(3 * next)) += -(a - a.dot(b) * b).transpose() / s;
    }
    // Minimum-norm correction. Near flat the constraints lose rank: directions with singular
    // values below 1e-6 of the largest are left alone, or rounding in c would be blown up into
    // visible jumps.
    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(J);
    cod.setThreshold(1e-6);
    const Eigen::VectorXd dx = cod.solve(c);
    const std::vector<Vector3d> kept = u_;
    const double before = constraint_error();
    for (std::size_t k = 0; k < m; ++k) u_[static_cast<std::size_t>(active_[k])] -= dx.segment<3>(static_cast<Eigen::Index>(3 * k));
    if (constraint_error() >= before) {  // at rounding level: stop where it was best
      u_ = kept;
      break;
    }
  }
  for (int i : active_) u_[static_cast<std::size_t>(i)].normalize();
  place_locked();
  return constraint_error() < 1e-13;
}

std::vector<double> Polygon::fold_angles(const std::vector<double>& reference) const {
  const std::size_t n = u_.size();
  std::vector<double> f(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    if (locked_[i]) continue;
    const Vector3d& prev = u_[(i + n - 1) % n];
    const Vector3d& here = u_[i];
    const Vector3d& next = u_[(i + 1) % n];
    const Vector3d before = prev.cross(here).normalized(), after = here.cross(next).normalized();
    // The sheet's normal turns by −ρ about the crease from the sector before it to the one after:
    // a mountain (ρ > 0) drops both sectors below the crease.
    double a = -std::atan2(before.cross(after).dot(here), before.dot(after));
    if (i < reference.size()) a += 2.0 * M_PI * std::round((reference[i] - a) / (2.0 * M_PI));
    f[i] = a;
  }
  return f;
}

int Polygon::lock_straight(const std::vector<double>& folds, double tolerance) {
  int count = 0;
  for (bool again = true; again && active_.size() > 3;) {
    again = false;
    const std::size_t m = active_.size();
    for (std::size_t k = 0; k < m; ++k) {
      const int i = active_[k];
      const std::size_t before = (k + m - 1) % m;
      const double merged = bars_[before] + bars_[k];
      if (std::abs(folds[static_cast<std::size_t>(i)]) >= tolerance || merged >= M_PI - 1e-9) continue;
      locked_[static_cast<std::size_t>(i)] = true;
      bars_[before] = merged;
      bars_.erase(bars_.begin() + static_cast<std::ptrdiff_t>(k));
      active_.erase(active_.begin() + static_cast<std::ptrdiff_t>(k));
      ++count;
      again = true;
      break;
    }
  }
  if (count > 0) restore();
  return count;
}

double Polygon::sector_error() const {
  const std::size_t n = u_.size();
  double e = 0.0;
  for (std::size_t i = 0; i < n; ++i) e = std::max(e, std::abs(distance(u_[i], u_[(i + 1) % n]) - s_[i]));
  return e;
}

std::vector<double> Polygon::all_distances() const {
  std::vector<double> d;
  for (std::size_t i = 0; i < u_.size(); ++i)
    for (std::size_t j = i + 1; j < u_.size(); ++j) d.push_back(distance(u_[i], u_[j]));
  return d;
}

void Polygon::set_flat() {
  double at = 0.0;
  for (std::size_t i = 0; i < u_.size(); ++i) {
    u_[i] = Vector3d(std::cos(at), std::sin(at), 0.0);
    at += s_[i];
  }
}

Velocity Polygon::expansive_velocity() const {
  Velocity v;
  const std::size_t m = active_.size();
  if (m <= 3) {
    v.message = "only three creases are not straight";
    return v;
  }
  LinearProgram lp;
  std::vector<int> col(3 * m);
  for (std::size_t k = 0; k < m; ++k)
    for (int c = 0; c < 3; ++c) {
      const double bound = k < 2 ? 0.0 : 1.0;  // the first two unlocked creases are pinned
      col[3 * k + static_cast<std::size_t>(c)] = lp.add_column(-bound, bound, 0.0);
    }
  const int t = lp.add_column(0.0, 1e6, -1.0);
  const auto point = [&](std::size_t k) -> const Vector3d& { return u_[static_cast<std::size_t>(active_[k])]; };
  // d(uₖ·uₗ)/dt = u̇ₖ·uₗ + uₖ·u̇ₗ, as coefficients.
  const auto rate = [&](std::size_t k, std::size_t l) {
    std::vector<std::pair<int, double>> row;
    for (int c = 0; c < 3; ++c) {
      row.emplace_back(col[3 * k + static_cast<std::size_t>(c)], point(l)[c]);
      row.emplace_back(col[3 * l + static_cast<std::size_t>(c)], point(k)[c]);
    }
    return row;
  };
  for (std::size_t k = 0; k < m; ++k) {
    std::vector<std::pair<int, double>> tangent;
    for (int c = 0; c < 3; ++c) tangent.emplace_back(col[3 * k + static_cast<std::size_t>(c)], point(k)[c]);
    lp.add_row(tangent, 0.0, 0.0);
    lp.add_row(rate(k, (k + 1) % m), 0.0, 0.0);
  }
  std::vector<Vector3d> points(m);
  for (std::size_t k = 0; k < m; ++k) points[k] = point(k);
  const std::vector<Strut> struts = strut_list(points, bars_);
  const auto strut_row = [&](const Strut& st) {
    auto row = rate(st.k, st.l);
    row.emplace_back(t, st.t_coefficient);
    return row;
  };
  const LpSolution sol = solve_with_struts(lp, struts, seed_struts(struts, m), t, strut_row);
  if (sol.status != LpSolution::Status::Optimal) {
    v.message = std::string("the expansion LP is ") + to_string(sol.status);
    return v;
  }
  v.rate = sol.x[static_cast<std::size_t>(t)];
  for (std::size_t k = 0; k < m; ++k)
    v.du.emplace_back(sol.x[static_cast<std::size_t>(col[3 * k])], sol.x[static_cast<std::size_t>(col[3 * k + 1])],
                      sol.x[static_cast<std::size_t>(col[3 * k + 2])]);
  // Clp leaves rounding in the tangency rows; the step is projected onto the sphere anyway.
  for (std::size_t k = 0; k < m; ++k) v.du[k] -= v.du[k].dot(point(k)) * point(k);
  v.status = Velocity::Status::Ok;
  std::ostringstream msg;
  msg << "rate " << v.rate;
  v.message = msg.str();
  return v;
}

StepOutcome Polygon::advance(const Velocity& velocity, double step, double frame_step, const std::vector<double>& folds,
                             double straight_tolerance) {
  StepOutcome out;
  const std::vector<double> before = all_distances();
  double fastest = 0.0;
  for (const Vector3d& d : velocity.du) fastest = std::max(fastest, d.norm());
  if (!(fastest > 0)) {
    out.message = "the expansive velocity is zero";
    return out;
  }
  struct Trial {
    Polygon polygon;
    std::vector<double> folds;
    bool restored = false;
    bool crosses_straight = false;  // a crease changed the sign of its fold angle
    std::vector<std::size_t> crossing;  // which
    double change = 0.0;
  };
  const auto trial = [&](double h) {
    Trial tr{*this, {}, false, false, {}, 0.0};
    for (std::size_t k = 0; k < active_.size(); ++k) tr.polygon.u_[static_cast<std::size_t>(active_[k])] += h * velocity.du[k];
    tr.restored = tr.polygon.restore();
    tr.folds = tr.polygon.fold_angles(folds);
    for (int i : active_) {
      const std::size_t j = static_cast<std::size_t>(i);
      tr.change = std::max(tr.change, std::abs(tr.folds[j] - folds[j]));
      // A crease already straight to rounding (one that cannot be locked, its bar would reach π)
      // flips sign with the noise: that is not going straight.
      if (std::abs(folds[j]) > straight_tolerance && folds[j] * tr.folds[j] < 0.0) {
        tr.crosses_straight = true;
        tr.crossing.push_back(j);
      }
    }
    return tr;
  };
  double h = step / fastest;
  for (int attempt = 0; attempt < 80; ++attempt, h *= 0.5) {
    Trial tr = trial(h);
    if (!tr.restored || tr.change > frame_step) continue;
    if (tr.crosses_straight) {
      // Meet the crease where it is straight: bisect on the step for the last one before the sign flips.
      double lo = 0.0, hi = h;
      std::optional<Trial> best;
      std::vector<std::size_t> going = tr.crossing;
      for (int b = 0; b < 60; ++b) {
        const double mid = 0.5 * (lo + hi);
        Trial t = trial(mid);
        if (!t.restored || t.crosses_straight) {
          hi = mid;
          if (t.restored) going = t.crossing;
        } else {
          lo = mid;
          best = std::move(t);
          double smallest = std::numeric_limits<double>::infinity();
          for (std::size_t j : going) smallest = std::min(smallest, std::abs(best->folds[j]));
          if (smallest < straight_tolerance) break;
        }
      }
      if (!best) continue;
      tr = std::move(*best);
      h = lo;
    }
    if (min_difference(before, tr.polygon.all_distances()) < -kShrinkTolerance) continue;
    Polygon next = tr.polygon;
    std::vector<double> f = tr.folds;
    if (next.lock_straight(f, straight_tolerance) > 0) f = next.fold_angles(f);
    const double growth = min_difference(before, next.all_distances());
    if (growth < -kShrinkTolerance) continue;
    *this = std::move(next);
    out.ok = true;
    out.folds = std::move(f);
    out.min_growth = growth;
    return out;
  }
  out.message = "no step keeps every pairwise distance from shrinking (the motion is not expansive to second order)";
  return out;
}

}  // namespace foldkit::folding::detail::spherical
