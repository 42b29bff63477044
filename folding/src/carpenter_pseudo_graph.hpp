#pragma once
// Pointed pseudo-triangulations (PPTs) of the merged chain's vertices, private to
// foldkit::folding: the graph, the pointedness and crossing tests, completion of a pointed
// non-crossing graph to a maximal one (greedy, shortest candidates first), and the faces around
// an edge or a vertex, where a flip's or a merge's new edges must lie. carpenter_pseudo.cpp moves
// the chain with them (Streinu's mechanism; docs/CARPENTER.md, "Method `pseudo`").
#include <cstddef>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace foldkit::folding::pseudo_detail {

using Vec = Eigen::Vector2d;
using Points = std::vector<Vec>;

// An undirected simple graph on vertices 0 … m−1 (adjacency lists; degrees in a PPT average < 4,
// so linear scans beat a hash set).
class PptGraph {
 public:
  explicit PptGraph(int m = 0) : adj_(static_cast<std::size_t>(m)) {}
  int vertices() const { return static_cast<int>(adj_.size()); }
  std::size_t edges() const { return count_; }
  bool has(int a, int b) const;
  void add(int a, int b);
  void remove(int a, int b);
  const std::vector<int>& neighbours(int a) const { return adj_[a]; }
  // Every edge once, as (a, b) with a < b, in increasing order (deterministic).
  std::vector<std::pair<int, int>> edge_list() const;

 private:
  std::vector<std::vector<int>> adj_;
  std::size_t count_ = 0;
};

// Whether vertex a is pointed (some angle between consecutive incident edges exceeds π), with the
// edge to `extra` added when extra ≥ 0. A vertex of degree < 2 is pointed.
bool pointed(const Points& q, const PptGraph& g, int a, int extra = -1);

// The two neighbours bounding a's reflex angle, in counter-clockwise order (turning from the
// first to the second counter-clockwise sweeps more than π); (−1, −1) when a is not pointed or
// has degree < 2.
std::pair<int, int> reflex_gap(const Points& q, const PptGraph& g, int a);

// Whether segments ab and cd share a point other than a common endpoint (touching counts).
bool segments_meet(const Vec& a, const Vec& b, const Vec& c, const Vec& d);

// An edge that completion must not add (the strut a flip just removed); (−1, −1) for none.
using Excluded = std::pair<int, int>;

// Adds edges to the pointed non-crossing graph g until it has 2m − 3 edges or no edge can be added
// that keeps every vertex pointed and crosses nothing: first the convex hull's edges, then pairs
// by distance bands of 2, 4, 8, … mean edge lengths (shortest first within a band), a uniform
// grid finding near pairs and the edges a candidate could cross. Returns the edges added.
int complete_global(const Points& q, PptGraph& g, Excluded excluded = {-1, -1});

// The same, trying only pairs of `region` vertices (a flip's or a merge's faces), shortest first.
int complete_local(const Points& q, PptGraph& g, const std::vector<int>& region, Excluded excluded = {-1, -1});

// The vertices of the faces on both sides of edge ab (b ≥ 0), or of every face at vertex a
// (b < 0): where a maximal graph, after losing those edges, regains its missing edges.
std::vector<int> faces_around(const Points& q, const PptGraph& g, int a, int b = -1);

// Checks of a PPT for tests: 2m − 3 edges, every vertex pointed, no two edges meeting.
struct PptCheck {
  bool edge_count = false;
  bool pointed = false;
  bool non_crossing = false;
};
PptCheck check_ppt(const Points& q, const PptGraph& g);

// The edges of the convex hull of q (counter-clockwise, collinear points left out).
std::vector<std::pair<int, int>> hull_edges(const Points& q);

}  // namespace foldkit::folding::pseudo_detail
