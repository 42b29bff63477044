#pragma once
#include <string>

namespace foldkit::io {

// Writes to a temporary file beside `path`, then renames it over `path`: readers never see a
// partial file, and a failure leaves any old file untouched. Throws std::runtime_error.
void write_file_atomic(const std::string& path, const std::string& content);

// Whole file as bytes; throws ParseError(path, 0, …) when it cannot be read.
std::string read_file(const std::string& path);

}  // namespace foldkit::io
