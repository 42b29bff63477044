#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "foldkit/analysis/equilibrium.hpp"

namespace foldkit::analysis {

struct LoadSpec {
  int actor = 0;  // actor ID
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  std::optional<Eigen::Vector3d> point;  // in the folded state's frame; none = the centroid
  int line = 0;
};

// A load case (docs/FORMATS.md, "Load case"): stiffness per connection kind (Eq. 6 for a kind
// left out), fixed actors, dead loads.
struct LoadCase {
  std::string title;
  std::array<Matrix6, 3> stiffness{default_stiffness(ConnectionKind::Hinged), default_stiffness(ConnectionKind::Face),
                                   default_stiffness(ConnectionKind::Edge)};
  std::vector<int> fixed;  // actor IDs
  std::vector<int> fixed_lines;
  std::vector<LoadSpec> loads;
  int line = 1;  // of <LoadCase>
};

// Throws io::ParseError ("NAME:LINE: message") for anything that is not a load case: unknown or
// repeated elements, attributes, non-finite numbers, a stiffness that is not 6 positive values or
// a symmetric positive definite 6×6, no fixed actor.
LoadCase parse_load_case(const std::string& text, const std::string& name);
LoadCase read_load_case(const std::string& path);

// The load case applied to a structure; ParseError at the offending line of the load case for an
// actor ID the pattern lacks, or a module no chain of connections ties to a fixed one.
Problem make_problem(Structure structure, const LoadCase& load_case, const std::string& name);

}  // namespace foldkit::analysis
