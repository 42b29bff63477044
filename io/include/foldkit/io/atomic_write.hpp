#pragma once
#include <stdexcept>
#include <string>

namespace foldkit::io {

// A file could not be written; what() is "PATH: cannot write: reason".
class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writes to a temporary file beside `path`, then renames it over `path`: readers never see a
// partial file, and a failure leaves any old file untouched. A symbolic link is followed (its
// target is replaced), and an existing file keeps its permissions. Throws WriteError.
void write_file_atomic(const std::string& path, const std::string& content);

// Whole file as bytes; throws ParseError(path, 0, …) when it cannot be read.
std::string read_file(const std::string& path);

}  // namespace foldkit::io
