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
#include "plain_cursor.hpp"

namespace foldkit::io::detail {
namespace {

// The one number of a token as XmlInput::numbers() reads it (the same parse_numbers); nothing
// when it is not exactly one finite number.
bool one_number(std::string_view token, double& value) {
  const NumberList list = parse_numbers(token);
  if (!list.error.empty() || list.values.size() != 1) return false;
  value = list.values[0];
  return true;
}

// One <Fold> at the cursor (after its white space) with the checks of cmml.cpp's read_fold().
bool plain_fold(PlainCursor& in, std::pair<int, geometry::FoldCommand>& out) {
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
  PlainCursor in(body, first_line);
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
