#pragma once
/// @file
/// Planar chain files (the input of Carpenter's rule, docs/CARPENTER.md) and the frames of a
/// chain's motion written as CSV or JSON.
#include <string>
#include <vector>

#include <Eigen/Core>

namespace foldkit::io {

// One frame of a planar chain's motion: a position per chain vertex (folding::Frame2 is the same type).
using Frame2 = std::vector<Eigen::Vector2d>;

// A chain file: one "x y" per line, '#' starts a comment, blank lines skipped. Throws
// io::ParseError "FILE:LINE: what is wrong".
Frame2 parse_chain_points(const std::string& text, const std::string& file);

// Outputs. CSV: "frame,vertex,x,y" rows. JSON: {"closed", "frames": [[[x, y], …], …]}.
std::string frames_csv(const std::vector<Frame2>& frames);
std::string frames_json(const std::vector<Frame2>& frames, bool closed);

}  // namespace foldkit::io
