// Chain files in, frames and CMML out, for the planar Carpenter's rule.
#include <algorithm>
#include <cmath>
#include <string>

#include "foldkit/io/number_format.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/folding/carpenter.hpp"

namespace foldkit::folding {

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
    const io::NumberList numbers = io::parse_numbers(content);
    if (!numbers.error.empty()) throw io::ParseError(file, line, numbers.error);
    if (numbers.values.size() != 2)
      throw io::ParseError(file, line, "expected two numbers 'x y', found " + std::to_string(numbers.values.size()));
    points.emplace_back(numbers.values[0], numbers.values[1]);
  }
  if (points.empty()) throw io::ParseError(file, std::max(line, 1), "no points (one 'x y' per line)");
  return points;
}

std::string frames_csv(const std::vector<Frame2>& frames) {
  std::string out = "frame,vertex,x,y\n";
  for (std::size_t f = 0; f < frames.size(); ++f)
    for (std::size_t v = 0; v < frames[f].size(); ++v)
      out += std::to_string(f) + ',' + std::to_string(v) + ',' + io::format_number(frames[f][v].x()) + ',' +
             io::format_number(frames[f][v].y()) + '\n';
  return out;
}

std::string frames_json(const std::vector<Frame2>& frames, bool closed) {
  std::string out = std::string("{\"closed\": ") + (closed ? "true" : "false") + ", \"frames\": [";
  for (std::size_t f = 0; f < frames.size(); ++f) {
    out += f == 0 ? "\n  [" : ",\n  [";
    for (std::size_t v = 0; v < frames[f].size(); ++v)
      out += (v == 0 ? "[" : ", [") + io::format_number(frames[f][v].x()) + ", " + io::format_number(frames[f][v].y()) + "]";
    out += "]";
  }
  out += "\n]}\n";
  return out;
}

geometry::FoldSequence turning_angle_sequence(const std::vector<Frame2>& frames, bool closed, std::string title) {
  // Within an event every joint arrives together, the fastest turning at 1 rad/s; CMML needs a
  // positive velocity even for a joint that does not move.
  constexpr double kFastest = 1.0, kSlowest = 1e-6;
  geometry::FoldSequence sequence;
  sequence.title = std::move(title);
  std::vector<double> previous;
  for (std::size_t f = 0; f < frames.size(); ++f) {
    const std::vector<double> angles = turning_angles(frames[f], closed);
    if (previous.empty()) previous.assign(angles.size(), 0.0);  // CMML starts from flat
    double largest = 0.0;
    for (std::size_t j = 0; j < angles.size(); ++j) largest = std::max(largest, std::abs(angles[j] - previous[j]));
    geometry::FoldEvent event;
    event.number = static_cast<int>(f);
    const int first_joint = closed ? 0 : 1;
    for (std::size_t j = 0; j < angles.size(); ++j) {
      geometry::FoldCommand c;
      c.joint_id = first_joint + static_cast<int>(j);
      c.angle = angles[j];
      const double share = largest > 0.0 ? std::abs(angles[j] - previous[j]) / largest : 1.0;
      c.velocity = std::max(kFastest * share, kSlowest);
      event.folds.push_back(c);
    }
    sequence.events.push_back(std::move(event));
    previous = angles;
  }
  return sequence;
}

}  // namespace foldkit::folding
