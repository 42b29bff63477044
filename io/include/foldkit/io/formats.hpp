#pragma once
/// @file
/// The file formats foldkit reads and writes, in one table chosen by a path's extension. The CLI,
/// `foldkit serve` and the Python module all pick formats through it, so a new format is one new
/// entry in `io/src/formats.cpp` (docs/FORMATS.md, docs/ARCHITECTURE.md).
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/diagnostics.hpp"
#include "foldkit/geometry/fold_state.hpp"

namespace foldkit::io {

/// The formats of the table.
enum class FileKind {
  Pmml,  ///< the paper's crease-pattern file (Table 1)
  Cmml,  ///< the paper's fold sequence (Table 2)
  Fold,  ///< FOLD 1.2 (edemaine/fold), the origami world's exchange format
  Svg,   ///< a drawing of the pattern in Origami Simulator's convention (drawn_lines.hpp)
  Cp,    ///< ORIPA's line format (read only; drawn_lines.hpp)
  Opx,   ///< ORIPA's XML (read only; drawn_lines.hpp)
};

/// A crease pattern read from a file, with the fold angles the file carries.
struct PatternFile {
  geometry::CreasePattern pattern;  ///< flat, as every reader builds it
  /// Fold angles the file gives (one per joint, radians, positive = mountain); empty when none.
  std::optional<geometry::FoldState> state;
  geometry::Diagnostics warnings;  ///< what the reader accepted but reports (FILE:LINE)
};

/// What writing a pattern may use besides the pattern.
struct PatternOutput {
  /// Fold angles (radians; must outlive the call): FOLD keeps them, SVG colours the creases by
  /// their sign, CMML needs them (one event from flat to them); may be null.
  const geometry::FoldState* state = nullptr;
  bool joint_ids = false;  ///< SVG: label each joint with its ID
};

/// One format of the table. An empty reader or writer: the format does not hold that.
struct FileFormat {
  FileKind kind;           ///< which format
  std::string name;        ///< as messages and docs name it: "PMML"
  std::string extension;   ///< with its dot, lower case (matched ignoring case): ".pmml"
  std::string media_type;  ///< how `foldkit serve` sends the file: "application/xml"
  /// Reads a crease pattern; throws ParseError at the file's line.
  std::function<PatternFile(const std::string& path, const geometry::BuildOptions& options)> read_pattern;
  /// The text of a file holding `pattern`; throws std::invalid_argument when the format needs
  /// what `output` lacks (CMML without a state).
  std::function<std::string(const geometry::CreasePattern& pattern, const PatternOutput& output)> write_pattern;
  bool sequence = false;  ///< whether it holds a fold sequence (read_cmml, write_cmml)
};

/// Every format, in a fixed order (PMML, CMML, FOLD, SVG, .cp, .opx): the order messages list them in.
const std::vector<FileFormat>& file_formats();

/// The format of `path` by its extension, ignoring case and a trailing `.gz` (`X.cmml.gz` is CMML,
/// written gzip-compressed; docs/FORMATS.md, "Compressed files"); null when no format has it.
const FileFormat* format_of(const std::string& path);

/// The extensions of the formats `which` accepts, as a message lists them: ".pmml or .fold",
/// ".pmml, .cmml, .fold or .svg".
std::string extensions(const std::function<bool(const FileFormat&)>& which);

/// Whether the format reads crease patterns; for extensions() and format checks.
inline bool reads_patterns(const FileFormat& f) { return static_cast<bool>(f.read_pattern); }
/// Whether the format writes crease patterns.
inline bool writes_patterns(const FileFormat& f) { return static_cast<bool>(f.write_pattern); }
/// Whether foldkit reads the format at all (a pattern or a sequence).
inline bool readable(const FileFormat& f) { return f.read_pattern || f.sequence; }

/// A file whose extension names no format that can do what was asked. The CLI reports it as a
/// usage error (exit 2), Python as ValueError.
class UnknownFormat : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// A crease pattern from `path`, read by the format its extension names.
/// @throws UnknownFormat "PATH: a crease pattern must be a .pmml or .fold file" for any other extension
/// @throws ParseError at the file's line for a file its format refuses
PatternFile read_pattern_file(const std::string& path, const geometry::BuildOptions& options = {});

/// The text of a file at `path` holding `pattern`, in the format its extension names.
/// @throws UnknownFormat "PATH: unknown output type (use .pmml, .cmml, .fold or .svg)" for any other extension
/// @throws std::invalid_argument when the format needs what `output` lacks
std::string pattern_text(const std::string& path, const geometry::CreasePattern& pattern, const PatternOutput& output = {});

}  // namespace foldkit::io
