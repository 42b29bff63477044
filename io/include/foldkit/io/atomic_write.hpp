#pragma once
/// @file
/// Whole-file reads, and writes that never leave a partial file behind.
#include <stdexcept>
#include <optional>
#include <string>

/// Reading and writing foldkit's file formats: PMML patterns, CMML fold sequences, FOLD 1.2
/// import and export, SVG drawings, and the number formatting they share.
namespace foldkit::io {

/// A file could not be written; what() is "PATH: cannot write: reason".
class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Writes to a temporary file beside `path`, then renames it over `path`: readers never see a
/// partial file, and a failure leaves any old file untouched. A symbolic link is followed (its
/// target is replaced); an existing file keeps its permissions, a new one gets those the umask
/// allows. The data is synced to disk before the rename. When `path` ends in `.gz` (`X.cmml.gz`,
/// `X.fold.gz`, any case), the file holds `content` gzip-compressed, a chunk at a time
/// (docs/FORMATS.md, "Compressed files").
/// @param path     the file to write
/// @param content  its bytes (uncompressed)
/// @throws WriteError when any step fails (the temporary file is removed)
void write_file_atomic(const std::string& path, const std::string& content);

/// Whole file as bytes, decompressed when it is gzip-compressed (it starts with gzip's magic bytes
/// 1f 8b, whatever its name).
/// @throws ParseError (path, line 0) when it cannot be opened or read, or is a directory; for
///         compressed data that is corrupt or cut short, at the line its text reached
///         ("FILE:LINE: truncated gzip data: …")
std::string read_file(const std::string& path);

/// read_file()'s bytes, or nothing when `path` does not exist: a file that a command makes when
/// it is missing (`foldkit plan --experience DB`). A path that cannot be looked at is an error,
/// not a missing file, so that nothing is written over a file that could not be read.
/// @throws ParseError (path, line 0) as read_file(), and when its existence cannot be told
std::optional<std::string> read_file_if_present(const std::string& path);

}  // namespace foldkit::io
