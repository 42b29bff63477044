#pragma once
/// @file
/// Hamiltonian paths through pixel and voxel shapes: the chain of cubes of the paper's Sec. 3.3
/// (docs/HAMILTONIAN.md).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "foldkit/geometry/cell_shape.hpp"
#include "foldkit/geometry/status.hpp"

namespace foldkit::folding {

/// The largest coarse shape, in filled cells, the exact search takes: beyond it the answer would
/// not fit in time (StatusCode::LimitReached).
constexpr std::size_t kMaxExactCells = 1024;
/// The largest coarse shape, in filled cells, the 2× refinement takes: beyond it the answer would
/// not fit in memory or time (StatusCode::LimitReached).
constexpr std::size_t kMaxRefineCells = 2'500'000;

// The shapes live in geometry (their files in io/shape_file.hpp); the names stay usable here.
using geometry::Cell;
using geometry::kMaxGridCells;
using geometry::PixelShape;
using geometry::VoxelShape;
using geometry::refine;

/// A Hamiltonian path or cycle through the filled cells of a shape, or why there is none.
struct HamiltonianResult {
  /// StatusCode::Success (a path or cycle was found), StatusCode::NoSolution (the shape is empty
  /// or not connected, the start is not a filled cell, it fails a necessary condition, or the
  /// exhausted search found none: proven), StatusCode::LimitReached (the node budget ran out or
  /// the shape is too large: undecided); the message says why.
  geometry::Status status;
  /// Cells in visiting order, each a unit step from the last; for a cycle the last cell is also
  /// a unit step from the first (the first is not repeated). Empty unless the status is
  /// StatusCode::Success.
  std::vector<Cell> path;
  bool cycle = false;       ///< whether `path` is a cycle
  std::uint64_t nodes = 0;  ///< search nodes expanded (exact search; 0 when it did not search)
};

/// Options of exact_hamiltonian().
struct ExactOptions {
  std::uint64_t node_budget = 200'000;  ///< search nodes to expand at most (then StatusCode::LimitReached)
  bool cycle = false;         ///< look for a Hamiltonian cycle instead of a path
  std::optional<Cell> start;  ///< the path must start here (path mode only; ignored for a cycle)
};

/// A Hamiltonian path (or cycle) through the filled pixels, by backtracking with parity, degree
/// and connectivity pruning (moves with fewest onward moves first). StatusCode::NoSolution when
/// the shape is empty, not connected, the start is not a filled cell, a necessary condition
/// fails (every failing one is listed) or the search is exhausted; StatusCode::LimitReached when
/// the budget runs out or the shape has more than kMaxExactCells filled cells.
/// @throws std::invalid_argument when `shape.cells` does not hold width × height entries
HamiltonianResult exact_hamiltonian(const PixelShape& shape, const ExactOptions& options = {});
/// A Hamiltonian path (or cycle) through the filled voxels; as the PixelShape overload.
/// @throws std::invalid_argument when `shape.cells` does not hold nx × ny × nz entries
HamiltonianResult exact_hamiltonian(const VoxelShape& shape, const ExactOptions& options = {});

/// The Hamiltonian cycle of refine(shape), in refined coordinates, built in linear time along a
/// spanning tree of the coarse cells; it starts at the first refined pixel of the first filled
/// coarse cell (in grid order: by row, then column). StatusCode::NoSolution when the shape is
/// empty or not connected; StatusCode::LimitReached beyond kMaxRefineCells filled coarse cells.
/// @throws std::invalid_argument when `shape.cells` does not hold width × height entries
HamiltonianResult refined_hamiltonian_cycle(const PixelShape& shape);
/// The Hamiltonian cycle of refine(shape) for voxels (2×2×2 blocks); as the PixelShape overload.
/// @throws std::invalid_argument when `shape.cells` does not hold nx × ny × nz entries
HamiltonianResult refined_hamiltonian_cycle(const VoxelShape& shape);

}  // namespace foldkit::folding
