#pragma once
/// @file
/// Load cases (docs/FORMATS.md, "Load case"): reading them and applying them to a structure.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "foldkit/analysis/equilibrium.hpp"

namespace foldkit::analysis {

/// A dead load as written in a load case (`<Load>`).
struct LoadSpec {
  int actor = 0;  ///< actor ID
  Eigen::Vector3d force = Eigen::Vector3d::Zero();  ///< force, N (fixed direction)
  std::optional<Eigen::Vector3d> point;  ///< in the folded state's coordinates, pattern units; none = the centroid
  int line = 0;  ///< source line of the `<Load>`
};

/// A load case (docs/FORMATS.md, "Load case"): stiffness per connection kind (Eq. 6 for a kind
/// left out), fixed actors, dead loads.
struct LoadCase {
  std::string title;  ///< free text
  std::array<Matrix6, 3> stiffness{default_stiffness(ConnectionKind::Hinged), default_stiffness(ConnectionKind::Face),
                                   default_stiffness(ConnectionKind::Edge)};  ///< one matrix per ConnectionKind, indexed by its value
  std::vector<int> fixed;  ///< actor IDs, each once
  std::vector<int> fixed_lines;  ///< source line of each entry of `fixed`
  std::vector<LoadSpec> loads;  ///< in file order
  int line = 1;  ///< source line of `<LoadCase>`
};

/// Parses load-case XML.
/// @param text  the file's content
/// @param name  the file name used in error messages
/// @throws io::ParseError ("NAME:LINE: message") for anything that is not a load case: unknown
///         or repeated elements, attributes, non-finite numbers, a stiffness that is not 6
///         positive values or a symmetric positive definite 6×6, an actor fixed twice, no fixed
///         actor
LoadCase parse_load_case(const std::string& text, const std::string& name);
/// Reads and parses the load case at `path`.
/// @throws io::ParseError when the file cannot be read or parse_load_case() fails
LoadCase read_load_case(const std::string& path);

/// The load case applied to a structure: actor IDs become module indices, a load without a
/// point acts at its module's centroid.
/// @param structure  the structure (moved into the problem)
/// @param load_case  the load case
/// @param name       the load case's file name, for error messages
/// @throws io::ParseError at the offending line of the load case for an actor ID the pattern
///         lacks, or a module no chain of connections ties to a fixed one
Problem make_problem(Structure structure, const LoadCase& load_case, const std::string& name);

}  // namespace foldkit::analysis
