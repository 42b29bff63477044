#pragma once
/// @file
/// Pixel and voxel shape files: ASCII grids, PBM (P1 and P4) and voxel text (docs/HAMILTONIAN.md).
#include <string>

#include "foldkit/geometry/cell_shape.hpp"

namespace foldkit::io {

// Readers throw foldkit::io::ParseError ("FILE:LINE: message"); `file` only names the source.
// ASCII grid: '#' filled, '.' or ' ' empty, one row per line, all rows equally long.
geometry::PixelShape parse_pixel_grid(const std::string& text, const std::string& file);
// PBM, P1 (plain) or P4 (raw); 1 = filled.
geometry::PixelShape parse_pbm(const std::string& bytes, const std::string& file);
// Voxel text: ASCII-grid layers (z = 0 first) separated by blank lines, all of one size.
geometry::VoxelShape parse_voxel_layers(const std::string& text, const std::string& file);

bool is_voxel_path(const std::string& path);           // .vox
geometry::PixelShape read_pixel_shape(const std::string& path);  // .pbm, else ASCII grid (.txt, .grid)
geometry::VoxelShape read_voxel_shape(const std::string& path);

}  // namespace foldkit::io
