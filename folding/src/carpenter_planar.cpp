// Carpenter's rule for planar chains (Connelly, Demaine & Rote; docs/CARPENTER.md): merge straight
// joints, solve the expansive-motion LP, step, restore bar lengths exactly, repeat.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "carpenter_planar_velocity.hpp"
#include "foldkit/folding/carpenter.hpp"

namespace foldkit::folding {
namespace {

using Vec = Eigen::Vector2d;
using geometry::StatusCode;

double cross(const Vec& a, const Vec& b) { return a.x() * b.y() - a.y() * b.x(); }

double turn(const Vec& a, const Vec& b, const Vec& c) {
  const Vec u = b - a, w = c - b;
  return std::atan2(cross(u, w), u.dot(w));
}

// The chain with its straight joints merged: vertex a of the merged chain is input vertex
// key[a]; merged bar a runs from key[a] to key[a + 1] (closed: the last one back to key[0]) and
// carries the input vertices between them at their arc lengths.
class MergedChain {
 public:
  MergedChain(const Frame2& points, bool closed) : closed_(closed), n_(static_cast<int>(points.size())) {
    const int bars = closed ? n_ : n_ - 1;
    arc_.assign(static_cast<std::size_t>(n_) + 1, 0.0);
    for (int b = 0; b < bars; ++b) arc_[b + 1] = arc_[b] + (points[(b + 1) % n_] - points[b]).norm();
    for (int i = 0; i < n_; ++i) key_.push_back(i);
    q_ = points;
    lengths();
  }

  bool closed() const { return closed_; }
  int vertices() const { return static_cast<int>(key_.size()); }
  int bars() const { return closed_ ? vertices() : vertices() - 1; }
  const Frame2& q() const { return q_; }
  const std::vector<double>& length() const { return length_; }
  int key(int a) const { return key_[a]; }
  int next(int a) const { return (a + 1) % vertices(); }
  // Merged vertices that are joints (not chain ends).
  bool is_joint(int a) const { return closed_ || (a > 0 && a + 1 < vertices()); }
  double theta(const Frame2& q, int a) const {
    const int m = vertices();
    return turn(q[(a + m - 1) % m], q[a], q[(a + 1) % m]);
  }

  void set_q(Frame2 q) { q_ = std::move(q); }

  // Drops merged joints a (which must be joints); the input vertices they held now lie on the
  // merged bar through their neighbours.
  void merge(const std::vector<int>& joints) {
    std::vector<char> drop(key_.size(), 0);
    for (int a : joints) drop[a] = 1;
    std::vector<int> key;
    Frame2 q;
    for (std::size_t a = 0; a < key_.size(); ++a)
      if (!drop[a]) {
        key.push_back(key_[a]);
        q.push_back(q_[a]);
      }
    key_ = std::move(key);
    q_ = std::move(q);
    lengths();
  }

  // Input-vertex positions: merged vertices where they are, the others along their merged bar.
  Frame2 expand(const Frame2& q) const {
    Frame2 p(static_cast<std::size_t>(n_));
    const int m = vertices();
    for (int a = 0; a < bars(); ++a) {
      const int b = next(a);
      const Vec d = q[b] - q[a];
      const Vec u = d / d.norm();
      p[key_[a]] = q[a];
      for (int i = (key_[a] + 1) % n_; i != key_[b]; i = (i + 1) % n_) p[i] = q[a] + along(key_[a], i) * u;
    }
    if (!closed_) p[key_[m - 1]] = q[m - 1];
    return p;
  }

 private:
  // Arc length from input vertex i forward to j (through vertex 0 of a closed chain if j ≤ i).
  double along(int i, int j) const { return j > i ? arc_[j] - arc_[i] : arc_[n_] - arc_[i] + arc_[j]; }

  void lengths() {
    length_.clear();
    for (int a = 0; a < bars(); ++a) {
      const int b = next(a);
      length_.push_back(along(key_[a], key_[b]));
    }
  }

  bool closed_;
  int n_;
  std::vector<double> arc_;  // arc length from vertex 0 to each vertex (closed: [n] = perimeter)
  std::vector<int> key_;
  Frame2 q_;
  std::vector<double> length_;
};

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
  std::vector<double> bx(m), by(m), ax(m), ay(m), shrunk(m);
  for (int a = 0; a < m; ++a) {
    bx[a] = before[a].x();
    by[a] = before[a].y();
    ax[a] = after[a].x();
    ay[a] = after[a].y();
  }
  for (int a = 0; a < m; ++a) {
    const int last = chain.closed() && a == 0 ? m - 2 : m - 1;
    bool any = false;
    for (int b = a + 2; b <= last; ++b) {
      const double ex = bx[b] - bx[a], ey = by[b] - by[a], fx = ax[b] - ax[a], fy = ay[b] - ay[a];
      shrunk[b] = (fx * fx + fy * fy) - (ex * ex + ey * ey);
      any = any || shrunk[b] < 0.0;
    }
    if (!any) continue;
    for (int b = a + 2; b <= last; ++b)
      if (shrunk[b] < 0.0 && (after[b] - after[a]).norm() < (before[b] - before[a]).norm() - rounding(a, b)) return false;
  }
  return true;
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
  for (int a = 0; a < chain.vertices() && !flips; ++a) flips = chain.is_joint(a) && sign(chain.theta(q, a)) != sign(theta0[a]);
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

// The step length within (0, h] at which joint a passes straight, from below (by bisection).
double straight_crossing(const MergedChain& chain, const Frame2& v, const std::vector<double>& omega,
                         const std::vector<double>& theta0, int a, double h) {
  double lo = 0.0, hi = h;
  // Open chains turn each joint at a constant rate in angle coordinates, so the crossing is near
  // −θ₀/θ̇: bisection starts from a bracket around it when the bracket holds (it spares some 30
  // of the ~50 halvings, each a layout of the whole chain).
  const double rate = joint_rate(chain, omega, a);
  const double guess = rate != 0.0 ? -theta0[a] / rate : 0.0;
  if (!chain.closed() && guess > 0.0 && guess < h) {
    const double below = guess * (1.0 - 1e-9), above = std::min(h, guess * (1.0 + 1e-9));
    if (sign(chain.theta(advance(chain, v, below), a)) == sign(theta0[a]) &&
        sign(chain.theta(advance(chain, v, above), a)) != sign(theta0[a])) {
      lo = below;
      hi = above;
    }
  }
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    if (sign(chain.theta(advance(chain, v, mid), a)) == sign(theta0[a]))
      lo = mid;
    else
      hi = mid;
  }
  return lo;
}

struct StepOutcome {
  Frame2 next;
  int event_joint = -1;  // the joint the step ends at, straight; -1: none
  bool accepted = false;
  int attempts = 0;
};

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
      if (!chain.is_joint(a) || sign(chain.theta(step.next, a)) == sign(theta0[a])) continue;
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

// One run of carpenter_planar: the merged chain, the result it fills and what carries from one
// step to the next.
class PlanarRun {
 public:
  PlanarRun(const PlanarChain& input, const CarpenterPlanarOptions& options)
      : input_(input),
        options_(options),
        closed_(input.closed),
        chain_(input.points, input.closed),
        mean_bar_(mean_bar_length(chain_)),
        stride_(std::max<std::size_t>(1, options.frame_stride)),
        turn_budget_(options.max_turn) {
    result_.closed = closed_;
  }

  CarpenterPlanarResult run() {
    merge_straight_input();
    record(chain_.expand(chain_.q()));
    while (!finished(chain_)) {
      if (result_.steps >= options_.max_steps) {
        result_.status = {StatusCode::LimitReached, "stopped after " + std::to_string(options_.max_steps) + " steps"};
        break;
      }
      if (!closed_ && !monotone_failed_) {
        const std::vector<double> phi = bar_directions(chain_);
        if (monotone(phi)) {
          straighten_monotone(phi);
          continue;
        }
      }
      if (!lp_step()) break;
    }
    if (!pending_.empty()) record(pending_);
    if (finished(chain_)) result_.status = {StatusCode::Success, closed_ ? "convex" : "straight"};
    result_.min_distance_growth = std::isinf(min_growth_) ? 0.0 : min_growth_;
    return std::move(result_);
  }

 private:
  void record(const Frame2& p) {
    if (!last_recorded_.empty()) {
      const MotionCheck c = check_motion({last_recorded_, p}, closed_);
      min_growth_ = std::min(min_growth_, c.min_distance_growth);
    }
    const MotionCheck lengths = check_motion({input_.points, p}, closed_);
    result_.max_length_error = std::max(result_.max_length_error, lengths.max_length_error);
    result_.frames.push_back(p);
    last_recorded_ = p;
  }

  // Every `stride`-th step's frame is recorded, the last one always; the others wait in `pending`.
  void record_step() {
    const Frame2 p = chain_.expand(chain_.q());
    if (result_.steps % stride_ == 0 || finished(chain_)) {
      record(p);
      pending_.clear();
    } else {
      pending_ = p;
    }
  }

  // Joints straight in the input (within rounding) are rigid from the start: an expansive motion
  // cannot open them further, so the LP would have no strictly expansive solution.
  void merge_straight_input() {
    std::vector<int> straight;
    for (int a = 0; a < chain_.vertices(); ++a)
      if (chain_.is_joint(a) && std::abs(chain_.theta(chain_.q(), a)) <= 1e-12) straight.push_back(a);
    if (closed_ && chain_.vertices() - static_cast<int>(straight.size()) < 3) return;  // a flat polygon: rejected earlier
    if (!straight.empty()) chain_.merge(straight);
  }

  // Every bar direction moves linearly to their common direction in `pieces` steps, each checked
  // like an LP step; a failed check hands the chain back to the LP steps for good.
  void straighten_monotone(const std::vector<double>& phi) {
    const double c = common_direction(chain_, phi);
    // Joints turn by θₖ/pieces per step, at most max_turn.
    const int pieces = std::max(1, static_cast<int>(std::ceil(sharpest_joint(chain_) / options_.max_turn)));
    for (int k = 1; k <= pieces && !monotone_failed_; ++k) {
      if (result_.steps >= options_.max_steps) break;
      const double s = static_cast<double>(k) / pieces;
      std::vector<double> to(phi.size());
      for (std::size_t a = 0; a < phi.size(); ++a) to[a] = k == pieces ? c : c + (1.0 - s) * (phi[a] - c);
      const Frame2 next = lay_out(chain_, to);
      // The argument above kMonotoneSpread, checked like every LP step (rounding could only
      // matter at a spread of π, which the threshold keeps away from).
      if (!expansive(chain_, chain_.q(), next)) {
        monotone_failed_ = true;
        break;
      }
      chain_.set_q(next);
      ++result_.steps;
      if (k == pieces) {
        std::vector<int> joints;
        for (int a = 1; a + 1 < chain_.vertices(); ++a) joints.push_back(a);
        chain_.merge(joints);
      }
      record_step();
    }
  }

  // Struts carried over from the last step, renumbered after merges.
  std::vector<std::pair<int, int>> seed_struts() const {
    const int m = chain_.vertices();
    std::vector<int> merged_index(input_.points.size(), -1);
    for (int a = 0; a < m; ++a) merged_index[chain_.key(a)] = a;
    std::vector<std::pair<int, int>> seed;
    for (const auto& [i, j] : carried_)
      if (merged_index[i] >= 0 && merged_index[j] >= 0) seed.emplace_back(merged_index[i], merged_index[j]);
    return seed;
  }

  // The expansive velocity of the current chain; false (with the status set) when there is none.
  bool solve_velocity(detail::ExpansiveVelocity& field) {
    const int m = chain_.vertices();
    std::vector<int> keys(static_cast<std::size_t>(m));
    for (int a = 0; a < m; ++a) keys[a] = chain_.key(a);
    const std::vector<std::pair<int, int>> seed = seed_struts();
    const double mean_merged = mean_bar_length(chain_);
    field = detail::expansive_velocity(chain_.q(), closed_, seed, options_.near_radius * mean_merged, options_.all_struts,
                                       &keys, &basis_memo_);
    result_.lp_solves += field.lp_solves;
    result_.max_struts = std::max(result_.max_struts, field.struts);
    if (!field.solved) {
      result_.status = {StatusCode::NoProgress,
                        "the expansive-motion LP failed at step " + std::to_string(result_.steps) + " (" + field.status + ")"};
      return false;
    }
    if (!(field.t > 0.0)) {
      result_.status = {StatusCode::NoProgress, "no strictly expansive motion found at step " + std::to_string(result_.steps) +
                                                    " (smallest weighted strut rate " + std::to_string(field.t) + ")"};
      return false;
    }
    carried_.clear();
    for (const auto& [a, b] : field.binding) carried_.emplace_back(chain_.key(a), chain_.key(b));
    return true;
  }

  // One LP step: solve for the velocity, size the step, take it, merge what it straightened.
  // False (with the status set) when the run cannot go on.
  bool lp_step() {
    detail::ExpansiveVelocity field;
    if (!solve_velocity(field)) return false;
    // The step turns the fastest joint by about `turn_budget` radians: far vertices may sweep a
    // long way when a large part of the chain turns almost rigidly, which angle coordinates
    // integrate exactly. The budget grows while steps pass at once and shrinks when halved.
    const std::vector<double> omega = bar_rates(chain_, field.v);
    double h = turn_budget_ / fastest_joint(chain_, omega);
    const std::vector<double> theta0 = joint_angles(chain_);
    const int free_halvings = look_ahead(chain_, field.v, theta0, h);
    const StepOutcome step = try_steps(chain_, field.v, omega, theta0, h);
    const int halvings = std::max(0, step.attempts - 1 - free_halvings);
    turn_budget_ = halvings == 0 ? std::min(turn_budget_ * 1.5, options_.max_turn) : turn_budget_ * std::pow(0.5, halvings);
    if (!step.accepted) {
      result_.status = {StatusCode::NoProgress, "no step keeps every distance growing at step " + std::to_string(result_.steps)};
      return false;
    }
    const int m = chain_.vertices();
    chain_.set_q(step.next);
    ++result_.steps;
    if (options_.progress) options_.progress({static_cast<double>(result_.steps), 0.0, "steps", -1.0});
    merge_after_step(step.next, step.event_joint, m);
    record_step();
    return true;
  }

  // Merges the event joint and any other joint the step left straight to within rounding.
  void merge_after_step(const Frame2& next, int event_joint, int m) {
    std::vector<int> straight;
    for (int a = 0; a < m; ++a) {
      if (!chain_.is_joint(a)) continue;
      const double t = chain_.theta(next, a);
      const double reach = std::min(chain_.length()[(a + m - 1) % m], chain_.length()[a % chain_.bars()]);
      if (a == event_joint || std::abs(t) * reach <= 1e-13 * mean_bar_) straight.push_back(a);
    }
    if (!straight.empty()) chain_.merge(straight);
  }

  const PlanarChain& input_;
  const CarpenterPlanarOptions& options_;
  const bool closed_;
  MergedChain chain_;
  const double mean_bar_;  // of the input's bars
  const std::size_t stride_;
  double turn_budget_;
  CarpenterPlanarResult result_;
  double min_growth_ = std::numeric_limits<double>::infinity();
  Frame2 last_recorded_;
  Frame2 pending_;                            // the last unrecorded frame (frame_stride > 1)
  detail::BasisMemo basis_memo_;              // the last LP's optimal basis: the next starts there
  std::vector<std::pair<int, int>> carried_;  // binding struts of the last step, as input vertices
  bool monotone_failed_ = false;              // the closed-form straightening was tried and a check failed
};

}  // namespace

CarpenterPlanarResult carpenter_planar(const PlanarChain& input, const CarpenterPlanarOptions& options) {
  check_simple_chain(input);
  const auto start = std::chrono::steady_clock::now();
  CarpenterPlanarResult result = PlanarRun(input, options).run();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace foldkit::folding
