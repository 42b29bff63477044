// The curved step of issue 36 (detail::bend(), carpenter_planar_repair.cpp): joint accelerations
// that keep far pairs growing to second order, against an oracle that shares none of its code:
// the chain laid out here from its joint angles θ₀ + s·θ̇ + ½s²·θ̈ and each pair's squared
// distance differentiated numerically along that path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "../../folding/src/carpenter_planar_chain.hpp"
#include "../../folding/src/carpenter_planar_struts.hpp"
#include "../../folding/src/carpenter_planar_velocity.hpp"
#include "carpenter_inputs.hpp"
#include "foldkit/folding/carpenter.hpp"

namespace {

using namespace foldkit::folding;
using Vec = Eigen::Vector2d;

double cross(const Vec& a, const Vec& b) { return a.x() * b.y() - a.y() * b.x(); }

// The open chain p with each joint k turned by s·speed_k + ½s²·accel_k, bar 0 fixed, laid out bar
// by bar from vertex 0 with the input lengths.
Frame2 curved_layout(const Frame2& p, const std::vector<double>& speed, const std::vector<double>& accel, double s) {
  const int n = static_cast<int>(p.size());
  Frame2 q(p.size());
  q[0] = p[0];
  double turn = 0.0;  // the turn of bar a relative to its input direction
  for (int a = 0; a + 1 < n; ++a) {
    if (a > 0) turn += s * speed[a] + 0.5 * s * s * accel[a];
    const Vec d = p[a + 1] - p[a];
    const double c = std::cos(turn), t = std::sin(turn);
    q[a + 1] = q[a] + Vec(c * d.x() - t * d.y(), t * d.x() + c * d.y());
  }
  return q;
}

struct Field {
  Frame2 p;
  std::vector<double> speed;
};

// A lattice walk and the joint speeds of its expansive LP field.
Field walk_field(int links, unsigned seed) {
  Field f{foldkit::microbench::random_lattice_walk(links, seed), {}};
  const int n = static_cast<int>(f.p.size());
  const detail::ExpansiveVelocity lp = detail::expansive_velocity(f.p, false, {}, 1.0, false);
  EXPECT_TRUE(lp.solved);
  f.speed.assign(f.p.size(), 0.0);
  for (int k = 1; k + 1 < n; ++k) {
    const Vec u = f.p[k] - f.p[k - 1], w = f.p[k + 1] - f.p[k];
    f.speed[k] = cross(w, lp.v[k + 1] - lp.v[k]) / w.squaredNorm() - cross(u, lp.v[k] - lp.v[k - 1]) / u.squaredNorm();
  }
  return f;
}

// Far pairs (more than kShortArc vertices between them) whose squared distance, by central
// differences along the curved path at s = 0, gives back more than `share` of its first-order
// growth by s = h: f̈·h < −2·share·ḟ.
int bent_far_pairs(const Field& f, const std::vector<double>& accel, double h, double share) {
  const double e = 1e-4 * h;
  const Frame2 minus = curved_layout(f.p, f.speed, accel, -e), plus = curved_layout(f.p, f.speed, accel, e);
  const int n = static_cast<int>(f.p.size());
  int bent = 0;
  for (int a = 0; a < n; ++a)
    for (int b = a + detail::struts::kShortArc + 2; b < n; ++b) {
      const double f0 = 0.5 * (f.p[b] - f.p[a]).squaredNorm(), fm = 0.5 * (minus[b] - minus[a]).squaredNorm(),
                   fp = 0.5 * (plus[b] - plus[a]).squaredNorm();
      const double rate = (fp - fm) / (2 * e), second = (fp - 2 * f0 + fm) / (e * e);
      if (rate > 0.0 && second * h < -2.0 * share * rate) ++bent;
    }
  return bent;
}

// Pairs (a, b ≥ a + 2) whose distance at s = h is below the one at s = 0.
int shrinking_pairs(const Field& f, const std::vector<double>& accel, double h) {
  const Frame2 q = curved_layout(f.p, f.speed, accel, h);
  const int n = static_cast<int>(f.p.size());
  int shrunk = 0;
  for (int a = 0; a < n; ++a)
    for (int b = a + 2; b < n; ++b) shrunk += (q[b] - q[a]).norm() < (f.p[b] - f.p[a]).norm();
  return shrunk;
}

// A step long enough that the straight path (θ̈ = 0) lets far pairs shrink: bend() finds θ̈ with
// which no far pair gives back more than half its first-order growth to second order (the oracle
// allows 0.6 for the finite differences), and fewer pairs shrink over the whole step.
TEST(CarpenterBend, CurvedStepKeepsFarPairsGrowingToSecondOrder) {
  for (const unsigned seed : {1u, 2u}) {
    const Field f = walk_field(300, seed);
    double fastest = 0.0;
    for (double s : f.speed) fastest = std::max(fastest, std::abs(s));
    const double h = 1.0 / fastest;  // a full radian at the fastest joint
    const std::vector<double> none(f.p.size(), 0.0);
    const int bent_straight = bent_far_pairs(f, none, h, 0.5);
    ASSERT_GT(bent_straight, 0) << "seed " << seed << ": the straight step bends no far pair; nothing to test";

    const detail::BentPath path = detail::bend(f.p, f.speed, h, static_cast<int>(f.p.size()));
    ASSERT_TRUE(path.bent) << seed;
    EXPECT_EQ(path.rounds_left, 0u) << seed;
    EXPECT_EQ(bent_far_pairs(f, path.accel, h, 0.6), 0) << "seed " << seed << " (straight: " << bent_straight << ")";
    // u is θ̈ laid out as velocities, as along() takes it.
    const std::vector<Vec> u = detail::open_chain_velocities(f.p, path.accel);
    for (std::size_t i = 0; i < u.size(); ++i) EXPECT_LT((u[i] - path.u[i]).norm(), 1e-12 * (1.0 + u[i].norm())) << i;
    EXPECT_LT(shrinking_pairs(f, path.accel, h), shrinking_pairs(f, none, h)) << seed;
  }
}

// A field whose steps bend nothing (a tiny h): bend() leaves the path straight and solves no LP.
TEST(CarpenterBend, ShortStepIsLeftStraight) {
  const Field f = walk_field(120, 3);
  const detail::BentPath path = detail::bend(f.p, f.speed, 1e-9, static_cast<int>(f.p.size()));
  EXPECT_FALSE(path.bent);
  EXPECT_EQ(path.lp_solves, 0u);
  for (double a : path.accel) EXPECT_EQ(a, 0.0);
}

}  // namespace
