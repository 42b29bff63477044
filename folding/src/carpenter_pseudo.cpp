// Streinu's pseudo-triangulation mechanism for method `pseudo` (carpenter_pseudo.hpp).
#include "carpenter_pseudo.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace foldkit::folding::pseudo_detail {
namespace {

using planar_detail::cross;

std::size_t target(int m) { return m < 2 ? 0 : 2 * static_cast<std::size_t>(m) - 3; }

// A vertex counts as no longer pointed once its reflex angle is within this (radians) of π: the
// event search then stops before it, so a step never leaves a vertex unpointed.
constexpr double kEventMargin = 1e-13;
// Where bisection stops: the aligned edges within this angle (radians) of straight. Two bars are then
// merged, snapping the joint by no more than rounding; a strut is flipped to the edge across the
// vertex, which is valid only at or just past the event (flip()).
constexpr double kEventAngle = 4e-13;

// The excess over π of a's reflex angle from e.first counter-clockwise to e.second, radians in
// (−π, π]: > 0 while a is pointed by it. (Its sine alone also vanishes where the two edges
// nearly overlap, a joint folded almost flat, which it once took for an event.)
double excess(const Frame2& p, int a, Edge e) {
  const Vec u = p[e.first] - p[a], w = p[e.second] - p[a];
  return std::atan2(-cross(u, w), -u.dot(w));
}

}  // namespace

PptGraph build_ppt(const Points& q, bool closed) {
  const int m = static_cast<int>(q.size());
  PptGraph g(m);
  for (int a = 0; a + 1 < m; ++a) g.add(a, a + 1);
  if (closed && m > 2) g.add(m - 1, 0);
  complete_global(q, g);
  return g;
}

Edge choose_driver(const Points& q, bool closed, const PptGraph& g) {
  const int m = g.vertices();
  Edge best{-1, -1};
  double longest = -1.0;
  for (const auto& [a, b] : hull_edges(q)) {
    if (is_bar(a, b, m, closed) || !g.has(a, b)) continue;
    const double l = (q[b] - q[a]).squaredNorm();
    if (l > longest) longest = l, best = {std::min(a, b), std::max(a, b)};
  }
  return best;
}

Eigen::SparseMatrix<double> mechanism_matrix(const Points& q, const PptGraph& g) {
  const int m = g.vertices();
  const auto edges = g.edge_list();
  const int rows = static_cast<int>(edges.size()) + 3;
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(4 * edges.size() + 6);
  int r = 0;
  for (const auto& [i, j] : edges) {
    const Vec d = q[j] - q[i];
    t.emplace_back(r, 2 * i, -d.x());
    t.emplace_back(r, 2 * i + 1, -d.y());
    t.emplace_back(r, 2 * j, d.x());
    t.emplace_back(r, 2 * j + 1, d.y());
    ++r;
  }
  // Pins: v₀ = 0 and cross(q₁ − q₀, v₁ − v₀) = 0 kill the rigid motions, as bar 0 is pinned in
  // the other methods (so the closed-form end and the frames look alike).
  const Vec d0 = q[1] - q[0];
  t.emplace_back(r, 0, 1.0);
  t.emplace_back(r + 1, 1, 1.0);
  t.emplace_back(r + 2, 0, d0.y());
  t.emplace_back(r + 2, 1, -d0.x());
  t.emplace_back(r + 2, 2, -d0.y());
  t.emplace_back(r + 2, 3, d0.x());
  Eigen::SparseMatrix<double> a(rows, 2 * m);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

Frame2 mechanism_velocity(const Points& q, const PptGraph& g, Edge driver) {
  const int m = g.vertices();
  if (g.edges() != target(m)) return {};
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
  const Eigen::SparseMatrix<double> a = mechanism_matrix(q, g);
  lu.analyzePattern(a);
  lu.factorize(a);
  if (lu.info() != Eigen::Success) return {};
  const auto edges = g.edge_list();
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * m);
  rhs[std::lower_bound(edges.begin(), edges.end(), driver) - edges.begin()] = 1.0;
  const Eigen::VectorXd x = lu.solve(rhs);
  if (!x.allFinite()) return {};
  Frame2 v(static_cast<std::size_t>(m));
  for (int i = 0; i < m; ++i) v[i] = Vec(x[2 * i], x[2 * i + 1]);
  return v;
}

void PseudoMechanism::rebuild_from(const MergedChain& chain, const Points& q) {
  g_ = build_ppt(q, chain.closed());
  keys_.clear();
  for (int a = 0; a < chain.vertices(); ++a) keys_.push_back(chain.key(a));
}

bool PseudoMechanism::sync(const MergedChain& chain) {
  const int m = chain.vertices();
  closed_ = chain.closed();
  std::vector<int> keys(static_cast<std::size_t>(m));
  for (int a = 0; a < m; ++a) keys[a] = chain.key(a);
  if (keys_.empty()) {
    rebuild_from(chain, chain.q());
    return g_.edges() == target(m);
  }
  if (keys != keys_) {
    // Vertices merged since the last step: their edges go, the merged bar joins their
    // neighbours, and the missing edges are sought among the vertices of their faces (taken
    // where the old vertices lie now: on the merged bars).
    const Frame2 p = chain.expand(chain.q());
    Points old(keys_.size());
    for (std::size_t i = 0; i < keys_.size(); ++i) old[i] = p[keys_[i]];
    std::vector<int> index(p.size(), -1);
    for (int a = 0; a < m; ++a) index[keys[a]] = a;
    std::vector<int> region;
    for (std::size_t i = 0; i < keys_.size(); ++i)
      if (index[keys_[i]] < 0)
        for (int r : faces_around(old, g_, static_cast<int>(i)))
          if (index[keys_[r]] >= 0) region.push_back(index[keys_[r]]);
    PptGraph g(m);
    for (const auto& [a, b] : g_.edge_list())
      if (index[keys_[a]] >= 0 && index[keys_[b]] >= 0) g.add(index[keys_[a]], index[keys_[b]]);
    for (int a = 0; a < chain.bars(); ++a) g.add(a, chain.next(a));
    g_ = std::move(g);
    keys_ = keys;
    if (g_.edges() > target(m)) {
      rebuild_from(chain, chain.q());
      ++counts.rebuilds;
    } else {
      complete_local(chain.q(), g_, region);
    }
  }
  if (g_.edges() < target(m)) {
    complete_global(chain.q(), g_);
    ++counts.rebuilds;
  }
  return g_.edges() == target(m);
}

bool PseudoMechanism::velocity(const MergedChain& chain, Frame2& v) {
  const Points& q = chain.q();
  const int m = chain.vertices();
  driver_ = choose_driver(q, closed_, g_);
  if (driver_.first < 0 || g_.edges() != target(m)) return false;
  // Events are those of the mechanism, the PPT less the driver: the driver is not held, and a
  // vertex may cross its line (the hull then changes; settle() replaces it).
  PptGraph mechanism = g_;
  mechanism.remove(driver_.first, driver_.second);
  gaps_.assign(static_cast<std::size_t>(m), {-1, -1});
  for (int a = 0; a < m; ++a) {
    gaps_[a] = reflex_gap(q, mechanism, a);
    if (gaps_[a].first < 0) return false;  // not pointed: no PPT
  }
  const Eigen::SparseMatrix<double> a = mechanism_matrix(q, g_);
  lu_.analyzePattern(a);
  lu_.factorize(a);
  if (lu_.info() != Eigen::Success) return false;
  rigid_ = g_.edge_list();
  length2_.clear();
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * m);
  for (std::size_t r = 0; r < rigid_.size(); ++r) {
    const auto [i, j] = rigid_[r];
    // Every edge, bars included, is held at its length now: pulling a bar to its arc length (which
    // differs by the rounding of the arc sums, 1e-14 relative) strains a nearly flexible rigid
    // part, and the pairs inside it moved by 1e-11 (a 100-link walk). Drift stays at rounding.
    length2_.push_back((q[j] - q[i]).squaredNorm());
    if (rigid_[r] == driver_) rhs[static_cast<Eigen::Index>(r)] = 1.0;
  }
  const Eigen::VectorXd x = lu_.solve(rhs);
  if (!x.allFinite()) return false;
  v.assign(static_cast<std::size_t>(m), Vec::Zero());
  for (int i = 0; i < m; ++i) v[i] = Vec(x[2 * i], x[2 * i + 1]);
  return true;
}

Frame2 PseudoMechanism::advance(const MergedChain& chain, const Frame2& v, double h) const {
  const Points& q = chain.q();
  const int m = chain.vertices();
  Frame2 p(static_cast<std::size_t>(m));
  for (int i = 0; i < m; ++i) p[i] = q[i] + h * v[i];
  const Vec d0 = q[1] - q[0];
  Eigen::VectorXd f(2 * m);
  double last = std::numeric_limits<double>::infinity();
  // Chord Newton: the factorisation at the step's start serves every iteration (it converges
  // linearly at a rate of order h, ample for the step lengths the events allow).
  for (int iteration = 0; iteration < 40; ++iteration) {
    double worst = 0.0;
    for (std::size_t r = 0; r < rigid_.size(); ++r) {
      const auto [i, j] = rigid_[r];
      const double now = (p[j] - p[i]).squaredNorm();
      // The driver is free: its row only keeps the correction from moving along the mechanism.
      const double want = rigid_[r] == driver_ ? (q[j] + h * v[j] - q[i] - h * v[i]).squaredNorm() : length2_[r];
      f[static_cast<Eigen::Index>(r)] = 0.5 * (now - want);
      worst = std::max(worst, std::abs(now - want) / want);
    }
    const Eigen::Index r = static_cast<Eigen::Index>(rigid_.size());
    f[r] = p[0].x() - q[0].x();
    f[r + 1] = p[0].y() - q[0].y();
    f[r + 2] = cross(d0, p[1] - p[0]);
    if (worst <= 1e-15) return p;
    if (iteration >= 3 && worst > 0.5 * last) return worst <= 1e-12 ? p : Frame2{};
    last = worst;
    const Eigen::VectorXd dx = lu_.solve(f);
    if (!dx.allFinite()) return {};
    for (int i = 0; i < m; ++i) p[i] -= Vec(dx[2 * i], dx[2 * i + 1]);
  }
  return last <= 1e-12 ? p : Frame2{};
}

int PseudoMechanism::unpointed(const Frame2& p) const {
  for (int a = 0; a < static_cast<int>(gaps_.size()); ++a)
    if (excess(p, a, gaps_[a]) <= kEventMargin) return a;
  return -1;
}

PseudoMechanism::Event PseudoMechanism::to_event(const MergedChain& chain, const Frame2& v, double h, const Frame2& p,
                                                 int a) const {
  // Regula falsi (Illinois) on the excess at a; another vertex found unpointed at a trial point
  // earlier takes over the bracket's upper end. The Illinois halving scales the ends' values,
  // so the true excess at the lower end is kept apart: it alone decides the stop.
  Event e{chain.q(), 0.0, a, excess(chain.q(), a, gaps_[a])};
  double hi = h, flo = e.excess, fhi = excess(p, a, gaps_[a]);
  int side = 0;
  for (int it = 0; it < 200 && hi - e.length > 1e-16 * hi && e.excess > kEventAngle; ++it) {
    double t = (e.length * fhi - hi * flo) / (fhi - flo);
    if (!(t > e.length && t < hi)) t = 0.5 * (e.length + hi);
    Frame2 trial = advance(chain, v, t);
    const int b = trial.empty() ? e.vertex : unpointed(trial);
    if (trial.empty() || b >= 0) {
      if (b != e.vertex) e.vertex = b, e.excess = flo = excess(e.at, b, gaps_[b]), side = 0;
      hi = t, fhi = trial.empty() ? -1.0 : excess(trial, e.vertex, gaps_[e.vertex]);
      if (side == -1) flo *= 0.5;
      side = -1;
    } else {
      e.excess = flo = excess(trial, e.vertex, gaps_[e.vertex]);
      e.length = t, e.at = std::move(trial);
      if (side == 1) fhi *= 0.5;
      side = 1;
    }
  }
  return e;
}

PseudoStep PseudoMechanism::step(const MergedChain& chain, const Frame2& v, double h) {
  PseudoStep s;
  for (int attempt = 0; attempt < 60 && !s.accepted; ++attempt, h *= 0.5) {
    ++s.attempts;
    Frame2 p = advance(chain, v, h);
    if (p.empty()) continue;
    const int a = unpointed(p);
    s.event_vertex = -1;
    if (a >= 0) {
      Event e = to_event(chain, v, h, p, a);
      // Only a vertex brought to its event counts (the bracket can also close where the
      // correction failed): the step then just ends short of it, and nothing is merged or flipped.
      if (e.excess <= kEventAngle) {
        s.event_vertex = e.vertex;
        s.aligned = gaps_[e.vertex];
      } else if (!(e.length > 0.0)) {
        continue;  // no progress at this length: halve
      }
      p = std::move(e.at);
    }
    const auto start = std::chrono::steady_clock::now();
    const bool ok = planar_detail::expansive(chain, chain.q(), p);
    counts.certificate_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (ok) {
      s.next = std::move(p);
      s.accepted = true;
    }
  }
  return s;
}

bool PseudoMechanism::mend(const MergedChain& chain, Edge e) {
  const Points& q = chain.q();
  const auto [a, b] = e;
  if (a < 0 || !g_.has(a, b)) return false;
  bool valid = pointed(q, g_, a) && pointed(q, g_, b);
  for (const auto& [u, w] : g_.edge_list())
    if (valid && Edge{u, w} != e && segments_meet(q[a], q[b], q[u], q[w])) valid = false;
  if (valid) return false;
  g_.remove(a, b);
  std::vector<int> region = faces_around(q, g_, a);
  for (int r : faces_around(q, g_, b)) region.push_back(r);
  complete_local(q, g_, region, e);
  if (g_.edges() < target(chain.vertices())) {
    complete_global(q, g_, e);
    ++counts.rebuilds;
  }
  return true;
}

void PseudoMechanism::settle(const MergedChain& chain) {
  // The edge of the last flip joined x and y across v, valid only if v went on to the side of
  // its other edges; where the new mechanism took v back, it crosses them, and is replaced.
  if (pending_.first >= 0 && pending_ != driver_ && pending_.second < chain.vertices() && mend(chain, pending_)) ++counts.unflips;
  pending_ = flipped_;
  flipped_ = {-1, -1};
  // A vertex that crossed the driver's line changed the hull: the edge that completes the PPT
  // again is a new hull edge among the faces at the driver's ends.
  if (driver_.second < chain.vertices() && mend(chain, driver_)) ++counts.hull_changes;
}

void PseudoMechanism::flip(const MergedChain& chain, int vertex, Edge aligned) {
  const Points& q = chain.q();
  const int m = chain.vertices();
  // Streinu's flip: v's edges to x and y have aligned (v on the segment xy, to the event's
  // precision); the strut vx goes and xy comes. Just past the event v leaves the line on the side
  // of its other edges, and xy, on the side that v's reflex angle left empty, crosses nothing. The
  // strut removed is not a bar, and not the driver unless both are struts and one is the driver.
  int x = -1;
  for (const int other : {aligned.first, aligned.second}) {
    if (is_bar(vertex, other, m, closed_)) continue;
    const Edge e{std::min(vertex, other), std::max(vertex, other)};
    if (x < 0 || Edge{std::min(vertex, x), std::max(vertex, x)} == driver_) x = other;
  }
  if (x < 0) return;  // two bars: the joint is merged instead
  const int y = x == aligned.first ? aligned.second : aligned.first;
  ++counts.flips;
  const Edge strut{std::min(vertex, x), std::max(vertex, x)};
  if (!g_.has(x, y)) {
    g_.remove(vertex, x);
    g_.add(x, y);
    flipped_ = {std::min(x, y), std::max(x, y)};
    return;
  }
  // xy was there already (the driver, grown until its triangle with v went flat): the missing
  // edge is sought among the faces of the strut removed.
  const std::vector<int> region = faces_around(q, g_, strut.first, strut.second);
  g_.remove(strut.first, strut.second);
  complete_local(q, g_, region, strut);
  if (g_.edges() < target(m)) {
    complete_global(q, g_, strut);
    ++counts.rebuilds;
  }
}

}  // namespace foldkit::folding::pseudo_detail
