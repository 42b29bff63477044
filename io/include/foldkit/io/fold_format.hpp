#pragma once
/// @file
/// FOLD 1.2 (edemaine/fold) import and export. FOLD's edges_foldAngle is positive for valley
/// folds, the opposite of ours; conversion negates it. Angles in FOLD are degrees, in foldkit
/// radians. docs/FOLD.md.
#include <optional>
#include <string>
#include <vector>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_state.hpp"

namespace foldkit::io {

/// What a FOLD file holds, as foldkit sees it.
struct FoldImport {
  geometry::CreasePattern pattern;  ///< the crease pattern, flat (unfolded when the file is folded)
  /// The state the file describes (one angle per joint, radians): edges_foldAngle where given,
  /// else the dihedral angles of a folded form (3D coordinates); empty for a plain crease
  /// pattern without angles.
  std::optional<geometry::FoldState> state;
  /// One state per file_frames entry with fold angles or coordinates of its own (an entry whose
  /// edges or faces differ from the key frame's is skipped, with a warning).
  std::vector<geometry::FoldState> frames;
  /// Warnings of the reader (a newer file_spec, a frame skipped) and of build_pattern().
  geometry::Diagnostics warnings;
};

/// Parses FOLD JSON. Faces become actors (faces joined by "J" edges form one actor), edges
/// shared by two actors become joints with ID = FOLD edge index + 1, actors get IDs 1.. in order
/// of their first face. A folded form (3D, or flagged foldedForm) is unfolded isometrically into
/// the plane first.
/// @param text     the file's content
/// @param name     the file name used in error messages
/// @param options  tolerances of build_pattern()
/// @throws ParseError for anything that is not FOLD foldkit can read, and for a crease pattern
///         build_pattern() rejects (every error listed)
FoldImport parse_fold(const std::string& text, const std::string& name,
                      const geometry::BuildOptions& options = {});
/// Reads and parses the FOLD file at `path`.
/// @throws ParseError when the file cannot be read or parse_fold() fails
FoldImport read_fold(const std::string& path, const geometry::BuildOptions& options = {});

/// Fold states written with a pattern by write_fold().
struct FoldExport {
  std::optional<geometry::FoldState> state;   ///< written as edges_foldAngle of the key frame
  std::vector<geometry::FoldState> frames;     ///< written as file_frames (inheriting the key frame)
  /// Seconds from the start of each frame (a simulated trajectory), written in each frame as
  /// the custom key "foldkit:time"; empty: not written.
  std::vector<double> frame_times;
};
/// The FOLD JSON of `pattern`. Triangles become faces, every triangle side an edge
/// (docs/FOLD.md). Joint IDs are not kept: re-import numbers joints by edge index + 1.
/// @throws std::invalid_argument when a state or frame does not hold one angle per joint, or
///         frame_times is neither empty nor one finite time per frame
std::string write_fold(const geometry::CreasePattern& pattern, const FoldExport& extra = {});

}  // namespace foldkit::io
