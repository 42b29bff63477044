#pragma once
/// @file
/// Pixel and voxel shapes: the cells a chain of cubes fills (the paper's Sec. 3.3). The files
/// they are read from are io/shape_file.hpp; the Hamiltonian paths through them are
/// folding/hamiltonian.hpp.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace foldkit::geometry {

// Largest grid (filled or not) the readers accept: beyond it the answer would not fit in memory
// or time.
constexpr std::size_t kMaxGridCells = 10'000'000;

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

// Each pixel → 2×2 pixels, each voxel → 2×2×2 voxels.
PixelShape refine(const PixelShape& shape);
VoxelShape refine(const VoxelShape& shape);

}  // namespace foldkit::geometry
