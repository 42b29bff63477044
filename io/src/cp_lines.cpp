// ORIPA's plain `.cp` line format (drawn_lines.hpp): one record `TYPE X1 Y1 X2 Y2` per line.
#include <cmath>
#include <string>

#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/drawn_lines.hpp"
#include "foldkit/io/number_format.hpp"
#include "foldkit/io/parse_error.hpp"

namespace foldkit::io {

std::vector<DrawnLine> parse_cp_lines(const std::string& text, const std::string& name) {
  std::vector<DrawnLine> lines;
  int number = 0;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    ++number;
    const std::string record = text.substr(begin, end - begin);
    begin = end + 1;
    if (record.find_first_not_of(" \t\r") == std::string::npos) continue;
    const NumberList v = parse_numbers(record);
    if (!v.error.empty()) throw ParseError(name, number, v.error);
    if (v.values.size() != 5) throw ParseError(name, number, "a record is TYPE X1 Y1 X2 Y2, five numbers; this has " + std::to_string(v.values.size()));
    const double type = v.values[0];
    if (type == 0.0) continue;  // an auxiliary line: not part of the sheet
    DrawnLine l;
    if (type == 1.0) l.kind = LineKind::Border;
    else if (type == 2.0) l.kind = LineKind::Mountain;
    else if (type == 3.0) l.kind = LineKind::Valley;
    else throw ParseError(name, number, "line type " + format_number(type) + " is none of 0 (auxiliary), 1 (border), 2 (mountain), 3 (valley)");
    l.a = {v.values[1], v.values[2]};
    l.b = {v.values[3], v.values[4]};
    l.line = number;
    lines.push_back(l);
  }
  return lines;
}

PatternFile read_cp_pattern(const std::string& path, const geometry::BuildOptions& options) {
  LineImportOptions o;
  o.build = options;
  return pattern_from_lines(parse_cp_lines(read_file(path), path), path, o);
}

}  // namespace foldkit::io
