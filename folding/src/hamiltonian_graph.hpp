#pragma once
// The grid graph of a pixel or voxel shape, shared by the exact search and the refinement.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "foldkit/folding/hamiltonian.hpp"

namespace foldkit::folding::detail {

struct CellGraph {
  int size[3] = {0, 0, 0};           // grid extent in x, y, z
  std::vector<Cell> cells;           // vertex → coordinates, in grid order
  std::vector<std::int32_t> index;   // grid position → vertex, −1 when empty
  std::vector<std::uint32_t> first;  // CSR: neighbours of v are adj[first[v] .. first[v + 1])
  std::vector<std::int32_t> adj;

  std::size_t vertex_count() const { return cells.size(); }
  std::size_t grid_position(int x, int y, int z) const {
    return (static_cast<std::size_t>(z) * static_cast<std::size_t>(size[1]) + static_cast<std::size_t>(y)) *
               static_cast<std::size_t>(size[0]) +
           static_cast<std::size_t>(x);
  }
  std::int32_t vertex_at(int x, int y, int z) const;  // −1 outside the grid or empty
  int degree(std::int32_t v) const {
    return static_cast<int>(first[static_cast<std::size_t>(v) + 1] - first[static_cast<std::size_t>(v)]);
  }
};

CellGraph make_graph(const std::vector<std::uint8_t>& cells, int nx, int ny, int nz);

// Connected components and a BFS spanning tree, both by Boost.Graph.
std::size_t component_count(const CellGraph& g);
struct SpanningTree {
  std::vector<std::int32_t> parent;  // −1 for the root (vertex 0) and for vertices it cannot reach
  std::size_t components = 0;
};
SpanningTree spanning_tree(const CellGraph& g);

HamiltonianResult exact_search(const CellGraph& g, const ExactOptions& options);
// dimension 2 or 3; `tree` spans g (connected, non-empty).
HamiltonianResult refine_cycle(const CellGraph& g, const SpanningTree& tree, int dimension);

}  // namespace foldkit::folding::detail
