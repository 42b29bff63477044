#pragma once
// gzip for io's files (docs/FORMATS.md, "Compressed files"): a file whose name ends in .gz is
// written compressed, a file that starts with gzip's magic bytes is read decompressed, whatever
// its name. Both ways go a chunk at a time, so that memory does not grow with the file: a Miura
// 60 × 60 fold is 112 MB of CMML and 8 MB of gzip. zlib stays inside io (gzip_stream.cpp).
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>

namespace foldkit::io::detail {

// Whether `path` names a compressed file: it ends in ".gz", ignoring case. The one place that
// knows the suffix: formats.cpp strips it to find the format, AtomicFile compresses by it.
bool gzip_name(const std::string& path);

// `path` without its trailing ".gz" (as is when it has none).
std::string without_gzip_suffix(const std::string& path);

// A file's text read a chunk at a time: inflated when the file starts with gzip's magic bytes
// (1f 8b), as is otherwise. Concatenated gzip members read as one text, as `gzip -d` reads them.
class TextReader {
 public:
  // Opens `path`: ParseError (line 0) when it cannot be opened or is a directory.
  explicit TextReader(const std::string& path);
  ~TextReader();
  TextReader(const TextReader&) = delete;
  TextReader& operator=(const TextReader&) = delete;

  // Appends up to `max` (> 0) bytes of text to `out`; false, appending nothing, once the text is
  // all read. ParseError for a read error, and for compressed data that is corrupt or cut short,
  // at the line the decompressed text had reached ("FILE:LINE: truncated gzip data: …").
  bool read(std::string& out, std::size_t max);
  // Whether the file is gzip-compressed.
  bool compressed() const;
  // The file's size in bytes on disk (0 when unknown): how much a plain file's text will take.
  std::size_t file_size() const;

 private:
  struct State;
  std::unique_ptr<State> s_;
};

// Deflates text into the gzip format, handing the compressed bytes to `out` a chunk at a time.
// The header has no name and no time stamp: the same text always gives the same bytes.
class GzipWriter {
 public:
  // Where compressed bytes go; it may throw, which abandons the stream.
  using Sink = std::function<void(const char* data, std::size_t size)>;
  explicit GzipWriter(Sink out);
  ~GzipWriter();
  GzipWriter(const GzipWriter&) = delete;
  GzipWriter& operator=(const GzipWriter&) = delete;

  // Compresses `text` (the output follows as the compressor's buffer fills).
  void write(std::string_view text);
  // Ends the stream: the rest of the compressed data and the trailer (CRC-32, length).
  void finish();

 private:
  struct State;
  std::unique_ptr<State> s_;
};

}  // namespace foldkit::io::detail
