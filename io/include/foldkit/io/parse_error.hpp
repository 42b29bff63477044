#pragma once
#include <stdexcept>
#include <string>

namespace foldkit::io {

// Invalid input, located in its file: what() is "FILE:LINE: message" ("FILE: message" when
// line is 0). The CLI prints it as is and exits 1.
class ParseError : public std::runtime_error {
 public:
  ParseError(std::string file, int line, std::string message);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& message() const { return message_; }

 private:
  std::string file_;
  int line_;
  std::string message_;
};

}  // namespace foldkit::io
