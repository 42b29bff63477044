#pragma once
// Streinu's pseudo-triangulation mechanism (FOCS 2000, DCG 2005), private to foldkit::folding: the
// merged chain's bars completed to a pointed pseudo-triangulation (PPT), one non-bar convex-hull
// edge removed; the rest is a 1-DOF mechanism whose motion, with the removed edge growing, is
// expansive (no distance shrinks). carpenter_planar.cpp takes its steps (method `pseudo`,
// docs/CARPENTER.md): a predictor along the velocity, a Newton correction back onto every rigid
// edge length, the event where a vertex stops being pointed met by bisection, then a flip (the
// strut removed, the PPT re-completed) or, two bars aligned, the joint merged.
#include <cstddef>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseLU>

#include "carpenter_planar_chain.hpp"
#include "carpenter_pseudo_graph.hpp"

namespace foldkit::folding::pseudo_detail {

using planar_detail::MergedChain;
using Edge = std::pair<int, int>;

// Whether a and b are joined by a bar of the (merged) chain of m vertices.
inline bool is_bar(int a, int b, int m, bool closed) {
  const int d = a > b ? a - b : b - a;
  return d == 1 || (closed && d == m - 1);
}

// The chain's bars completed to a PPT of q (complete_global()).
PptGraph build_ppt(const Points& q, bool closed);

// A convex-hull edge of q in g that is not a bar (the longest; deterministic); (−1, −1) if none.
Edge choose_driver(const Points& q, bool closed, const PptGraph& g);

// The square system of the mechanism at q: a row (qⱼ − qᵢ)·(vⱼ − vᵢ) per edge of g (the driver's
// right-hand side 1, the others 0), then v₀ = 0 and bar 0's direction fixed (3 rows): 2m rows for
// the 2m − 3 edges of a PPT. Unknowns (x₀, y₀, x₁, …).
Eigen::SparseMatrix<double> mechanism_matrix(const Points& q, const PptGraph& g);

// The mechanism's velocity; empty when the system is singular (g not a PPT).
Frame2 mechanism_velocity(const Points& q, const PptGraph& g, Edge driver);

// What PseudoMechanism::step() found.
struct PseudoStep {
  Frame2 next;
  bool accepted = false;
  int event_vertex = -1;  // merged vertex that stops being pointed at `next` (−1: none)
  Edge aligned{-1, -1};   // its two neighbours bounding the angle that reached π
  int attempts = 0;
};

// The run's counters (CarpenterPlanarResult::flips and friends).
struct PseudoCounts {
  std::size_t flips = 0;           // strut removed and the PPT re-completed
  std::size_t straightenings = 0;  // two bars aligned: the joint merged
  std::size_t hull_changes = 0;    // a vertex crossed the driver's line: the driver replaced
  std::size_t unflips = 0;         // a flip's new edge found crossing one step later, replaced
  std::size_t rebuilds = 0;        // local re-completion fell short: completed over the whole chain
  double certificate_seconds = 0;  // in the all-pairs expansive() check
};

// The mechanism between steps: the PPT, kept by input vertex so that it survives merges.
class PseudoMechanism {
 public:
  // Brings the PPT up to date with `chain` (vertices merged since are dropped with their edges
  // and the gaps re-completed locally), or builds it. False when no PPT could be completed.
  bool sync(const MergedChain& chain);
  // The velocity at the chain's positions (factorises the system kept for the correction);
  // false when singular.
  bool velocity(const MergedChain& chain, Frame2& v);
  // A step of length at most h along v: predictor, correction, the first vertex that stops being
  // pointed met by bisection, and the all-pairs expansive() check; halved up to 60 times.
  PseudoStep step(const MergedChain& chain, const Frame2& v, double h);
  // At the accepted event step's positions: removes the strut of `aligned` (not a bar; the
  // driver last) and re-completes the PPT around it.
  void flip(const MergedChain& chain, int vertex, Edge aligned);
  // After every accepted step, at its positions: the driver put back into the PPT if it still
  // crosses nothing and keeps its ends pointed, else replaced by the edge that completes the
  // PPT again (a hull change).
  void settle(const MergedChain& chain);

  // Forgets the PPT: the next sync() builds it again from the bars.
  void reset() {
    keys_.clear();
    g_ = PptGraph();
    flipped_ = pending_ = {-1, -1};
  }
  const PptGraph& graph() const { return g_; }
  PseudoCounts counts;

 private:
  // Positions after a predictor step of length h, corrected onto the rigid edge lengths by
  // Newton steps with the velocity's factorisation; empty when that does not converge.
  Frame2 advance(const MergedChain& chain, const Frame2& v, double h) const;
  // Where the first vertex that stops being pointed within (0, h] (a at p, the step of length h)
  // meets its event: the positions at the longest length found with every vertex pointed, the
  // vertex and its excess over π there (≤ the event angle when it was reached).
  struct Event {
    Frame2 at;
    double length;
    int vertex;
    double excess;
  };
  Event to_event(const MergedChain& chain, const Frame2& v, double h, const Frame2& p, int a) const;
  // The first vertex (in index order) whose recorded reflex angle is no longer beyond π at p.
  int unpointed(const Frame2& p) const;
  // Replaces edge e when at the chain's positions it meets another edge or leaves an end
  // unpointed (re-completing around it); true if it did.
  bool mend(const MergedChain& chain, Edge e);
  void rebuild_from(const MergedChain& chain, const Points& q);

  std::vector<int> keys_;  // input vertex of each graph vertex
  PptGraph g_;
  Edge driver_{-1, -1};
  Edge flipped_{-1, -1};  // the edge this step's flip added
  Edge pending_{-1, -1};  // the edge the last step's flip added, checked after this step
  bool closed_ = false;
  std::vector<Edge> rigid_;           // edges held at their length, with their squared lengths
  std::vector<double> length2_;
  std::vector<Edge> gaps_;            // reflex angle of each vertex at the step's start
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu_;
};

}  // namespace foldkit::folding::pseudo_detail
