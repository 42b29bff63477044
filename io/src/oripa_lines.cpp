// ORIPA's files (drawn_lines.hpp): the plain `.cp` line format, one record `TYPE X1 Y1 X2 Y2`
// per line, and `.opx`, its XML (java.beans.XMLEncoder) of line proxies.
#include <cmath>
#include <cstring>
#include <functional>
#include <optional>
#include <string>

#include <tinyxml2.h>

#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/drawn_lines.hpp"
#include "foldkit/io/number_format.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/io/xml_reader.hpp"
#include "text_lines.hpp"

namespace foldkit::io {

namespace {

// ORIPA's line types, in both of its formats: 0 auxiliary (skipped), 1 border (its cut line),
// 2 mountain, 3 valley. Empty for an auxiliary line; false for any other type.
bool line_kind(double type, std::optional<LineKind>& kind) {
  kind.reset();
  if (type == 0.0) return true;
  if (type == 1.0) kind = LineKind::Border;
  else if (type == 2.0) kind = LineKind::Mountain;
  else if (type == 3.0) kind = LineKind::Valley;
  return kind.has_value();
}

const char* kTypes = "none of 0 (auxiliary), 1 (border), 2 (mountain), 3 (valley)";

}  // namespace

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
    if (detail::blank(record)) continue;
    const NumberList v = parse_numbers(record);
    if (!v.error.empty()) throw ParseError(name, number, v.error);
    if (v.values.size() != 5) throw ParseError(name, number, "a record is TYPE X1 Y1 X2 Y2, five numbers; this has " + std::to_string(v.values.size()));
    std::optional<LineKind> kind;
    if (!line_kind(v.values[0], kind)) throw ParseError(name, number, "line type " + format_number(v.values[0]) + " is " + kTypes);
    if (!kind) continue;  // an auxiliary line: not part of the sheet
    DrawnLine l;
    l.kind = *kind;
    l.a = {v.values[1], v.values[2]};
    l.b = {v.values[3], v.values[4]};
    l.line = number;
    lines.push_back(l);
  }
  return lines;
}

std::vector<DrawnLine> parse_opx_lines(const std::string& text, const std::string& name) {
  const detail::XmlInput in(text, name);
  std::vector<DrawnLine> lines;
  // Every <object class="oripa.OriLineProxy">, wherever the encoder nested it; XMLEncoder leaves
  // out properties at their default (0), so a missing one is 0.
  const std::function<void(const tinyxml2::XMLElement&)> walk = [&](const tinyxml2::XMLElement& e) {
    const char* cls = e.Attribute("class");
    if (std::strcmp(e.Name(), "object") == 0 && cls && std::strcmp(cls, "oripa.OriLineProxy") == 0) {
      double type = 0, x0 = 0, y0 = 0, x1 = 0, y1 = 0;
      for (const tinyxml2::XMLElement* p = e.FirstChildElement("void"); p; p = p->NextSiblingElement("void")) {
        const char* property = p->Attribute("property");
        const tinyxml2::XMLElement* value = p->FirstChildElement();
        if (!property || !value) continue;
        const std::string which(property);
        double* into = which == "type" ? &type : which == "x0" ? &x0 : which == "y0" ? &y0 : which == "x1" ? &x1 : which == "y1" ? &y1 : nullptr;
        if (into) *into = in.number(*value);
      }
      std::optional<LineKind> kind;
      if (!line_kind(type, kind)) in.fail(e, "line type " + format_number(type) + " is " + kTypes);
      if (kind) lines.push_back({{x0, y0}, {x1, y1}, *kind, std::nullopt, in.line(e)});
      return;
    }
    for (const tinyxml2::XMLElement* c = e.FirstChildElement(); c; c = c->NextSiblingElement()) walk(*c);
  };
  walk(in.root("java"));
  return lines;
}

PatternFile read_opx_pattern(const std::string& path, const geometry::BuildOptions& options) {
  LineImportOptions o;
  o.build = options;
  return pattern_from_lines(parse_opx_lines(read_file(path), path), path, o);
}

PatternFile read_cp_pattern(const std::string& path, const geometry::BuildOptions& options) {
  LineImportOptions o;
  o.build = options;
  return pattern_from_lines(parse_cp_lines(read_file(path), path), path, o);
}

}  // namespace foldkit::io
