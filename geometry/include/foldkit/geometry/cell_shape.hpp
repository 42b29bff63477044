#pragma once
/// @file
/// Pixel and voxel shapes: the cells a chain of cubes fills (the paper's Sec. 3.3). The files
/// they are read from are io/shape_file.hpp; the Hamiltonian paths through them are
/// folding/hamiltonian.hpp.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace foldkit::geometry {

/// Largest grid, in cells filled or not, that the shape readers (io/shape_file.hpp) accept:
/// beyond it the answer would not fit in memory or time. refine() does not check it.
constexpr std::size_t kMaxGridCells = 10'000'000;

/// A pixel or voxel, by its integer grid coordinates; z is 0 in 2D. y grows downwards (row 0 is
/// the file's top row).
struct Cell {
  int x = 0,  ///< column
      y = 0,  ///< row, downwards
      z = 0;  ///< layer (0 in 2D)
  /// Same coordinates.
  friend bool operator==(const Cell& a, const Cell& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
  /// Different coordinates.
  friend bool operator!=(const Cell& a, const Cell& b) { return !(a == b); }
};

/// A 2D shape: a width × height grid of pixels, some of them filled.
struct PixelShape {
  int width = 0,   ///< columns of the grid
      height = 0;  ///< rows of the grid
  /// Row-major, width × height entries (row 0 on top): cells[y * width + x] != 0 when filled.
  std::vector<std::uint8_t> cells;
  /// Whether pixel (x, y) is filled; false outside the grid.
  bool filled(int x, int y) const;
  /// Number of filled pixels.
  std::size_t count() const;
};

/// A 3D shape: an nx × ny × nz grid of voxels, some of them filled.
struct VoxelShape {
  int nx = 0,  ///< grid size along x, in voxels
      ny = 0,  ///< grid size along y (downwards), in voxels
      nz = 0;  ///< grid size along z: the number of layers
  /// nx × ny × nz entries, layer by layer, each layer row-major: cells[(z * ny + y) * nx + x] != 0
  /// when filled.
  std::vector<std::uint8_t> cells;
  /// Whether voxel (x, y, z) is filled; false outside the grid.
  bool filled(int x, int y, int z) const;
  /// Number of filled voxels.
  std::size_t count() const;
};

/// The shape at twice the resolution: each pixel becomes 2×2 pixels (filled ones are 1, others 0).
PixelShape refine(const PixelShape& shape);
/// The shape at twice the resolution: each voxel becomes 2×2×2 voxels (filled ones are 1, others 0).
VoxelShape refine(const VoxelShape& shape);

}  // namespace foldkit::geometry
