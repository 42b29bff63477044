// Planar chain files in (one "x y" per line), chain frames out as CSV and JSON.
#include "foldkit/io/chain_file.hpp"

#include <algorithm>
#include <string>

#include "foldkit/io/number_format.hpp"
#include "foldkit/io/parse_error.hpp"

namespace foldkit::io {

Frame2 parse_chain_points(const std::string& text, const std::string& file) {
  Frame2 points;
  std::size_t pos = 0;
  int line = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string content = text.substr(pos, end - pos);
    pos = end + 1;
    ++line;
    const std::size_t hash = content.find('#');
    if (hash != std::string::npos) content.erase(hash);
    if (content.find_first_not_of(" \t\r") == std::string::npos) continue;
    const NumberList numbers = parse_numbers(content);
    if (!numbers.error.empty()) throw ParseError(file, line, numbers.error);
    if (numbers.values.size() != 2)
      throw ParseError(file, line, "expected two numbers 'x y', found " + std::to_string(numbers.values.size()));
    points.emplace_back(numbers.values[0], numbers.values[1]);
  }
  if (points.empty()) throw ParseError(file, std::max(line, 1), "no points (one 'x y' per line)");
  return points;
}

std::string frames_csv(const std::vector<Frame2>& frames) {
  std::string out = "frame,vertex,x,y\n";
  for (std::size_t f = 0; f < frames.size(); ++f)
    for (std::size_t v = 0; v < frames[f].size(); ++v)
      out += std::to_string(f) + ',' + std::to_string(v) + ',' + format_number(frames[f][v].x()) + ',' +
             format_number(frames[f][v].y()) + '\n';
  return out;
}

std::string frames_json(const std::vector<Frame2>& frames, bool closed) {
  std::string out = std::string("{\"closed\": ") + (closed ? "true" : "false") + ", \"frames\": [";
  for (std::size_t f = 0; f < frames.size(); ++f) {
    out += f == 0 ? "\n  [" : ",\n  [";
    for (std::size_t v = 0; v < frames[f].size(); ++v)
      out += (v == 0 ? "[" : ", [") + format_number(frames[f][v].x()) + ", " + format_number(frames[f][v].y()) + "]";
    out += "]";
  }
  out += "\n]}\n";
  return out;
}

}  // namespace foldkit::io
