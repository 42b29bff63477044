#pragma once
#include <algorithm>
#include <string_view>

namespace foldkit::io::detail {

// 1-based line of the byte at `offset` in `text`.
inline int line_at(std::string_view text, std::size_t offset) {
  offset = std::min(offset, text.size());
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

// Whether `s` is XML white space only (space, tab, line feed, carriage return), or empty.
inline bool blank(std::string_view s) { return s.find_first_not_of(" \t\n\r") == std::string_view::npos; }

}  // namespace foldkit::io::detail
