#pragma once
#include <optional>
#include <string>
#include <vector>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"

// FOLD 1.2 (edemaine/fold). Its edges_foldAngle is positive for valley folds, the opposite of
// ours; conversion negates it. Angles in FOLD are degrees.
namespace foldkit::io {

struct FoldImport {
  geometry::CreasePattern pattern;
  // The state the file describes: edges_foldAngle where given, else the dihedral angles of a
  // folded form (3D coordinates); empty for a plain crease pattern without angles.
  std::optional<geometry::FoldState> state;
  // One state per file_frames entry that carries edges_foldAngle.
  std::vector<geometry::FoldState> frames;
  geometry::Diagnostics warnings;
};

// Faces become actors (faces joined by "J" edges form one actor), edges shared by two actors
// become joints with ID = FOLD edge index + 1, actors get IDs 1.. in order of their first face.
// A folded form (3D, or flagged foldedForm) is unfolded isometrically into the plane first.
// Throws ParseError.
FoldImport parse_fold(const std::string& text, const std::string& name,
                      const geometry::BuildOptions& options = {});
FoldImport read_fold(const std::string& path, const geometry::BuildOptions& options = {});

struct FoldExport {
  std::optional<geometry::FoldState> state;   // written as edges_foldAngle of the key frame
  std::vector<geometry::FoldState> frames;     // written as file_frames (inheriting the key frame)
};
// Triangles become faces, every triangle side an edge (docs/FOLD.md). Joint IDs are not kept:
// re-import numbers joints by edge index + 1. Throws std::invalid_argument when a state or
// frame does not hold one angle per joint.
std::string write_fold(const geometry::CreasePattern& pattern, const FoldExport& extra = {});

}  // namespace foldkit::io
