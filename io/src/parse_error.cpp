#include "foldkit/io/parse_error.hpp"

namespace foldkit::io {
namespace {
std::string located(const std::string& file, int line, const std::string& message) {
  return file + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + message;
}
}  // namespace

ParseError::ParseError(std::string file, int line, std::string message)
    : std::runtime_error(located(file, line, message)), file_(std::move(file)), line_(line), message_(std::move(message)) {}

}  // namespace foldkit::io
