// The <Fold> elements of a large CMML read without an XML parser, when they are in the plain shape
// foldkit writes. A Miura 40×40 goal is 308,000 of them (49 MB); tinyxml2's document, its checks
// and the strings of XmlInput took 1.0 s of `foldkit plan`'s 5.6 s. Anything out of that shape,
// any number the checks of read_fold() would refuse, declines, and the slice is read by XML as
// before: errors are reported as they were, at their lines.
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "foldkit/io/cmml.hpp"
#include "foldkit/io/number_format.hpp"

namespace foldkit::io::detail {
namespace {

// XML white space but the carriage return (whose line counting is left to the XML reader).
bool space(char c) { return c == ' ' || c == '\t' || c == '\n'; }

// The characters a number written by foldkit uses; nothing that could be markup, an entity or
// text that is not ASCII.
bool number_char(char c) { return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.' || c == 'e' || c == 'E'; }

// A walk through a slice's text that counts its lines.
class Cursor {
 public:
  Cursor(std::string_view text, int line) : text_(text), line_(line) {}

  bool done() const { return at_ == text_.size(); }
  int line() const { return line_; }
  void skip_space() {
    for (; at_ < text_.size() && space(text_[at_]); ++at_)
      if (text_[at_] == '\n') ++line_;
  }
  // Consumes `literal` when the text continues with it.
  bool take(std::string_view literal) {
    if (text_.compare(at_, literal.size(), literal) != 0) return false;
    at_ += literal.size();
    return true;
  }
  // <TAG>TOKEN</TAG>, white space before it: TOKEN (number characters only, not empty), or empty.
  std::string_view leaf(std::string_view open, std::string_view close) {
    skip_space();
    if (!take(open)) return {};
    const std::size_t begin = at_;
    while (at_ < text_.size() && number_char(text_[at_])) ++at_;
    const std::string_view token = text_.substr(begin, at_ - begin);
    if (token.empty() || !take(close)) return {};
    return token;
  }

 private:
  std::string_view text_;
  std::size_t at_ = 0;
  int line_;
};

// The one number of a token as XmlInput::numbers() reads it (the same parse_numbers); nothing
// when it is not exactly one finite number.
bool one_number(std::string_view token, double& value) {
  const NumberList list = parse_numbers(token);
  if (!list.error.empty() || list.values.size() != 1) return false;
  value = list.values[0];
  return true;
}

// One <Fold> at the cursor (after its white space) with the checks of cmml.cpp's read_fold().
bool plain_fold(Cursor& in, std::pair<int, geometry::FoldCommand>& out) {
  in.skip_space();
  out.second.line = in.line();
  if (!in.take("<Fold>")) return false;
  const std::optional<int> event = parse_int(in.leaf("<EventNumber>", "</EventNumber>"));
  const std::optional<int> id = parse_int(in.leaf("<ID>", "</ID>"));
  double degrees = 0.0, speed = 0.0;
  if (!event || *event < 0 || !id || !one_number(in.leaf("<FoldAngle>", "</FoldAngle>"), degrees) ||
      !one_number(in.leaf("<Velocity>", "</Velocity>"), speed))
    return false;
  in.skip_space();
  if (!in.take("</Fold>")) return false;
  if (degrees < -180.0 || degrees > 180.0 || !(speed > 0.0)) return false;
  out.first = *event;
  out.second.joint_id = *id;
  out.second.angle = degrees_to_radians(degrees);
  out.second.speed = degrees_to_radians(speed);
  return out.second.speed > 0.0;
}

}  // namespace

bool read_plain_folds(std::string_view body, int first_line, std::vector<std::pair<int, geometry::FoldCommand>>& folds) {
  const std::size_t before = folds.size();
  Cursor in(body, first_line);
  for (in.skip_space(); !in.done(); in.skip_space()) {
    std::pair<int, geometry::FoldCommand> fold;
    if (!plain_fold(in, fold)) {
      folds.resize(before);
      return false;
    }
    folds.push_back(fold);
  }
  return true;
}

}  // namespace foldkit::io::detail
