#pragma once
// The struts of the planar Carpenter's-rule LP, private to foldkit::folding: how a vertex pair's
// growth rate is weighted and written, and the all-pairs check of a candidate field. Shared by
// the LP (carpenter_planar_velocity.cpp) and the local repair of a carried field
// (carpenter_planar_repair.cpp).
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "pair_halves.hpp"

namespace foldkit::folding::detail::struts {

using Vec = Eigen::Vector2d;

// Struts whose chain arc holds at most this many vertices are written through the joint speeds.
constexpr int kShortArc = 8;

inline double cross(const Vec& a, const Vec& b) { return a.x() * b.y() - a.y() * b.x(); }

// The LP, for vertices p: columns v (2 per vertex), then one joint speed θ̇ and one |θ̇| bound
// per joint. A strut (a, b) grows at (v_b − v_a)·(p_b − p_a); when the chain arc from a to b is
// short this equals Σ θ̇_k · cross(p_b − p_k, p_b − p_a) over the joints k on the arc, which is
// how those struts are written: an almost straight joint makes the Cartesian form a difference
// of nearly equal terms, the joint form does not.
class StrutModel {
 public:
  StrutModel(const std::vector<Vec>& p, bool closed) : p_(p), closed_(closed), m_(static_cast<int>(p.size())) {
    const int bars = closed ? m_ : m_ - 1;
    for (int a = 0; a < bars; ++a) mean_bar_ += (p[(a + 1) % m_] - p[a]).norm();
    mean_bar_ /= bars;
  }

  int vertices() const { return m_; }
  bool closed() const { return closed_; }
  double mean_bar() const { return mean_bar_; }
  bool is_joint(int k) const { return closed_ || (k > 0 && k + 1 < m_); }
  bool is_bar(int a, int b) const {
    if (a > b) std::swap(a, b);
    return b == a + 1 || (closed_ && a == 0 && b == m_ - 1);
  }

  // A strut as a weighted row: w·rate ≥ 1, with rate = Σ coefficient·θ̇ (joint form, `joints`
  // non-empty) or d·(v_b − v_a) (Cartesian form).
  struct Row {
    std::vector<std::pair<int, double>> joints;  // (vertex k, w·cross)
    Vec d = Vec::Zero();                         // w·(p_b − p_a)
    int a = 0, b = 0;
  };

  // The weight makes the rows comparable: 1/distance (relative to the mean bar) so that far
  // pairs, whose distance the integration error disturbs most, grow in proportion; and, for a
  // short arc whose vertices lie almost on the line ab (joints nearly straight), the inverse of
  // their total distance from it, so that the row asks for joint speeds of order one instead of
  // speeds that grow without bound as the joints straighten. Any positive weight leaves the
  // strut strictly expansive.
  Row row(int a, int b) const {
    Row r;
    r.a = a;
    r.b = b;
    const double distance = (p_[b] - p_[a]).norm();
    double weight = mean_bar_ / distance;
    const int forward = b - a - 1, backward = closed_ ? m_ - (b - a) - 1 : kShortArc + 1;
    if (std::min(forward, backward) <= kShortArc) {
      const int from = forward <= backward ? a : b, to = forward <= backward ? b : a;
      const Vec line = p_[to] - p_[from];
      double room = 0.0;
      for (int k = (from + 1) % m_; k != to; k = (k + 1) % m_) room += std::abs(cross(line, p_[k] - p_[from])) / distance;
      if (room < mean_bar_) weight *= mean_bar_ / std::max(room, 1e-12 * mean_bar_);
      for (int k = (from + 1) % m_; k != to; k = (k + 1) % m_)
        r.joints.emplace_back(k, weight * cross(p_[to] - p_[k], line));
    } else {
      r.d = weight * (p_[b] - p_[a]);
    }
    return r;
  }

  double weighted_rate(const Row& r, const std::vector<Vec>& v, const std::vector<double>& joint_speed) const {
    if (!r.joints.empty()) {
      double rate = 0.0;
      for (const auto& [k, c] : r.joints) rate += c * joint_speed[k];
      return rate;
    }
    return r.d.dot(v[r.b] - v[r.a]);
  }

 private:
  const std::vector<Vec>& p_;
  bool closed_;
  int m_;
  double mean_bar_ = 0.0;
};

// Calls f(a, b, weighted rate) for every pair a < b that is not a bar and whose weighted rate is
// below kRateCap: the O(n²) check of a candidate field. Short-arc pairs go through
// StrutModel::row(); the far pairs, nearly all of them, through the Cartesian rate
// mean_bar·(p_b − p_a)·(v_b − v_a)/|p_b − p_a|, screened without a square root (rate < cap ⇔
// dot < 0 or (mean_bar·dot)² < cap²·|p_b − p_a|²) in plain loops over coordinate arrays that the
// compiler vectorises. (Building a Row per pair made this check a tenth of the planner's time at
// 1,000 links.) The pairs are scanned in two halves on two threads (pair_halves.hpp); f is called
// on the calling thread only, in the order of a single pass.
constexpr double kRateCap = 2.0;

template <typename F>
void for_each_low_rate(const StrutModel& model, const std::vector<Vec>& p, const std::vector<Vec>& v,
                       const std::vector<double>& joint_speed, F&& f) {
  const int m = model.vertices();
  const auto size = static_cast<std::size_t>(m);
  const Coordinates position(p), velocity(v);
  const std::vector<double>&px = position.x, &py = position.y, &vx = velocity.x, &vy = velocity.y;
  const double mean_bar = model.mean_bar();
  struct Low {
    int a, b;
    double rate;
  };
  // The first half (pair_halves.hpp) runs on this thread and calls f as it goes; the second
  // half's pairs wait in `later` and are handed to f after it, so f sees the order of one pass.
  std::vector<Low> later;
  for_two_halves(m, [&](int first, int last, int half) {
    std::vector<double> scaled_dot(size), squared(size);
    auto report = [&](int a, int b, double g) {
      if (half == 0)
        f(a, b, g);
      else
        later.push_back({a, b, g});
    };
    auto short_pair = [&](int a, int b) {
      if (model.is_bar(a, b)) return;
      const double g = model.weighted_rate(model.row(a, b), v, joint_speed);
      if (g < kRateCap) report(a, b, g);
    };
    for (int a = first; a < last; ++a) {
      // Far pairs: b in [far_lo, far_hi], where the chain arc both ways holds more than kShortArc
      // vertices (the Cartesian form of StrutModel::row()).
      const int far_lo = a + kShortArc + 2;
      const int far_hi = model.closed() ? std::min(m - 1, a + m - kShortArc - 2) : m - 1;
      for (int b = a + 2; b < std::min(far_lo, m); ++b) short_pair(a, b);
      if (far_lo <= far_hi) {
        const double ax = px[a], ay = py[a], avx = vx[a], avy = vy[a];
        bool any = false;
        for (int b = far_lo; b <= far_hi; ++b) {
          const double dx = px[b] - ax, dy = py[b] - ay;
          const double s = mean_bar * (dx * (vx[b] - avx) + dy * (vy[b] - avy)), d2 = dx * dx + dy * dy;
          scaled_dot[b] = s;
          squared[b] = d2;
          any = any || s < 0.0 || s * s < kRateCap * kRateCap * d2;
        }
        if (any)
          for (int b = far_lo; b <= far_hi; ++b) {
            const double s = scaled_dot[b], d2 = squared[b];
            if (s < 0.0 || s * s < kRateCap * kRateCap * d2) report(a, b, s / std::sqrt(d2));
          }
      }
      for (int b = std::max(far_hi + 1, far_lo); b < m; ++b) short_pair(a, b);
    }
  });
  for (const Low& l : later) f(l.a, l.b, l.rate);
}

}  // namespace foldkit::folding::detail::struts
