#pragma once
/// @file
/// CMML fold sequences (paper Table 2): reading and writing.
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "foldkit/geometry/fold_sequence.hpp"

namespace foldkit::io {

/// Parses CMML text (paper Table 2): FoldAngle in degrees within [−180, 180], Velocity in
/// degrees per second, positive (also once converted to radians: 5e-324 is rejected as too
/// small); EventNumber a non-negative integer. The text must be UTF-8. Angles and velocities are
/// returned in radians, folds grouped into events by number (geometry::make_sequence).
/// @param text  the file's content
/// @param name  the file name used in error messages
/// @throws ParseError for anything that is not CMML, at the offending line
geometry::FoldSequence parse_cmml(const std::string& text, const std::string& name);
/// Reads and parses the CMML file at `path`, gzip-compressed when it starts with gzip's magic bytes
/// (1f 8b), whatever its name. A large file is read a slice at a time as parse_cmml() reads it, the
/// file's text pulled as the slices need it, so that neither the text nor the compressed file is
/// in memory whole.
/// @throws ParseError when the file cannot be read or is not CMML; for compressed data that is
///         corrupt or cut short, at the line its text reached
geometry::FoldSequence read_cmml(const std::string& path);

/// The CMML text of `sequence`. Angles are clamped to [−π, π] and written in degrees; angles
/// within rounding of ±180° are written as ±180, so every written angle reads back. Velocities
/// are written in degrees per second. The title is written with escape rules that keep the file
/// valid XML (characters XML forbids become U+FFFD).
/// @throws std::invalid_argument for a non-finite angle or speed, a speed ≤ 0, or one
///         whose degrees overflow or are too small to read back as positive
std::string write_cmml(const geometry::FoldSequence& sequence);

/// Writes the CMML text of `sequence` (the bytes of write_cmml()) to `path` a piece at a time, as
/// write_file_atomic() writes: to a temporary renamed over `path`, gzip-compressed when `path`
/// ends in `.gz`. Nothing is left at `path` when it fails.
/// @throws std::invalid_argument as write_cmml() does
/// @throws WriteError when the file cannot be written
void write_cmml_file(const std::string& path, const geometry::FoldSequence& sequence);

namespace detail {
class AtomicFile;
}  // namespace detail

/// write_cmml_file() in two steps, so that a file can be written while what decides whether to
/// keep it still runs (`foldkit plan` writes its plan during the replay): the constructor writes
/// the CMML text of `sequence` (the bytes of write_cmml()) to a temporary beside `path`, commit()
/// puts it at `path`. Destroyed uncommitted, it removes the temporary and leaves `path` untouched.
class PendingCmmlFile {
 public:
  /// Writes the temporary file.
  /// @throws std::invalid_argument as write_cmml() does
  /// @throws WriteError when the file cannot be written
  PendingCmmlFile(const std::string& path, const geometry::FoldSequence& sequence);
  /// Removes the temporary file unless commit() succeeded.
  ~PendingCmmlFile();
  PendingCmmlFile(const PendingCmmlFile&) = delete;             ///< one temporary, one owner
  PendingCmmlFile& operator=(const PendingCmmlFile&) = delete;  ///< one temporary, one owner
  /// Syncs the file to disk and renames it over `path`, as write_file_atomic() does; once.
  /// @throws WriteError when that fails (the temporary is removed, an old file at `path` is untouched)
  void commit();

 private:
  std::unique_ptr<detail::AtomicFile> file_;
};

namespace detail {

/// parse_cmml() of a large file, a slice of about `slice_bytes` of <Fold> elements at a time, so
/// that only one slice's XML document is in memory (parse_cmml uses it from 4 MB on). Empty for a
/// file it does not read this way (a comment, CDATA, a processing instruction or a DOCTYPE after
/// <CMML>) and for any problem, which reading the whole file reports; otherwise equal to reading
/// it whole (lines included).
/// @param text         the file's content
/// @param name         the file name of the lines
/// @param slice_bytes  about how many bytes of <Fold> elements each slice holds
std::optional<geometry::FoldSequence> parse_cmml_sliced(const std::string& text, const std::string& name, std::size_t slice_bytes);

/// The <Fold> elements of `body`, part of a <CMML> element's content, read without an XML parser
/// when it holds nothing else (white space between them, but no carriage return) and each is in
/// the shape write_cmml() writes: <EventNumber>, <ID>, <FoldAngle>, <Velocity> in that order, no
/// attribute, comment or entity, each text a number's characters only. Appended to `folds` with
/// their event numbers and lines, exactly as parse_cmml() reads them, when every fold is in that
/// shape and passes parse_cmml()'s checks; false, `folds` unchanged, when one is not (the XML
/// reading then decides, and reports any error).
/// @param body        the text, a sequence of <Fold> elements and white space
/// @param first_line  the line of body's first byte in its file
/// @param folds       where the folds read are appended
bool read_plain_folds(std::string_view body, int first_line, std::vector<std::pair<int, geometry::FoldCommand>>& folds);

}  // namespace detail

}  // namespace foldkit::io
