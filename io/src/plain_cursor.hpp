#pragma once
// A walk through XML text in the one plain shape foldkit writes, for the readers that skip the XML
// parser on foldkit's own large files (cmml_plain.cpp, pmml_plain.cpp). Private to foldkit::io.
// It only recognises; it never reports an error: a reader that meets anything else declines, and
// the XML reading decides (and reports any error at its line).
#include <string_view>

namespace foldkit::io::detail {

// XML white space but the carriage return (whose line counting is left to the XML reader).
inline bool plain_space(char c) { return c == ' ' || c == '\t' || c == '\n'; }

// The characters a number written by foldkit uses; nothing that could be markup, an entity or
// text that is not ASCII.
inline bool number_char(char c) { return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.' || c == 'e' || c == 'E'; }

// A list of numbers: their characters and the blanks between them (no line break).
inline bool number_list_char(char c) { return number_char(c) || c == ' ' || c == '\t'; }

// A walk through a text that counts its lines.
class PlainCursor {
 public:
  PlainCursor(std::string_view text, int line) : text_(text), line_(line) {}

  bool done() const { return at_ == text_.size(); }
  int line() const { return line_; }
  void skip_space() {
    for (; at_ < text_.size() && plain_space(text_[at_]); ++at_)
      if (text_[at_] == '\n') ++line_;
  }
  // Whether the text continues with `literal` (nothing consumed).
  bool at(std::string_view literal) const { return text_.compare(at_, literal.size(), literal) == 0; }
  // Consumes `literal` when the text continues with it.
  bool take(std::string_view literal) {
    if (!at(literal)) return false;
    at_ += literal.size();
    return true;
  }
  // <TAG>TEXT</TAG>, white space before it, TEXT of characters `allowed` accepts only: TEXT
  // (perhaps empty), with `found` false when the element is not there in that shape.
  template <class Allowed>
  std::string_view leaf(std::string_view open, std::string_view close, Allowed allowed, bool& found) {
    skip_space();
    found = false;
    if (!take(open)) return {};
    const std::size_t begin = at_;
    while (at_ < text_.size() && allowed(text_[at_])) ++at_;
    const std::string_view text = text_.substr(begin, at_ - begin);
    found = take(close);
    return text;
  }
  // <TAG>TOKEN</TAG> of number characters, not empty; empty when it is not there in that shape.
  std::string_view leaf(std::string_view open, std::string_view close) {
    bool found = false;
    const std::string_view token = leaf(open, close, number_char, found);
    return found ? token : std::string_view();
  }

 private:
  std::string_view text_;
  std::size_t at_ = 0;
  int line_;
};

}  // namespace foldkit::io::detail
