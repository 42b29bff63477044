#include "foldkit/io/svg.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <tinyxml2.h>

#include "foldkit/io/number_format.hpp"
#include "foldkit/io/xml_reader.hpp"

namespace foldkit::io {
namespace {

using geometry::Assignment;

// Mountain/valley of a joint: by the sign of its angle when a state is given.
Assignment drawn_as(const geometry::CreasePattern& p, std::size_t j, const geometry::FoldState* state) {
  if (!state) return p.joints()[j].assignment;
  const double a = state->angles[static_cast<Eigen::Index>(j)];
  return a > 0 ? Assignment::Mountain : a < 0 ? Assignment::Valley : Assignment::Flat;
}

// Origami Simulator's colours (drawn_lines.hpp reads them back): flat and unassigned creases are
// its undriven hinges (magenta).
const char* style(Assignment a) {
  switch (a) {
    case Assignment::Mountain: return "stroke=\"#ff0000\" stroke-width=\"2\"";
    case Assignment::Valley: return "stroke=\"#0000ff\" stroke-width=\"2\" stroke-dasharray=\"8 4\"";
    case Assignment::Flat:
    case Assignment::Unassigned: break;
  }
  return "stroke=\"#ff00ff\" stroke-width=\"1.5\" stroke-dasharray=\"2 3\"";
}

// With a state, a folded crease's target as Origami Simulator reads it: opacity × 180°.
std::string target_opacity(const geometry::FoldState* state, std::size_t j) {
  if (!state) return "";
  const double a = std::abs(state->angles[static_cast<Eigen::Index>(j)]);
  return a > 0 ? " stroke-opacity=\"" + format_number(std::min(1.0, a / M_PI)) + "\"" : "";
}

}  // namespace

std::string write_svg(const geometry::CreasePattern& pattern, const SvgOptions& options) {
  Eigen::AlignedBox2d box;
  for (const auto& v : pattern.vertices()) box.extend(v);
  const double extent = std::max(box.sizes().x(), box.sizes().y());
  const double s = options.pixels_per_unit > 0 ? options.pixels_per_unit : 800.0 / extent, margin = 20.0;
  // SVG's y axis points down; flip so that the pattern reads as in its own coordinates.
  auto X = [&](const geometry::Vec2& p) { return format_number(margin + (p.x() - box.min().x()) * s); };
  auto Y = [&](const geometry::Vec2& p) { return format_number(margin + (box.max().y() - p.y()) * s); };
  const auto& V = pattern.vertices();

  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << format_number(box.sizes().x() * s + 2 * margin)
      << "\" height=\"" << format_number(box.sizes().y() * s + 2 * margin) << "\" viewBox=\"0 0 "
      << format_number(box.sizes().x() * s + 2 * margin) << ' ' << format_number(box.sizes().y() * s + 2 * margin) << "\">\n"
      << "  <title>" << detail::escape_xml(pattern.title()) << "</title>\n"
      << "  <g id=\"facets\" fill=\"#f4f1e8\" stroke=\"none\">\n";  // filled, not drawn lines
  for (const auto& a : pattern.actors())
    for (const auto& t : a.triangles)
      out << "    <polygon data-actor=\"" << a.id << "\" points=\"" << X(V[t.v[0]]) << ',' << Y(V[t.v[0]]) << ' '
          << X(V[t.v[1]]) << ',' << Y(V[t.v[1]]) << ' ' << X(V[t.v[2]]) << ',' << Y(V[t.v[2]]) << "\"/>\n";
  out << "  </g>\n  <g id=\"boundary\" stroke=\"#000000\" stroke-width=\"2\" stroke-linecap=\"round\">\n";
  for (const auto& [a, b] : pattern.boundary_edges())
    out << "    <line x1=\"" << X(V[a]) << "\" y1=\"" << Y(V[a]) << "\" x2=\"" << X(V[b]) << "\" y2=\"" << Y(V[b]) << "\"/>\n";
  out << "  </g>\n  <g id=\"creases\" stroke-linecap=\"round\">\n";
  for (std::size_t j = 0; j < pattern.joints().size(); ++j) {
    const auto& joint = pattern.joints()[j];
    const auto &p = V[joint.v[0]], &q = V[joint.v[1]];
    out << "    <line data-joint=\"" << joint.id << "\" " << style(drawn_as(pattern, j, options.state))
        << target_opacity(options.state, j) << " x1=\"" << X(p)
        << "\" y1=\"" << Y(p) << "\" x2=\"" << X(q) << "\" y2=\"" << Y(q) << "\"/>\n";
  }
  out << "  </g>\n";
  if (options.joint_ids) {
    out << "  <g id=\"joint-ids\" font-family=\"sans-serif\" font-size=\"12\" text-anchor=\"middle\" fill=\"#333333\">\n";
    for (const auto& joint : pattern.joints()) {
      const geometry::Vec2 mid = 0.5 * (V[joint.v[0]] + V[joint.v[1]]);
      out << "    <text x=\"" << X(mid) << "\" y=\"" << Y(mid) << "\" dy=\"-3\">" << joint.id << "</text>\n";
    }
    out << "  </g>\n";
  }
  out << "</svg>\n";
  return out.str();
}

}  // namespace foldkit::io
