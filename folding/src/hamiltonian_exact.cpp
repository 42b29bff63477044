// Exact Hamiltonian path/cycle search by backtracking. Hand-written: Boost.Graph has no
// Hamiltonian search, and the pruning needs the grid's bipartite colouring.
#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <utility>

#include "hamiltonian_graph.hpp"

namespace foldkit::folding::detail {

using geometry::StatusCode;
namespace {

int colour(const Cell& c) {
  return (c.x + c.y + c.z) & 1;
}

std::string where(const Cell& c, bool three_d) {
  return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + (three_d ? ", " + std::to_string(c.z) : "") + ")";
}

class Search {
 public:
  Search(const CellGraph& g, const ExactOptions& o)
      : g_(g), o_(o), n_(g.vertex_count()), visited_(n_, 0), free_deg_(n_), mark_(n_, 0), reach_(n_, 0) {
    for (std::size_t v = 0; v < n_; ++v) {
      free_deg_[v] = g.degree(static_cast<std::int32_t>(v));
      ++unvisited_colour_[colour(g.cells[v])];
    }
  }

  // Runs the search from `start`; true when a path (or cycle) was found, stops early on budget.
  bool run(std::int32_t start) {
    start_ = start;
    visit(start);
    if (path_.size() == n_ && !o_.cycle) return true;
    frames_.clear();
    frames_.push_back(expand());
    while (!frames_.empty()) {
      Frame& f = frames_.back();
      if (f.next == f.count) {
        frames_.pop_back();
        unvisit();
        continue;
      }
      const std::int32_t v = f.candidates[static_cast<std::size_t>(f.next++)];
      if (++nodes_ > o_.node_budget) {
        out_of_budget_ = true;
        return false;
      }
      visit(v);
      if (path_.size() == n_) {
        if (!o_.cycle || adjacent(v, start_)) return true;
        unvisit();
        continue;
      }
      frames_.push_back(expand());
    }
    return false;
  }

  const std::vector<std::int32_t>& path() const { return path_; }
  std::uint64_t nodes() const { return nodes_; }
  bool out_of_budget() const { return out_of_budget_; }

 private:
  struct Frame {
    std::array<std::int32_t, 6> candidates{};
    int count = 0, next = 0;
  };

  bool adjacent(std::int32_t a, std::int32_t b) const {
    for (std::uint32_t k = g_.first[static_cast<std::size_t>(a)]; k < g_.first[static_cast<std::size_t>(a) + 1]; ++k)
      if (g_.adj[k] == b) return true;
    return false;
  }

  void visit(std::int32_t v) {
    const auto vi = static_cast<std::size_t>(v);
    visited_[vi] = 1;
    path_.push_back(v);
    --unvisited_colour_[colour(g_.cells[vi])];
    for (std::uint32_t k = g_.first[vi]; k < g_.first[vi + 1]; ++k) --free_deg_[static_cast<std::size_t>(g_.adj[k])];
  }

  void unvisit() {
    const auto vi = static_cast<std::size_t>(path_.back());
    path_.pop_back();
    visited_[vi] = 0;
    ++unvisited_colour_[colour(g_.cells[vi])];
    for (std::uint32_t k = g_.first[vi]; k < g_.first[vi + 1]; ++k) ++free_deg_[static_cast<std::size_t>(g_.adj[k])];
  }

  // The moves from the current end, fewest onward moves first (Warnsdorff), or none when the
  // unvisited cells can no longer be covered.
  Frame expand() {
    Frame f;
    if (!viable()) return f;
    const auto head = static_cast<std::size_t>(path_.back());
    for (std::uint32_t k = g_.first[head]; k < g_.first[head + 1]; ++k)
      if (!visited_[static_cast<std::size_t>(g_.adj[k])]) f.candidates[static_cast<std::size_t>(f.count++)] = g_.adj[k];
    // Insertion sort of at most six moves (std::sort here trips GCC 12's -Warray-bounds).
    for (int i = 1; i < f.count; ++i)
      for (int j = i; j > 0; --j) {
        auto& a = f.candidates[static_cast<std::size_t>(j - 1)];
        auto& b = f.candidates[static_cast<std::size_t>(j)];
        if (free_deg_[static_cast<std::size_t>(b)] >= free_deg_[static_cast<std::size_t>(a)]) break;
        std::swap(a, b);
      }
    return f;
  }

  // Necessary conditions for the rest of the path: it starts next to the head, alternates
  // colours, every cell but its far end has two usable neighbours, and it is connected.
  bool viable() {
    const std::size_t k = n_ - path_.size();
    const std::int32_t head = path_.back();
    const int a = 1 - colour(g_.cells[static_cast<std::size_t>(head)]);
    if (unvisited_colour_[a] - unvisited_colour_[1 - a] != static_cast<int>(k % 2)) return false;
    if (o_.cycle && (k % 2 == 1 ? a : 1 - a) == colour(g_.cells[static_cast<std::size_t>(start_)])) return false;
    ++stamp_;
    auto mark_neighbours = [&](std::int32_t v) {
      for (std::uint32_t j = g_.first[static_cast<std::size_t>(v)]; j < g_.first[static_cast<std::size_t>(v) + 1]; ++j)
        ++mark_[static_cast<std::size_t>(g_.adj[j])];
    };
    // mark_ counts adjacency to the head (and to the start, which closes a cycle).
    std::fill(mark_.begin(), mark_.end(), 0);
    mark_neighbours(head);
    if (o_.cycle && head != start_) mark_neighbours(start_);
    int ends = 0;
    for (std::size_t v = 0; v < n_; ++v) {
      if (visited_[v]) continue;
      const int d = free_deg_[v] + mark_[v];
      if (d == 0 && k > 1) return false;
      if (d < 2 && k > 1 && (o_.cycle || ++ends > 1)) return false;
    }
    // Breadth-first over the unvisited cells from the head's neighbours, by hand: it runs at every
    // node on a shrinking subset, where Boost's BFS would need a filtered graph and a fresh colour map.
    queue_.clear();
    for (std::uint32_t j = g_.first[static_cast<std::size_t>(head)]; j < g_.first[static_cast<std::size_t>(head) + 1]; ++j) {
      const auto w = static_cast<std::size_t>(g_.adj[j]);
      if (!visited_[w] && reach_[w] != stamp_) {
        reach_[w] = stamp_;
        queue_.push_back(static_cast<std::int32_t>(w));
      }
    }
    for (std::size_t q = 0; q < queue_.size(); ++q) {
      const auto u = static_cast<std::size_t>(queue_[q]);
      for (std::uint32_t j = g_.first[u]; j < g_.first[u + 1]; ++j) {
        const auto w = static_cast<std::size_t>(g_.adj[j]);
        if (!visited_[w] && reach_[w] != stamp_) {
          reach_[w] = stamp_;
          queue_.push_back(static_cast<std::int32_t>(w));
        }
      }
    }
    return queue_.size() == k;
  }

  const CellGraph& g_;
  const ExactOptions& o_;
  std::size_t n_;
  std::vector<std::uint8_t> visited_;
  std::vector<int> free_deg_;  // unvisited neighbours
  std::vector<int> mark_;
  std::vector<std::uint64_t> reach_;
  std::uint64_t stamp_ = 0;
  std::vector<std::int32_t> queue_;
  int unvisited_colour_[2] = {0, 0};
  std::vector<std::int32_t> path_;
  std::vector<Frame> frames_;
  std::int32_t start_ = 0;
  std::uint64_t nodes_ = 0;
  bool out_of_budget_ = false;
};

HamiltonianResult none(std::string reason) {
  HamiltonianResult r;
  r.status = {StatusCode::NoSolution, std::move(reason)};
  return r;
}

// Cells of each colour, and the cells of degree 1.
struct Census {
  int count[2] = {0, 0};
  std::vector<std::int32_t> leaves;

  std::string counts() const {
    return std::to_string(count[0]) + " even and " + std::to_string(count[1]) + " odd cells";
  }
};

Census take_census(const CellGraph& g) {
  Census c;
  for (std::size_t v = 0; v < g.vertex_count(); ++v) {
    ++c.count[colour(g.cells[v])];
    if (g.degree(static_cast<std::int32_t>(v)) == 1) c.leaves.push_back(static_cast<std::int32_t>(v));
  }
  return c;
}

// Why the shape cannot be searched at all (empty, too large, not connected, or a start that is
// not a cell), or nothing. `start` is the start cell's vertex (-1: none given).
std::optional<HamiltonianResult> unsearchable(const CellGraph& g, const ExactOptions& o, bool three_d, std::int32_t& start) {
  const std::size_t n = g.vertex_count();
  if (n == 0) return none("the shape is empty");
  if (n > kMaxExactCells) {
    HamiltonianResult r;
    r.status = {StatusCode::LimitReached, "too large for the exact search (" + std::to_string(n) + " cells > " +
                                              std::to_string(kMaxExactCells) + "); use the refinement"};
    return r;
  }
  if (const std::size_t k = component_count(g); k > 1)
    return none("the shape is not connected (" + std::to_string(k) + " components)");
  start = -1;
  if (o.start && !o.cycle) {
    start = g.vertex_at(o.start->x, o.start->y, o.start->z);
    if (start < 0) return none("the start " + where(*o.start, three_d) + " is not a filled cell");
  }
  return std::nullopt;
}

void cycle_failures(const Census& c, std::size_t n, std::vector<std::string>& failed) {
  if (c.count[0] != c.count[1]) failed.push_back("colour parity: " + c.counts() + " (a cycle needs equal counts)");
  if (!c.leaves.empty())
    failed.push_back(std::to_string(c.leaves.size()) + (c.leaves.size() == 1 ? " cell" : " cells") +
                     " of degree 1 (a cycle has none)");
  if (n < 4) failed.push_back("fewer than 4 cells");
}

void path_failures(const CellGraph& g, const ExactOptions& o, const Census& c, std::int32_t start, bool three_d,
                   std::vector<std::string>& failed) {
  const bool balanced = c.count[0] - c.count[1] <= 1 && c.count[1] - c.count[0] <= 1;
  if (!balanced) failed.push_back("colour parity: " + c.counts() + " differ by more than 1");
  if (c.leaves.size() > 2) failed.push_back(std::to_string(c.leaves.size()) + " cells of degree 1 (a path has only two ends)");
  if (balanced && start >= 0 && c.count[0] != c.count[1]) {
    const int s = colour(g.cells[static_cast<std::size_t>(start)]);
    if (c.count[s] < c.count[1 - s])
      failed.push_back("colour parity: " + c.counts() + ", so the path must start on the majority colour, and the start " +
                       where(*o.start, three_d) + " is not");
  }
  if (start >= 0 && c.leaves.size() == 2 && start != c.leaves[0] && start != c.leaves[1])
    failed.push_back("the two cells of degree 1 must be the ends, and the start " + where(*o.start, three_d) + " is neither");
}

// Every necessary condition that fails, joined by "; " (not just the first); empty when none.
std::string failed_conditions(const CellGraph& g, const ExactOptions& o, const Census& c, std::int32_t start, bool three_d) {
  std::vector<std::string> failed;
  if (o.cycle) cycle_failures(c, g.vertex_count(), failed);
  else path_failures(g, o, c, start, three_d, failed);
  if (failed.empty()) return {};
  std::string reason = failed[0];
  for (std::size_t i = 1; i < failed.size(); ++i) reason += "; " + failed[i];
  return reason;
}

// Where the path may start: one end of a degree-1 cell (reversal covers the other), the
// majority colour, or for a cycle any one cell.
std::vector<std::int32_t> start_cells(const CellGraph& g, const ExactOptions& o, const Census& c, std::int32_t start) {
  std::vector<std::int32_t> starts;
  if (start >= 0) {
    starts.push_back(start);
  } else if (o.cycle) {
    starts.push_back(0);
  } else if (!c.leaves.empty()) {
    starts.push_back(c.leaves[0]);
  } else {
    for (std::size_t v = 0; v < g.vertex_count(); ++v)
      if (c.count[0] == c.count[1] || c.count[colour(g.cells[v])] > c.count[1 - colour(g.cells[v])])
        starts.push_back(static_cast<std::int32_t>(v));
  }
  return starts;
}

HamiltonianResult search_from(const CellGraph& g, const ExactOptions& o, const std::vector<std::int32_t>& starts) {
  Search search(g, o);
  HamiltonianResult r;
  for (const std::int32_t s : starts) {
    const bool found = search.run(s);
    r.nodes = search.nodes();
    if (found) {
      r.status = {StatusCode::Success, std::string("Hamiltonian ") + (o.cycle ? "cycle" : "path") + " found"};
      r.cycle = o.cycle;
      for (const std::int32_t v : search.path()) r.path.push_back(g.cells[static_cast<std::size_t>(v)]);
      return r;
    }
    if (search.out_of_budget()) {
      r.status = {StatusCode::LimitReached, "node budget of " + std::to_string(o.node_budget) + " exhausted"};
      return r;
    }
  }
  r.status = {StatusCode::NoSolution,
              "exhausted search (" + std::to_string(r.nodes) + " nodes): no Hamiltonian " + (o.cycle ? "cycle" : "path")};
  return r;
}

}  // namespace

HamiltonianResult exact_search(const CellGraph& g, const ExactOptions& o) {
  const bool three_d = g.size[2] > 1;
  std::int32_t start = -1;
  if (auto r = unsearchable(g, o, three_d, start)) return std::move(*r);
  const Census census = take_census(g);
  if (std::string reason = failed_conditions(g, o, census, start, three_d); !reason.empty()) return none(std::move(reason));
  return search_from(g, o, start_cells(g, o, census, start));
}

}  // namespace foldkit::folding::detail

namespace foldkit::folding {

HamiltonianResult exact_hamiltonian(const PixelShape& shape, const ExactOptions& options) {
  return detail::exact_search(detail::make_graph(shape.cells, shape.width, shape.height, 1), options);
}

HamiltonianResult exact_hamiltonian(const VoxelShape& shape, const ExactOptions& options) {
  return detail::exact_search(detail::make_graph(shape.cells, shape.nx, shape.ny, shape.nz), options);
}

}  // namespace foldkit::folding
