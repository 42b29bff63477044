#include "foldkit/geometry/cell_shape.hpp"

#include <algorithm>

namespace foldkit::geometry {

bool PixelShape::filled(int x, int y) const {
  return x >= 0 && y >= 0 && x < width && y < height &&
         cells[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)] != 0;
}
std::size_t PixelShape::count() const {
  return static_cast<std::size_t>(std::count_if(cells.begin(), cells.end(), [](std::uint8_t c) { return c != 0; }));
}

bool VoxelShape::filled(int x, int y, int z) const {
  return x >= 0 && y >= 0 && z >= 0 && x < nx && y < ny && z < nz &&
         cells[(static_cast<std::size_t>(z) * static_cast<std::size_t>(ny) + static_cast<std::size_t>(y)) *
                   static_cast<std::size_t>(nx) +
               static_cast<std::size_t>(x)] != 0;
}
std::size_t VoxelShape::count() const {
  return static_cast<std::size_t>(std::count_if(cells.begin(), cells.end(), [](std::uint8_t c) { return c != 0; }));
}

PixelShape refine(const PixelShape& s) {
  PixelShape r;
  r.width = 2 * s.width;
  r.height = 2 * s.height;
  r.cells.assign(static_cast<std::size_t>(r.width) * static_cast<std::size_t>(r.height), 0);
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x)
      r.cells[static_cast<std::size_t>(y) * static_cast<std::size_t>(r.width) + static_cast<std::size_t>(x)] =
          s.filled(x / 2, y / 2) ? 1 : 0;
  return r;
}

VoxelShape refine(const VoxelShape& s) {
  VoxelShape r;
  r.nx = 2 * s.nx;
  r.ny = 2 * s.ny;
  r.nz = 2 * s.nz;
  r.cells.reserve(static_cast<std::size_t>(r.nx) * static_cast<std::size_t>(r.ny) * static_cast<std::size_t>(r.nz));
  for (int z = 0; z < r.nz; ++z)
    for (int y = 0; y < r.ny; ++y)
      for (int x = 0; x < r.nx; ++x) r.cells.push_back(s.filled(x / 2, y / 2, z / 2) ? 1 : 0);
  return r;
}

}  // namespace foldkit::geometry
