#pragma once
// Hamiltonian paths through pixel and voxel shapes: the chain of cubes of the paper's Sec. 3.3
// (docs/HAMILTONIAN.md).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "foldkit/geometry/cell_shape.hpp"
#include "foldkit/geometry/status.hpp"

namespace foldkit::folding {

// The largest coarse shapes the exact search and the 2× refinement take: beyond them the answer
// would not fit in memory or time.
constexpr std::size_t kMaxExactCells = 1024;
constexpr std::size_t kMaxRefineCells = 2'500'000;

// The shapes live in geometry (their files in io/shape_file.hpp); the names stay usable here.
using geometry::Cell;
using geometry::PixelShape;
using geometry::VoxelShape;
using geometry::refine;

struct HamiltonianResult {
  // Success (a path or cycle was found), NoSolution (the shape is empty or not connected, fails
  // a necessary condition, or the exhausted search found none: proven), LimitReached (the node
  // budget ran out or the shape is too large: undecided); the message says why.
  geometry::Status status;
  // Cells in visiting order, each a unit step from the last; for a cycle the last cell is also
  // a unit step from the first (the first is not repeated).
  std::vector<Cell> path;
  bool cycle = false;
  std::uint64_t nodes = 0;  // search nodes expanded (exact search)
};

struct ExactOptions {
  std::uint64_t node_budget = 200'000;
  bool cycle = false;         // look for a Hamiltonian cycle instead of a path
  std::optional<Cell> start;  // the path must start here (path mode only)
};

// Backtracking with parity, degree and connectivity pruning. NoSolution when the shape is empty, not
// connected, fails a necessary condition or the search is exhausted; LimitReached when the budget
// runs out or the shape has more than kMaxExactCells cells.
HamiltonianResult exact_hamiltonian(const PixelShape& shape, const ExactOptions& options = {});
HamiltonianResult exact_hamiltonian(const VoxelShape& shape, const ExactOptions& options = {});

// The Hamiltonian cycle of refine(shape), in refined coordinates, built in linear time along a
// spanning tree of the coarse cells. NoSolution when the shape is empty or not connected; LimitReached
// beyond kMaxRefineCells coarse cells.
HamiltonianResult refined_hamiltonian_cycle(const PixelShape& shape);
HamiltonianResult refined_hamiltonian_cycle(const VoxelShape& shape);

}  // namespace foldkit::folding
