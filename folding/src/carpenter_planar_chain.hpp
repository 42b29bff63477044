#pragma once
// Carpenter's rule for planar chains, private to foldkit::folding: the chain with its straight
// joints merged, and the geometry of one step (advance, the expansive test, the look-ahead and
// the halving of steps). carpenter_planar.cpp runs the steps (docs/CARPENTER.md).
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "foldkit/folding/carpenter.hpp"

namespace foldkit::folding::planar_detail {

using Vec = Eigen::Vector2d;

inline double cross(const Vec& a, const Vec& b) { return a.x() * b.y() - a.y() * b.x(); }

// The signed turn at b of the path a → b → c, radians in (−π, π].
inline double turn(const Vec& a, const Vec& b, const Vec& c) {
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
Frame2 advance(const MergedChain& chain, const Frame2& v, double h);

// Every pair of merged vertices that is not a bar keeps or grows its distance, to within the
// rounding of the coordinates: a strut across an almost straight joint grows only to second
// order in the joint angle, below what doubles resolve. A layout places vertex k by summing k
// bars from vertex 0 (advance()), so its rounding error is up to k·u·(|p₀| + total length) (the
// summation bound), and a distance compared between two layouts carries four such errors: the
// tolerance of pair (a, b) is 2·(a + b + 2)·u·(|p₀| + total length). A fixed 4u·extent, as before,
// was below that error at about 100 vertices, and convexifying star-shaped 100–150-gons stopped
// as "no step keeps every distance growing" once the first-order growth fell under it.
bool expansive(const MergedChain& chain, const Frame2& before, const Frame2& after);

// What record() reports of each frame, without check_motion()'s generic loops: the largest |bar
// length − its length in `input`| of frame p (O(n)), and the smallest |after_j − after_i| −
// |before_j − before_i| over all vertex pairs (+inf for fewer than two vertices), exactly as
// check_motion() computes it (but for frames whose every pair is NaN: +inf there, 0 from
// check_motion), over coordinate arrays on two threads (pair_halves.hpp). At stride 1
// a frame is recorded per step, and check_motion() run twice a frame (the second only for the
// lengths, with an all-pairs loop whose result was dropped) was ~13·10⁹ pair evaluations for a
// 3,000-link chain's ~1,500 steps.
double bar_length_error(const Frame2& input, const Frame2& p, bool closed);
double min_distance_growth(const Frame2& before, const Frame2& after);

// Bar directions of an open chain, unwrapped along it: each differs from the one before by the
// turn at their joint, in (−π, π].
std::vector<double> bar_directions(const MergedChain& chain);

// The chain laid out from its (fixed) vertex 0 with bar a at direction phi[a], exact lengths.
Frame2 lay_out(const MergedChain& chain, const std::vector<double>& phi);

// Done: an open chain merged to one bar (straight), a closed one turning one way only (convex).
bool finished(const MergedChain& chain);

// −1, 0 or 1.
double sign(double x);

// Mean length of the merged bars.
double mean_bar_length(const MergedChain& chain);

// The contract on the frames' bars (each within 1e-9 of the shortest input bar of its input
// length) checked on the largest error found, `max_length_error`: empty when it holds, else why
// not. Every method's steps keep lengths to rounding; this makes a drift a failure, not a result.
std::string length_drift(const Frame2& input, bool closed, double max_length_error);

// The closed form applies while the bar directions span at most kMonotoneSpread.
bool monotone(const std::vector<double>& phi);

// The common final direction: the bar directions averaged by bar length.
double common_direction(const MergedChain& chain, const std::vector<double>& phi);

// Largest |turn| over the joints of an open chain.
double sharpest_joint(const MergedChain& chain);

// Angular speed of each bar under the velocity v.
std::vector<double> bar_rates(const MergedChain& chain, const Frame2& v);

// Rate at which joint a turns: the difference of its two bars' rates.
double joint_rate(const MergedChain& chain, const std::vector<double>& omega, int a);

// Largest |joint_rate| over the joints.
double fastest_joint(const MergedChain& chain, const std::vector<double>& omega);

// Turn of every joint (0 at the ends of an open chain).
std::vector<double> joint_angles(const MergedChain& chain);

// The sign of the turn at joint a of q (−1, 0, 1): sign(chain.theta(q, a)), cheaper.
double turn_sign(const MergedChain& chain, const Frame2& q, int a);

// Whether some joint turns the other way at q than in theta0 (it passed straight).
bool any_joint_flips(const MergedChain& chain, const Frame2& q, const std::vector<double>& theta0);

// Look ahead: a joint that would pass straight a little beyond the step is taken all the way
// there now, so no joint is left almost straight, where the LP optimum would be too small for the
// solver's tolerances.
// Farther probes catch a joint that creeps towards straight ever more slowly (its speed shrinks
// with its angle): stepping a little at a time would never reach it. Halvings back down to the
// usual step do not shrink the budget, so their count is returned. Scales h in place.
int look_ahead(const MergedChain& chain, const Frame2& v, const std::vector<double>& theta0, double& h);

// The step length within (0, h] at which joint a passes straight, from below (by bisection).
double straight_crossing(const MergedChain& chain, const Frame2& v, const std::vector<double>& omega,
                         const std::vector<double>& theta0, int a, double h);

// What try_steps() found.
struct StepOutcome {
  Frame2 next;
  int event_joint = -1;  // the joint the step ends at, straight; -1: none
  bool accepted = false;
  int attempts = 0;
};

// Steps of length h, halved until one keeps every distance growing (at most 200 tries).
StepOutcome try_steps(const MergedChain& chain, const Frame2& v, const std::vector<double>& omega,
                      const std::vector<double>& theta0, double h);

}  // namespace foldkit::folding::planar_detail
