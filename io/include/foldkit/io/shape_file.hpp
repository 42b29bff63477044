#pragma once
/// @file
/// Pixel and voxel shape files: ASCII grids, PBM (P1 and P4) and voxel text (docs/HAMILTONIAN.md).
#include <string>

#include "foldkit/geometry/cell_shape.hpp"

namespace foldkit::io {

/// Parses an ASCII grid: '#' filled, '.' or ' ' empty, one row per line (row 0 on top), all rows
/// equally long. Line ends may be "\n" or "\r\n"; trailing empty lines are ignored.
/// @param text  the file's content
/// @param file  names the source in error messages only
/// @throws ParseError ("FILE:LINE: message") for an empty grid, a blank line inside it, a ragged
///         row, any other character, more than geometry::kMaxGridCells cells, or no filled cell
geometry::PixelShape parse_pixel_grid(const std::string& text, const std::string& file);
/// Parses a PBM image, P1 (plain) or P4 (raw); 1 = filled, row 0 on top. `#` comments in the
/// header are skipped.
/// @param bytes  the file's content
/// @param file   names the source in error messages only
/// @throws ParseError ("FILE:LINE: message") for another magic number, a missing or zero width or
///         height, more than geometry::kMaxGridCells pixels, a truncated raster or data after it,
///         a P1 pixel other than 0 or 1, or no filled pixel
geometry::PixelShape parse_pbm(const std::string& bytes, const std::string& file);
/// Parses voxel text: ASCII-grid layers (as parse_pixel_grid(), z = 0 first) separated by blank
/// lines, all of one size.
/// @param text  the file's content
/// @param file  names the source in error messages only
/// @throws ParseError ("FILE:LINE: message") for a MagicaVoxel binary file ("VOX "), no layer,
///         layers of different sizes, anything parse_pixel_grid() rejects in a layer (more than
///         geometry::kMaxGridCells cells counts all layers), or no filled cell
geometry::VoxelShape parse_voxel_layers(const std::string& text, const std::string& file);

/// Whether `path` names a voxel file: it ends in ".vox", in any case.
bool is_voxel_path(const std::string& path);
/// Reads the pixel shape at `path`: PBM when it ends in ".pbm" (in any case), else an ASCII grid
/// (.txt, .grid or any other name).
/// @throws ParseError when the file cannot be read or does not parse (parse_pbm(), parse_pixel_grid())
geometry::PixelShape read_pixel_shape(const std::string& path);
/// Reads the voxel text at `path` (parse_voxel_layers()), whatever its extension.
/// @throws ParseError when the file cannot be read or does not parse
geometry::VoxelShape read_voxel_shape(const std::string& path);

}  // namespace foldkit::io
