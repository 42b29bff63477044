#pragma once
/// @file
/// The exception every reader throws for invalid input.
#include <stdexcept>
#include <string>

namespace foldkit::io {

/// Invalid input, located in its file: what() is "FILE:LINE: message" ("FILE: message" when
/// line is 0). The CLI prints it as is and exits 1.
class ParseError : public std::runtime_error {
 public:
  /// An error at `line` (1-based; 0 for the file as a whole) of `file`.
  ParseError(std::string file, int line, std::string message);
  /// The file name, as given to the reader.
  const std::string& file() const { return file_; }
  /// The line, 1-based; 0 when the error concerns the whole file.
  int line() const { return line_; }
  /// The message without its location.
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  int line_;
  std::string message_;
};

}  // namespace foldkit::io
