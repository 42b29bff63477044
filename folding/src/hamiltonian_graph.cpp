#include "hamiltonian_graph.hpp"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/breadth_first_search.hpp>
#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/graph/connected_components.hpp>
#include <boost/graph/visitors.hpp>
#include <stdexcept>
#include <utility>

namespace foldkit::folding::detail {
namespace {

using BoostGraph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;

BoostGraph to_boost(const CellGraph& g) {
  BoostGraph b(g.vertex_count());
  for (std::size_t v = 0; v < g.vertex_count(); ++v)
    for (std::uint32_t k = g.first[v]; k < g.first[v + 1]; ++k)
      if (static_cast<std::size_t>(g.adj[k]) > v) boost::add_edge(v, static_cast<std::size_t>(g.adj[k]), b);
  return b;
}

}  // namespace

std::int32_t CellGraph::vertex_at(int x, int y, int z) const {
  if (x < 0 || y < 0 || z < 0 || x >= size[0] || y >= size[1] || z >= size[2]) return -1;
  return index[grid_position(x, y, z)];
}

CellGraph make_graph(const std::vector<std::uint8_t>& cells, int nx, int ny, int nz) {
  CellGraph g;
  g.size[0] = nx;
  g.size[1] = ny;
  g.size[2] = nz;
  if (cells.size() != static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) * static_cast<std::size_t>(nz))
    throw std::invalid_argument("shape: cell array does not match its size");
  g.index.assign(cells.size(), -1);
  for (int z = 0; z < nz; ++z)
    for (int y = 0; y < ny; ++y)
      for (int x = 0; x < nx; ++x)
        if (cells[g.grid_position(x, y, z)] != 0) {
          g.index[g.grid_position(x, y, z)] = static_cast<std::int32_t>(g.cells.size());
          g.cells.push_back({x, y, z});
        }
  static constexpr int kSteps[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  g.first.reserve(g.cells.size() + 1);
  g.first.push_back(0);
  for (const Cell& c : g.cells) {
    for (const auto& s : kSteps) {
      const std::int32_t w = g.vertex_at(c.x + s[0], c.y + s[1], c.z + s[2]);
      if (w >= 0) g.adj.push_back(w);
    }
    g.first.push_back(static_cast<std::uint32_t>(g.adj.size()));
  }
  return g;
}

std::size_t component_count(const CellGraph& g) {
  if (g.vertex_count() == 0) return 0;
  const BoostGraph b = to_boost(g);
  std::vector<std::size_t> component(g.vertex_count());
  return static_cast<std::size_t>(boost::connected_components(b, component.data()));
}

SpanningTree spanning_tree(const CellGraph& g) {
  SpanningTree t;
  t.parent.assign(g.vertex_count(), -1);
  if (g.vertex_count() == 0) return t;
  // A CSR graph holding both directions of every edge: BFS on it is BFS on the undirected grid
  // graph, without the per-vertex allocations of adjacency_list (3× faster refinement).
  std::vector<std::pair<std::size_t, std::size_t>> arcs;
  arcs.reserve(g.adj.size());
  for (std::size_t v = 0; v < g.vertex_count(); ++v)
    for (std::uint32_t k = g.first[v]; k < g.first[v + 1]; ++k) arcs.emplace_back(v, static_cast<std::size_t>(g.adj[k]));
  const boost::compressed_sparse_row_graph<boost::directedS> csr(boost::edges_are_sorted, arcs.begin(), arcs.end(),
                                                                 g.vertex_count());
  std::vector<std::size_t> pred(g.vertex_count());
  for (std::size_t v = 0; v < pred.size(); ++v) pred[v] = v;
  boost::breadth_first_search(
      csr, boost::vertex(0, csr),
      boost::visitor(boost::make_bfs_visitor(boost::record_predecessors(pred.data(), boost::on_tree_edge()))));
  std::size_t reached = 1;
  for (std::size_t v = 0; v < pred.size(); ++v)
    if (pred[v] != v) {
      t.parent[v] = static_cast<std::int32_t>(pred[v]);
      ++reached;
    }
  t.components = reached == g.vertex_count() ? 1 : component_count(g);
  return t;
}

}  // namespace foldkit::folding::detail
