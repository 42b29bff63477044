#pragma once
/// @file
/// Planar chain files (the input of Carpenter's rule, docs/CARPENTER.md) and the frames of a
/// chain's motion written as CSV or JSON.
#include <string>
#include <vector>

#include <Eigen/Core>

namespace foldkit::io {

/// One frame of a planar chain's motion: a position per chain vertex, in the chain file's length
/// units (folding::Frame2 is the same type).
using Frame2 = std::vector<Eigen::Vector2d>;

/// Parses a chain file: one "x y" per line (two finite numbers, io::parse_numbers()), '#' starts
/// a comment, blank lines skipped.
/// @param text  the file's content
/// @param file  names the source in error messages only
/// @return the chain's vertices in file order, at least one
/// @throws ParseError ("FILE:LINE: what is wrong") for a line that is not two finite numbers, or a
///         file without any point
Frame2 parse_chain_points(const std::string& text, const std::string& file);

/// The frames as CSV: a "frame,vertex,x,y" header, then one row per vertex of each frame
/// (0-based indices, shortest round-trip numbers).
std::string frames_csv(const std::vector<Frame2>& frames);
/// The frames as JSON: {"closed": `closed`, "frames": [[[x, y], …], …]}, one array of vertex
/// positions per frame (shortest round-trip numbers).
/// @param frames  the frames, in order
/// @param closed  whether the chain is a closed polygon (written as is)
std::string frames_json(const std::vector<Frame2>& frames, bool closed);

}  // namespace foldkit::io
