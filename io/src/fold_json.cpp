// The JSON text of a FOLD file: checks before parsing, located parse errors, value lines.
#include "fold_json.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "foldkit/io/parse_error.hpp"
#include "text_lines.hpp"

namespace foldkit::io::detail {
namespace {

// FOLD needs about six levels; anything far deeper is not a FOLD file, and refusing it early
// keeps every recursive step after it (ours and nlohmann's) safe.
constexpr int kMaxDepth = 64;


// nlohmann reports number overflow (1e999) without a position; find the token ourselves.
int overflow_line(std::string_view text) {
  int line = 1;
  bool in_string = false;
  bool escaped = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') ++line;
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      std::size_t j = i;
      while (j < text.size() && std::string_view("0123456789+-.eE").find(text[j]) != std::string_view::npos) ++j;
      const std::string token(text.substr(i, j - i));
      if (!std::isfinite(std::strtod(token.c_str(), nullptr))) return line;
      i = j - 1;
    }
  }
  return 1;
}

}  // namespace

std::string printable(std::string_view s) {
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x20 && c < 0x7f) {
      out += ch;
    } else {
      out += "\\x";
      out += hex[c >> 4U];
      out += hex[c & 0xfU];
    }
  }
  return out;
}

void check_text(std::string_view text, const std::string& name) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos)
    throw ParseError(name, 1, "empty file: expected a FOLD JSON object");
  int depth = 0;
  int line = 1;
  bool in_string = false;
  bool escaped = false;
  for (char c : text) {
    if (c == '\n') ++line;
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxDepth)
        throw ParseError(name, line, "JSON nested deeper than " + std::to_string(kMaxDepth) + " levels");
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

json parse_json(const std::string& text, const std::string& name) {
  try {
    return json::parse(text);
  } catch (const json::parse_error& e) {
    std::string what = e.what();
    // nlohmann: "[json.exception.parse_error.101] parse error at line L, column C: detail"
    const std::size_t column = what.find("column ");
    const std::size_t colon = column == std::string::npos ? std::string::npos : what.find(": ", column);
    std::string detail = what;
    if (colon != std::string::npos)
      detail = "invalid JSON (" + what.substr(column, colon - column) + "): " + what.substr(colon + 2);
    const std::size_t offset = e.byte > 0 ? e.byte - 1 : 0;
    throw ParseError(name, line_at(text, offset), printable(detail));
  } catch (const json::out_of_range&) {
    throw ParseError(name, overflow_line(text), "number out of range (not a finite double)");
  } catch (const json::exception& e) {
    throw ParseError(name, 1, printable(e.what()));
  }
}

LineMap::LineMap(std::string_view text) : text_(text) { root_ = value(0); }

Loc LineMap::member(const Loc& at, std::string_view key) const {
  if (at.node < 0) return {-1, at.line};
  const Node& n = nodes_[static_cast<std::size_t>(at.node)];
  for (std::size_t i = n.keys.size(); i-- > 0;)  // nlohmann keeps the last duplicate
    if (n.keys[i] == key) return n.children[i];
  return {-1, at.line};
}

Loc LineMap::item(const Loc& at, std::size_t index) const {
  if (at.node < 0) return {-1, at.line};
  const Node& n = nodes_[static_cast<std::size_t>(at.node)];
  if (n.object || index >= n.children.size()) return {-1, at.line};
  return n.children[index];
}

char LineMap::peek() const { return pos_ < text_.size() ? text_[pos_] : '\0'; }

void LineMap::skip_space() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == '\n') ++line_;
    else if (c != ' ' && c != '\t' && c != '\r') break;
    ++pos_;
  }
}

std::string LineMap::string_token() {
  const std::size_t start = std::min(++pos_, text_.size());
  while (pos_ < text_.size() && text_[pos_] != '"') {
    if (text_[pos_] == '\\') ++pos_;
    else if (text_[pos_] == '\n') ++line_;
    ++pos_;
  }
  std::string s(text_.substr(start, std::min(pos_, text_.size()) - start));
  ++pos_;
  return s;
}

Loc LineMap::value(int depth) {
  skip_space();
  const int line = line_;
  const char c = peek();
  if (c == '"') {
    string_token();
    return {-1, line};
  }
  if (c != '[' && c != '{') {
    while (pos_ < text_.size()) {
      const char d = text_[pos_];
      if (d == ',' || d == ']' || d == '}' || d == ' ' || d == '\t' || d == '\r' || d == '\n') break;
      ++pos_;
    }
    return {-1, line};
  }
  const bool object = c == '{';
  const char close = object ? '}' : ']';
  int id = -1;
  if (depth <= kKeptDepth) {
    id = static_cast<int>(nodes_.size());
    nodes_.push_back(Node{object, {}, {}});
  }
  ++pos_;
  skip_space();
  if (peek() == close) {
    ++pos_;
    return {id, line};
  }
  while (pos_ < text_.size()) {
    skip_space();
    std::string key;
    if (object) {
      key = string_token();
      skip_space();
      ++pos_;  // ':'
    }
    const Loc child = value(depth + 1);
    if (id >= 0) {
      Node& n = nodes_[static_cast<std::size_t>(id)];
      if (object) n.keys.push_back(std::move(key));
      n.children.push_back(child);
    }
    skip_space();
    const char next = peek();
    ++pos_;
    if (next != ',') break;
  }
  return {id, line};
}

}  // namespace foldkit::io::detail
