#pragma once
// The file behind write_file_atomic, written a piece at a time (write_cmml_file streams a fold
// sequence through it): a temporary beside the target, renamed over it on commit(), removed when
// the writer is dropped before that, so that no failure leaves a partial file.
#include <memory>
#include <string>
#include <string_view>

namespace foldkit::io::detail {

class GzipWriter;

class AtomicFile {
 public:
  // Creates the temporary file beside `path` (a symbolic link's target is the one replaced); its
  // content is gzip-compressed when `path` ends in .gz (gzip_stream.hpp). WriteError on failure.
  explicit AtomicFile(const std::string& path);
  // Removes the temporary file unless commit() succeeded.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Appends text to the file. WriteError on failure.
  void write(std::string_view text);
  // Ends the compressed stream, syncs the data to disk and renames the file over `path`.
  // WriteError on failure (the temporary file is removed, an old file at `path` is untouched).
  void commit();

 private:
  void write_bytes(const char* data, std::size_t size);
  [[noreturn]] void fail(int err);

  std::string path_;         // as given, for messages
  std::string target_;       // the file replaced
  std::string temp_;         // the temporary beside it, empty once renamed or removed
  int fd_ = -1;
  std::unique_ptr<GzipWriter> gzip_;
};

}  // namespace foldkit::io::detail
