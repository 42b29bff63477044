// The carried field's repair (carpenter_planar_repair.cpp: window LPs written over running sums)
// and the all-pairs checks split over two threads
// (pair_halves.hpp), against oracles that share neither: every pair's rate summed joint by joint,
// every pair's distance compared directly, at sizes where the checks do run on two threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <thread>
#include <cmath>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "../../folding/src/carpenter_planar_chain.hpp"
#include "../../folding/src/carpenter_planar_struts.hpp"
#include "../../folding/src/carpenter_planar_velocity.hpp"
#include "../../folding/src/linear_program.hpp"
#include "../../folding/src/pair_halves.hpp"
#include "carpenter_inputs.hpp"
#include "foldkit/folding/carpenter.hpp"

namespace {

using namespace foldkit::folding;
using Vec = Eigen::Vector2d;

double cross(const Vec& a, const Vec& b) { return a.x() * b.y() - a.y() * b.x(); }

// The rate at which |p_b − p_a| grows when the joints turn at `speed` (an open chain, bar 0
// fixed): Σ over the joints k strictly between a and b of θ̇_k·cross(p_b − p_k, p_b − p_a) / |p_b − p_a|,
// summed joint by joint (the window LP writes it over running sums, the field through velocities).
double pair_rate(const Frame2& p, const std::vector<double>& speed, int a, int b) {
  const Vec d = p[b] - p[a];
  double rate = 0.0;
  for (int k = a + 1; k < b; ++k) rate += speed[k] * cross(p[b] - p[k], d);
  return rate / d.norm();
}

// A chain whose field was solved, then lost its fastest joint (the joint's vertex dropped, as a
// merge drops a joint that went straight, the other joints keeping their speeds): the window LP
// mends it, and every pair grows under the mended speeds, by the joint-by-joint sum.
TEST(CarpenterRepair, WindowLpMendsAFieldThatLostItsFastestJoint) {
  for (const int links : {120, 450}) {
    const Frame2 p = foldkit::microbench::random_lattice_walk(links, 4);
    const int n = static_cast<int>(p.size());
    const detail::ExpansiveVelocity lp = detail::expansive_velocity(p, false, {}, 1.0, false);
    ASSERT_TRUE(lp.solved) << links;
    std::vector<double> speed(static_cast<std::size_t>(n), 0.0);
    for (int k = 1; k + 1 < n; ++k) {  // joint speed = difference of its bars' turning rates
      const Vec u = p[k] - p[k - 1], w = p[k + 1] - p[k];
      speed[k] = cross(w, lp.v[k + 1] - lp.v[k]) / w.squaredNorm() - cross(u, lp.v[k] - lp.v[k - 1]) / u.squaredNorm();
    }
    const int lost = static_cast<int>(std::max_element(speed.begin() + 1, speed.end() - 1, [](double x, double y) {
                                        return std::abs(x) < std::abs(y);
                                      }) - speed.begin());
    Frame2 q = p;
    q.erase(q.begin() + lost);
    speed.erase(speed.begin() + lost);
    const int m = n - 1;
    int weak_before = 0;
    for (int a = 0; a < m; ++a)
      for (int b = a + 2; b < m; ++b) weak_before += pair_rate(q, speed, a, b) <= 0.0;
    ASSERT_GT(weak_before, 0) << "losing the fastest joint weakened no pair: nothing to mend at " << links;

    // Bar lost − 1 (from vertex lost − 1 to the old vertex lost + 1) is the one that lost a joint.
    const detail::CarriedVelocity mended = detail::carried_velocity(q, speed, {lost - 1}, 0.5, m);
    ASSERT_TRUE(mended.solved) << links;
    EXPECT_GE(mended.lp_solves, 1u);
    EXPECT_GE(mended.t, 0.5);
    double slowest = INFINITY;
    for (int a = 0; a < m; ++a)
      for (int b = a + 2; b < m; ++b) slowest = std::min(slowest, pair_rate(q, mended.speed, a, b));
    EXPECT_GT(slowest, 0.0) << links << " links: some pair shrinks under the mended field";
    // The field is the one the speeds give (bar 0 fixed).
    const std::vector<Vec> v = detail::open_chain_velocities(q, mended.speed);
    for (int i = 0; i < m; ++i) EXPECT_LT((v[i] - mended.v[i]).norm(), 1e-9 * (1.0 + v[i].norm())) << i;
  }
}

// The window LP (rows over running sums) against the same LP written joint by joint in the test,
// each far pair's row Σₖ θ̇ₖ·cross(p_b − pₖ, w·(p_b − pₐ)) over the window joints between its ends:
// the same optimum Σ|θ̇|, and the speeds found satisfy every row evaluated from the velocities.
TEST(CarpenterRepair, WindowLpOverRunningSumsHasTheOptimumOfTheJointByJointLp) {
  const Frame2 p = foldkit::microbench::random_lattice_walk(450, 6);
  const int m = static_cast<int>(p.size());
  std::vector<double> speed(static_cast<std::size_t>(m), 0.0);
  for (int k = 1; k + 1 < m; ++k) speed[k] = 0.05 * std::sin(0.7 * k);
  std::vector<char> in(static_cast<std::size_t>(m), 0);
  for (int k = 150; k < 230; ++k) in[k] = 1;
  const detail::struts::StrutModel model(p, false);
  const std::vector<Vec> v0 = detail::open_chain_velocities(p, speed);
  std::vector<std::pair<double, std::pair<int, int>>> weak;  // pairs with a window joint inside
  detail::struts::for_each_low_rate(model, p, v0, speed, [&](int a, int b, double g) {
    if (a < 229 && b > 151) weak.push_back({g, {a, b}});
  });
  std::sort(weak.begin(), weak.end());
  ASSERT_GT(weak.size(), 400u);
  std::set<std::pair<int, int>> rows;
  for (std::size_t i = 0; i < 400; ++i) rows.insert(weak[i].second);

  detail::LinearProgram dense;  // the oracle: θ̇⁺, θ̇⁻ per window joint, one entry per joint a row
  std::vector<int> column(static_cast<std::size_t>(m), -1);
  for (int k = 0; k < m; ++k)
    if (in[k]) {
      column[k] = dense.add_column(0.0, 1e12, 1.0);
      dense.add_column(0.0, 1e12, 1.0);
    }
  for (const auto& [a, b] : rows) {
    const detail::struts::StrutModel::Row r = model.row(a, b);
    std::vector<std::pair<int, double>> joints = r.joints;
    if (joints.empty())
      for (int k = a + 1; k < b; ++k) joints.emplace_back(k, cross(p[b] - p[k], r.d));
    std::vector<std::pair<int, double>> row;
    double fixed = 0.0;
    for (const auto& [k, c] : joints) {
      if (column[k] < 0) {
        fixed += c * speed[k];
        continue;
      }
      row.emplace_back(column[k], c);
      row.emplace_back(column[k] + 1, -c);
    }
    dense.add_row(row, 1.0 - fixed, INFINITY);
  }
  const detail::LpSolution oracle = detail::solve(dense);
  ASSERT_EQ(oracle.status, detail::LpSolution::Status::Optimal);

  std::vector<double> found = speed;
  ASSERT_TRUE(detail::window_speeds(p, rows, in, found));
  double objective = 0.0;
  for (int k = 0; k < m; ++k) {
    if (in[k]) {
      objective += std::abs(found[k]);
    } else {
      EXPECT_EQ(found[k], speed[k]) << "joint " << k << " is outside the window";
    }
  }
  EXPECT_NEAR(objective, oracle.objective, 1e-6 * oracle.objective);
  const std::vector<Vec> v = detail::open_chain_velocities(p, found);
  for (const auto& [a, b] : rows) EXPECT_GT(model.weighted_rate(model.row(a, b), v, found), 1.0 - 1e-6) << a << "-" << b;
}

// The two halves cover every a once, half 0 on the calling thread, half 1 on another thread from
// kTwoThreadsFrom vertices on (after half 0 on the calling thread below that).
TEST(CarpenterRepair, TwoHalvesCoverEveryVertexOnceOnTwoThreads) {
  for (const int m : {5, detail::kTwoThreadsFrom - 1, detail::kTwoThreadsFrom, 3000}) {
    std::vector<int> seen(static_cast<std::size_t>(m), 0);
    std::thread::id where[2];
    long pairs[2] = {0, 0};
    detail::for_two_halves(m, [&](int first, int last, int half) {
      where[half] = std::this_thread::get_id();
      for (int a = first; a < last; ++a) {
        ++seen[a];  // each half writes its own a's only
        pairs[half] += m - 1 - a;
      }
    });
    for (int a = 0; a < m; ++a) ASSERT_EQ(seen[a], 1) << a << " of " << m;
    EXPECT_EQ(where[0], std::this_thread::get_id());
    EXPECT_EQ(where[1] != std::this_thread::get_id(), m >= detail::kTwoThreadsFrom) << m;
    if (m >= 100) {
      EXPECT_NEAR(static_cast<double>(pairs[0]) / static_cast<double>(pairs[0] + pairs[1]), 0.5, 0.01) << m;
    }
  }
}

// for_each_low_rate on two threads reports the pairs a plain loop over StrutModel's rows finds,
// in the same order (a, then b), with the same rates.
TEST(CarpenterRepair, LowRatePairsOnTwoThreadsAreThoseOfAPlainLoop) {
  for (const bool closed : {false, true}) {
    const Frame2 p = closed ? foldkit::microbench::random_star(700, 3) : foldkit::microbench::random_lattice_walk(700, 3);
    const int m = static_cast<int>(p.size());
    ASSERT_GE(m, detail::kTwoThreadsFrom);
    std::vector<Vec> v(p.size());
    std::vector<double> speed(p.size(), 0.0);
    for (int i = 0; i < m; ++i) {  // a field with pairs on both sides of the rate cap
      v[i] = Vec(std::sin(0.37 * i), std::cos(0.11 * i)) * 3.0;
      speed[i] = std::sin(0.05 * i);
    }
    const detail::struts::StrutModel model(p, closed);
    std::vector<std::tuple<int, int, double>> threaded, plain;
    detail::struts::for_each_low_rate(model, p, v, speed, [&](int a, int b, double g) { threaded.emplace_back(a, b, g); });
    for (int a = 0; a < m; ++a)
      for (int b = a + 2; b < m; ++b) {
        if (model.is_bar(a, b)) continue;
        const double g = model.weighted_rate(model.row(a, b), v, speed);
        if (g < detail::struts::kRateCap) plain.emplace_back(a, b, g);
      }
    ASSERT_GT(plain.size(), 1000u);
    ASSERT_EQ(threaded.size(), plain.size()) << (closed ? "closed" : "open");
    for (std::size_t i = 0; i < plain.size(); ++i) {
      ASSERT_EQ(std::get<0>(threaded[i]), std::get<0>(plain[i])) << i;
      ASSERT_EQ(std::get<1>(threaded[i]), std::get<1>(plain[i])) << i;
      ASSERT_NEAR(std::get<2>(threaded[i]), std::get<2>(plain[i]), 1e-9 * (1.0 + std::abs(std::get<2>(plain[i])))) << i;
    }
  }
}

// The pairs whose distance the oracle finds shrinking from p to q (no tolerance: the moves here are
// ~1e-3), by their smaller index.
std::vector<int> shrinking(const Frame2& p, const Frame2& q) {
  std::vector<int> first;
  for (int a = 0; a < static_cast<int>(p.size()); ++a)
    for (int b = a + 2; b < static_cast<int>(p.size()); ++b)
      if ((q[b] - q[a]).norm() < (p[b] - p[a]).norm() - 1e-9) first.push_back(a);
  return first;
}

// The step check split over two halves of the pairs finds a shrinking pair in either half: layouts
// grown by 0.1 % about vertex 0 (every pair grows) in which one vertex then moves 0.2 % of its
// distance towards the vertex two further on, chosen so that every pair that shrinks lies in one
// half (checked by the oracle), once in each.
TEST(CarpenterRepair, StepCheckOnTwoThreadsFindsAShrinkingPairInEitherHalf) {
  const Frame2 p = foldkit::microbench::random_lattice_walk(900, 5);
  const planar_detail::MergedChain chain(p, false);
  const int m = chain.vertices();
  ASSERT_GE(m, detail::kTwoThreadsFrom);
  const int split = detail::pair_split(m);
  Frame2 grown = p;
  for (Vec& x : grown) x = p[0] + 1.001 * (x - p[0]);
  EXPECT_TRUE(planar_detail::expansive(chain, p, p));
  EXPECT_TRUE(planar_detail::expansive(chain, p, grown));
  for (const int half : {0, 1}) {
    bool found = false;
    for (int a = half == 0 ? 1 : m - 3; !found && a > 0 && (half == 0 ? a < split - 2 : a > split); a += half == 0 ? 1 : -1) {
      Frame2 moved = grown;
      moved[a] += 0.002 * (grown[a + 2] - grown[a]);
      const std::vector<int> first = shrinking(p, moved);
      found = !first.empty() && std::all_of(first.begin(), first.end(), [&](int k) { return (k >= split) == (half == 1); });
      if (found) {
        EXPECT_FALSE(planar_detail::expansive(chain, p, moved)) << "vertex " << a << ", half " << half;
      }
    }
    EXPECT_TRUE(found) << "no layout that shrinks pairs of half " << half << " only";
  }
}

// record()'s figures of each frame (bar_length_error, min_distance_growth: vectorised, on two
// threads from 400 vertices) are check_motion()'s, bit for bit. Frames: a 700-link walk moved
// along its LP field (bars stretch, pairs shrink); the walk with its first (then last) vertex
// moved towards the vertex two along, so that the most shrinking pair lies in the first (then
// second) half of the pairs; and a row of points scaled by 1.5 with its closest pair at either
// end, where no pair shrinks and the second pass, over every pair, decides.
TEST(CarpenterRepair, RecordedFiguresAreThoseOfCheckMotion) {
  const Frame2 p = foldkit::microbench::random_lattice_walk(700, 2);
  const int n = static_cast<int>(p.size());
  const detail::ExpansiveVelocity lp = detail::expansive_velocity(p, false, {}, 1.0, false);
  ASSERT_TRUE(lp.solved);
  std::vector<std::pair<Frame2, Frame2>> cases;
  for (const double h : {1e-3, 1e-1, 1.0}) {
    Frame2 q = p;
    for (int i = 0; i < n; ++i) q[i] += h * lp.v[i];
    cases.emplace_back(p, q);
  }
  for (const auto& [moved, towards] : {std::pair<int, int>{0, 2}, {n - 1, n - 3}}) {
    Frame2 q = p;
    q[moved] += 0.1 * (p[towards] - p[moved]);
    cases.emplace_back(p, q);
  }
  for (const bool close_at_end : {false, true}) {
    Frame2 row(static_cast<std::size_t>(n)), scaled(static_cast<std::size_t>(n));
    double x = 0.0;
    for (int i = 0; i < n; ++i) {
      const bool close = close_at_end ? i == n - 1 : i == 1;
      x += i == 0 ? 0.0 : (close ? 0.5 : 1.0);
      row[i] = Vec(x, 0.0);
      scaled[i] = 1.5 * row[i];
    }
    cases.emplace_back(row, scaled);
  }
  int shrinking = 0, growing = 0;
  for (std::size_t k = 0; k < cases.size(); ++k)
    for (const bool closed : {false, true}) {
      const auto& [before, after] = cases[k];
      const MotionCheck c = check_motion({before, after}, closed);
      EXPECT_EQ(planar_detail::min_distance_growth(before, after), c.min_distance_growth) << "case " << k;
      EXPECT_EQ(planar_detail::bar_length_error(before, after, closed), c.max_length_error) << "case " << k;
      shrinking += c.min_distance_growth < 0.0;
      growing += c.min_distance_growth > 0.0;
    }
  EXPECT_GE(shrinking, 4);  // at least the moved vertices' frames: the first pass decides
  EXPECT_GE(growing, 4);    // at least the rows: the second pass decides
  EXPECT_TRUE(std::isinf(planar_detail::min_distance_growth(Frame2{Vec(1, 2)}, Frame2{Vec(1, 2)})));
}

}  // namespace
