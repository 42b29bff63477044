#pragma once
// Hamiltonian paths through pixel and voxel shapes: the chain of cubes of the paper's Sec. 3.3
// (docs/HAMILTONIAN.md).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "foldkit/geometry/status.hpp"

namespace foldkit::folding {

// Largest grid (filled or not) the readers accept, and the largest coarse shapes the exact search
// and the 2× refinement take: beyond them the answer would not fit in memory or time.
constexpr std::size_t kMaxGridCells = 10'000'000;
constexpr std::size_t kMaxExactCells = 1024;
constexpr std::size_t kMaxRefineCells = 2'500'000;

// A pixel or voxel; z is 0 in 2D. y grows downwards (row 0 is the file's top row).
struct Cell {
  int x = 0, y = 0, z = 0;
  friend bool operator==(const Cell& a, const Cell& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
  friend bool operator!=(const Cell& a, const Cell& b) { return !(a == b); }
};

// Row-major, cells[y * width + x] != 0 when filled.
struct PixelShape {
  int width = 0, height = 0;
  std::vector<std::uint8_t> cells;
  bool filled(int x, int y) const;  // false outside the grid
  std::size_t count() const;
};

// cells[(z * ny + y) * nx + x] != 0 when filled.
struct VoxelShape {
  int nx = 0, ny = 0, nz = 0;
  std::vector<std::uint8_t> cells;
  bool filled(int x, int y, int z) const;  // false outside the grid
  std::size_t count() const;
};

// Readers throw foldkit::io::ParseError ("FILE:LINE: message"); `file` only names the source.
// ASCII grid: '#' filled, '.' or ' ' empty, one row per line, all rows equally long.
PixelShape parse_pixel_grid(const std::string& text, const std::string& file);
// PBM, P1 (plain) or P4 (raw); 1 = filled.
PixelShape parse_pbm(const std::string& bytes, const std::string& file);
// Voxel text: ASCII-grid layers (z = 0 first) separated by blank lines, all of one size.
VoxelShape parse_voxel_layers(const std::string& text, const std::string& file);

bool is_voxel_path(const std::string& path);           // .vox
PixelShape read_pixel_shape(const std::string& path);  // .pbm, else ASCII grid (.txt, .grid)
VoxelShape read_voxel_shape(const std::string& path);

// Each pixel → 2×2 pixels, each voxel → 2×2×2 voxels.
PixelShape refine(const PixelShape& shape);
VoxelShape refine(const VoxelShape& shape);

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
