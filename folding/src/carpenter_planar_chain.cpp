// Carpenter's rule for planar chains: the geometry of one step (carpenter_planar_chain.hpp).
#include "carpenter_planar_chain.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "carpenter_planar_velocity.hpp"
#include "pair_halves.hpp"

namespace foldkit::folding::planar_detail {

// Positions after turning each bar for a time h at the angular speed v gives it, laid out with
// its own length from the pinned vertex 0: lengths stay exact, and a part of the chain that v
// turns rigidly turns exactly (moving along h·v and projecting back would not). A closed chain is
// then closed by Newton steps on the bar directions (bar 0 stays pinned).
Frame2 advance(const MergedChain& chain, const Frame2& v, double h) {
  const Frame2& q = chain.q();
  const int m = chain.vertices(), bars = chain.bars();
  const std::vector<double>& len = chain.length();
  std::vector<double> phi(static_cast<std::size_t>(bars));
  for (int a = 0; a < bars; ++a) {
    const int b = chain.next(a);
    const Vec d = q[b] - q[a], dv = v[b] - v[a];
    phi[a] = std::atan2(d.y(), d.x()) + h * cross(d, dv) / d.squaredNorm();
  }
  if (chain.closed()) {
    for (int iteration = 0; iteration < 50; ++iteration) {
      Vec gap = Vec::Zero();
      Eigen::Matrix2d normal = Eigen::Matrix2d::Zero();
      for (int a = 0; a < bars; ++a) {
        const Vec u(std::cos(phi[a]), std::sin(phi[a]));
        gap += len[a] * u;
        if (a == 0) continue;
        const Vec column = len[a] * Vec(-u.y(), u.x());
        normal += column * column.transpose();
      }
      if (gap.norm() <= 1e-15 * (std::abs(q[0].x()) + std::abs(q[0].y()) + len[0]) * bars) break;
      const Vec y = normal.ldlt().solve(gap);
      for (int a = 1; a < bars; ++a) {
        const Vec u(std::cos(phi[a]), std::sin(phi[a]));
        phi[a] -= len[a] * Vec(-u.y(), u.x()).dot(y);
      }
    }
  }
  Frame2 out(static_cast<std::size_t>(m));
  out[0] = q[0];
  for (int a = 0; a + 1 < m; ++a) out[a + 1] = out[a] + len[a] * Vec(std::cos(phi[a]), std::sin(phi[a]));
  return out;
}

// Every pair of merged vertices that is not a bar keeps or grows its distance, to within the
// rounding of the coordinates: a strut across an almost straight joint grows only to second
// order in the joint angle, below what doubles resolve. A layout places vertex k by summing k
// bars from vertex 0 (advance()), so its rounding error is up to k·u·(|p₀| + total length) (the
// summation bound), and a distance compared between two layouts carries four such errors: the
// tolerance of pair (a, b) is 2·(a + b + 2)·u·(|p₀| + total length). A fixed 4u·extent, as before,
// was below that error at about 100 vertices, and convexifying star-shaped 100–150-gons stopped
// as "no step keeps every distance growing" once the first-order growth fell under it.
bool expansive(const MergedChain& chain, const Frame2& before, const Frame2& after) {
  const int m = chain.vertices();
  double reach = before[0].cwiseAbs().maxCoeff();
  for (double l : chain.length()) reach += l;
  const double unit = 2.0 * std::numeric_limits<double>::epsilon() * reach;
  const auto rounding = [&](int a, int b) { return (a + b + 2) * unit; };
  // Squared distances first, over coordinate arrays (vectorised): a pair whose squared distance
  // did not shrink passes without a square root, as sqrt is monotone.
  const detail::Coordinates from(before), to(after);
  std::atomic<bool> shrank{false};  // set by either half (pair_halves.hpp: two threads); both stop
  detail::for_two_halves(m, [&](int first, int last_a, int) {
    std::vector<double> shrunk(static_cast<std::size_t>(m));
    for (int a = first; a < last_a && !shrank.load(std::memory_order_relaxed); ++a) {
      const int last = chain.closed() && a == 0 ? m - 2 : m - 1;
      if (detail::squared_changes(from, to, a, a + 2, last, shrunk) == 0) continue;
      for (int b = a + 2; b <= last; ++b)
        if (shrunk[b] < 0.0 && (after[b] - after[a]).norm() < (before[b] - before[a]).norm() - rounding(a, b)) {
          shrank.store(true, std::memory_order_relaxed);
          break;
        }
    }
  });
  return !shrank.load();
}

double bar_length_error(const Frame2& input, const Frame2& p, bool closed) {
  const std::size_t n = input.size(), bars = closed ? n : (n == 0 ? 0 : n - 1);
  double error = 0.0;
  for (std::size_t b = 0; b < bars; ++b) {
    const std::size_t e = (b + 1) % n;
    error = std::max(error, std::abs((p[e] - p[b]).norm() - (input[e] - input[b]).norm()));
  }
  return error;
}

// A pair whose squared distance did not shrink grew by ≥ 0 (sqrt is monotone), and one whose did
// by ≤ 0: when any pair's squared distance shrank, the minimum is over those pairs alone, so only
// they need square roots; otherwise every pair does (a second pass, rare at scale, where rounding
// shrinks some pair almost every frame). Which side a pair falls on agrees with Eigen's
// squaredNorm() in check_motion() because both round x² + y² the same way: true without fused
// multiply-adds (GCC in ISO mode on x86-64, as built here); with contraction a pair within rounding
// of 0 could land on the other side, a rounding-level difference (expansive() assumes the same).
// Each half keeps its minimum in a local and writes it once, so the threads share no cache line
// per pair.
double min_distance_growth(const Frame2& before, const Frame2& after) {
  const int n = static_cast<int>(before.size());
  const detail::Coordinates from(before), to(after);
  auto growth = [&](int a, int b) { return (after[b] - after[a]).norm() - (before[b] - before[a]).norm(); };
  const double inf = std::numeric_limits<double>::infinity();
  double minimum[2] = {inf, inf};
  bool shrank[2] = {false, false};
  detail::for_two_halves(n, [&](int first, int last, int half) {
    std::vector<double> change(static_cast<std::size_t>(n));
    double lowest = inf;
    bool any = false;
    for (int a = first; a < last; ++a) {
      if (detail::squared_changes(from, to, a, a + 1, n - 1, change) == 0) continue;
      any = true;
      for (int b = a + 1; b < n; ++b)
        if (change[b] < 0.0) lowest = std::min(lowest, growth(a, b));
    }
    minimum[half] = lowest;
    shrank[half] = any;
  });
  if (shrank[0] || shrank[1]) return std::min(minimum[0], minimum[1]);
  detail::for_two_halves(n, [&](int first, int last, int half) {
    double lowest = inf;
    for (int a = first; a < last; ++a)
      for (int b = a + 1; b < n; ++b) lowest = std::min(lowest, growth(a, b));
    minimum[half] = lowest;
  });
  return std::min(minimum[0], minimum[1]);
}

// Bar directions of an open chain, unwrapped along it: each differs from the one before by the
// turn at their joint, in (−π, π].
std::vector<double> bar_directions(const MergedChain& chain) {
  const Frame2& q = chain.q();
  std::vector<double> phi(static_cast<std::size_t>(chain.bars()));
  const Vec d = q[1] - q[0];
  phi[0] = std::atan2(d.y(), d.x());
  for (int a = 1; a < chain.bars(); ++a) phi[a] = phi[a - 1] + chain.theta(q, a);
  return phi;
}

// The chain laid out from its (fixed) vertex 0 with bar a at direction phi[a], exact lengths.
Frame2 lay_out(const MergedChain& chain, const std::vector<double>& phi) {
  const std::vector<double>& len = chain.length();
  Frame2 out(static_cast<std::size_t>(chain.vertices()));
  out[0] = chain.q()[0];
  for (int a = 0; a + 1 < chain.vertices(); ++a) out[a + 1] = out[a] + len[a] * Vec(std::cos(phi[a]), std::sin(phi[a]));
  return out;
}

// Open chains whose unwrapped bar directions span at most π (monotone in some direction) are
// straightened in closed form, without LPs: every bar direction moves linearly to a common angle c,
// φₐ(s) = c + (1 − s)(φₐ − c). The vector between two points of the chain is Σ ℓₐ u(φₐ) over the
// (partial) bars between them, so its squared length is Σ ℓₐ ℓ_b cos(φₐ − φ_b); every |φₐ − φ_b|
// shrinks by the factor (1 − s) and stays ≤ π, where cos decreases: no distance between any two
// points ever shrinks. This ends the run where the LP steps are worst: on an almost straight chain
// every distance is within second order of its final value, the first-order growth the LP asks
// for is swamped by the integration error, and steps crept (a 1,000-link chain once spent 60,000
// steps at 11 merged vertices with joints at 1e-3 rad).
constexpr double kMonotoneSpread = M_PI - 1e-6;

bool finished(const MergedChain& chain) {
  if (!chain.closed()) return chain.vertices() <= 2;
  bool left = false, right = false;
  for (int a = 0; a < chain.vertices(); ++a) {
    const double t = chain.theta(chain.q(), a);
    left = left || t > 0;
    right = right || t < 0;
  }
  return !(left && right);
}

double sign(double x) { return (x > 0) - (x < 0); }

constexpr double kLookahead = 4.0;
constexpr int kFarProbes = 4;  // look 4, 16, 64 and 256 steps ahead

double mean_bar_length(const MergedChain& chain) {
  double mean = 0.0;
  for (double l : chain.length()) mean += l;
  return mean / chain.bars();
}

std::string length_drift(const Frame2& input, bool closed, double max_length_error) {
  double shortest = std::numeric_limits<double>::infinity();
  const std::size_t n = input.size(), bars = closed ? n : n - 1;
  for (std::size_t i = 0; i < bars; ++i) shortest = std::min(shortest, (input[(i + 1) % n] - input[i]).norm());
  if (!(max_length_error > 1e-9 * shortest)) return {};
  return "a bar's length drifted by " + std::to_string(max_length_error) + " (more than 1e-9 of the shortest bar, " +
         std::to_string(shortest) + "): the frames are not a rigid motion";
}

// The closed form applies while the bar directions span at most kMonotoneSpread.
bool monotone(const std::vector<double>& phi) {
  const auto [lo, hi] = std::minmax_element(phi.begin(), phi.end());
  return *hi - *lo <= kMonotoneSpread;
}

// The common final direction: the bar directions averaged by bar length.
double common_direction(const MergedChain& chain, const std::vector<double>& phi) {
  double c = 0.0, total = 0.0;
  for (int a = 0; a < chain.bars(); ++a) {
    c += chain.length()[a] * phi[a];
    total += chain.length()[a];
  }
  return c / total;
}

// Largest |turn| over the joints of an open chain.
double sharpest_joint(const MergedChain& chain) {
  double sharpest = 0.0;
  for (int a = 1; a + 1 < chain.vertices(); ++a) sharpest = std::max(sharpest, std::abs(chain.theta(chain.q(), a)));
  return sharpest;
}

// Angular speed of each bar under the velocity v.
std::vector<double> bar_rates(const MergedChain& chain, const Frame2& v) {
  std::vector<double> omega(static_cast<std::size_t>(chain.bars()));
  for (int a = 0; a < chain.bars(); ++a) {
    const int b = chain.next(a);
    const Vec d = chain.q()[b] - chain.q()[a];
    omega[a] = cross(d, v[b] - v[a]) / d.squaredNorm();
  }
  return omega;
}

// Rate at which joint a turns: the difference of its two bars' rates.
double joint_rate(const MergedChain& chain, const std::vector<double>& omega, int a) {
  const int m = chain.vertices();
  return omega[a % chain.bars()] - omega[(a + m - 1) % m];
}

double fastest_joint(const MergedChain& chain, const std::vector<double>& omega) {
  double speed = 0.0;
  for (int a = 0; a < chain.vertices(); ++a)
    if (chain.is_joint(a)) speed = std::max(speed, std::abs(joint_rate(chain, omega, a)));
  return speed;
}

// Turn of every joint (0 at the ends of an open chain).
std::vector<double> joint_angles(const MergedChain& chain) {
  const int m = chain.vertices();
  std::vector<double> theta0(static_cast<std::size_t>(m), 0.0);
  for (int a = 0; a < m; ++a)
    if (chain.is_joint(a)) theta0[a] = chain.theta(chain.q(), a);
  return theta0;
}

bool any_joint_flips(const MergedChain& chain, const Frame2& q, const std::vector<double>& theta0) {
  bool flips = false;
  for (int a = 0; a < chain.vertices() && !flips; ++a) flips = chain.is_joint(a) && turn_sign(chain, q, a) != sign(theta0[a]);
  return flips;
}

// Look ahead: a joint that would pass straight a little beyond the step is taken all the way
// there now, so no joint is left almost straight, where the LP optimum would be too small for the
// solver's tolerances.
// Farther probes catch a joint that creeps towards straight ever more slowly (its speed shrinks
// with its angle): stepping a little at a time would never reach it. Halvings back down to the
// usual step do not shrink the budget, so their count is returned. Scales h in place.
int look_ahead(const MergedChain& chain, const Frame2& v, const std::vector<double>& theta0, double& h) {
  for (int reach = 0; reach < kFarProbes; ++reach) {
    const Frame2 probe = advance(chain, v, kLookahead * h);
    if (any_joint_flips(chain, probe, theta0)) {
      h *= kLookahead;
      return 2 * reach;
    }
    if (reach + 1 < kFarProbes) h *= kLookahead;
    else h /= std::pow(kLookahead, kFarProbes - 1);
  }
  return 0;
}

// The sign of the turn at joint a of q: sign(chain.theta(q, a)) without the arc tangent where the
// cross product decides it (atan2(y, x) has the sign of y unless y is 0).
double turn_sign(const MergedChain& chain, const Frame2& q, int a) {
  const int m = chain.vertices();
  const Vec u = q[a] - q[(a + m - 1) % m], w = q[(a + 1) % m] - q[a];
  const double c = cross(u, w);
  return c != 0.0 ? sign(c) : sign(std::atan2(c, u.dot(w)));
}

// The step length within (0, h] at which joint a passes straight, from below (by bisection).
double straight_crossing(const MergedChain& chain, const Frame2& v, const std::vector<double>& omega,
                         const std::vector<double>& theta0, int a, double h) {
  double lo = 0.0, hi = h;
  // Which side joint a is on after a step of length s. An open chain's layout turns each bar at a
  // constant rate from its own direction, so the turn at a depends on bars a − 1 and a only:
  // evaluated on those two (as advance() turns them) instead of laying out the whole chain, once
  // per halving. A closed chain's closing correction moves every bar: laid out whole.
  const Frame2& q = chain.q();
  auto direction = [&](int bar, double s) {
    const Vec d = q[bar + 1] - q[bar], dv = v[bar + 1] - v[bar];
    const double phi = std::atan2(d.y(), d.x()) + s * cross(d, dv) / d.squaredNorm();
    return Vec(std::cos(phi), std::sin(phi));
  };
  auto side = [&](double s) {
    if (chain.closed()) return turn_sign(chain, advance(chain, v, s), a);
    const Vec u = direction(a - 1, s), w = direction(a, s);
    const double c = cross(u, w);
    return c != 0.0 ? sign(c) : sign(std::atan2(c, u.dot(w)));
  };
  const double before = sign(theta0[a]);
  // Open chains turn each joint at a constant rate in angle coordinates, so the crossing is near
  // −θ₀/θ̇: bisection starts from a bracket around it when the bracket holds (it spares some 30
  // of the ~50 halvings).
  const double rate = joint_rate(chain, omega, a);
  const double guess = rate != 0.0 ? -theta0[a] / rate : 0.0;
  if (!chain.closed() && guess > 0.0 && guess < h) {
    const double below = guess * (1.0 - 1e-9), above = std::min(h, guess * (1.0 + 1e-9));
    if (side(below) == before && side(above) != before) {
      lo = below;
      hi = above;
    }
  }
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    if (side(mid) == before)
      lo = mid;
    else
      hi = mid;
  }
  return lo;
}

// Steps of length h, halved until one keeps every distance growing (at most 200 tries).
StepOutcome try_steps(const MergedChain& chain, const Frame2& v, const std::vector<double>& omega,
                      const std::vector<double>& theta0, double h) {
  StepOutcome step;
  for (int attempt = 0; attempt < 200 && !step.accepted; ++attempt) {
    ++step.attempts;
    step.next = advance(chain, v, h);
    // A joint that would pass straight stops the step exactly there; it is then merged.
    step.event_joint = -1;
    for (int a = 0; a < chain.vertices(); ++a) {
      if (!chain.is_joint(a) || turn_sign(chain, step.next, a) == sign(theta0[a])) continue;
      // Joints are visited in order and `next` follows h, so a joint is bisected only when it
      // still passes straight within the step already shortened for earlier ones.
      h = straight_crossing(chain, v, omega, theta0, a, h);
      step.event_joint = a;
      step.next = advance(chain, v, h);
    }
    if (h > 0.0 && expansive(chain, chain.q(), step.next)) {
      step.accepted = true;
    } else {
      h *= 0.5;
    }
  }
  return step;
}

}  // namespace foldkit::folding::planar_detail
