#include "foldkit/simulation/snapshot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

namespace foldkit::simulation {
namespace {

struct Drawn {
  std::array<Eigen::Vector2d, 3> corners;
  double depth;
  bool marked;
  double facing = 1.0;  // |cos| of the angle between the triangle's normal and the view
};

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '&': out += "&amp;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string grey(double shade, bool marked) {
  char buf[16];
  const int v = static_cast<int>(std::lround(90 + 150 * std::clamp(shade, 0.0, 1.0)));
  if (marked) std::snprintf(buf, sizeof buf, "#%02x%02x%02x", 200 + v / 5, v / 3, v / 3);
  else std::snprintf(buf, sizeof buf, "#%02x%02x%02x", v * 4 / 5, v * 9 / 10, v);
  return buf;
}

}  // namespace

std::string snapshot_svg(const geometry::CreasePattern& pattern, const std::vector<Eigen::Isometry3d>& poses,
                         const SnapshotOptions& options) {
  if (poses.size() != pattern.actors().size()) throw std::invalid_argument("snapshot_svg: one pose per actor expected");
  const Eigen::Matrix3d view = (Eigen::AngleAxisd(-(M_PI / 2 - options.elevation), Eigen::Vector3d::UnitX()) *
                                Eigen::AngleAxisd(options.azimuth, Eigen::Vector3d::UnitZ()))
                                   .toRotationMatrix();
  const std::set<int> marked(options.marked.begin(), options.marked.end());
  std::vector<Drawn> drawn;
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  double near = -std::numeric_limits<double>::infinity(), far = -near;
  for (std::size_t a = 0; a < pattern.actors().size(); ++a)
    for (const auto& t : pattern.actors()[a].triangles) {
      Drawn d{{}, 0.0, marked.count(static_cast<int>(a)) > 0};
      d.facing = std::abs((view * poses[a].linear()).col(2).z());
      for (int k = 0; k < 3; ++k) {
        const geometry::Vec2& v = pattern.vertices()[t.v[k]];
        const Eigen::Vector3d p = view * (poses[a] * Eigen::Vector3d(v.x(), v.y(), 0.0));
        d.corners[k] = {p.x(), -p.y()};  // SVG's y runs down
        d.depth += p.z() / 3.0;
        lo = lo.cwiseMin(d.corners[k]);
        hi = hi.cwiseMax(d.corners[k]);
      }
      near = std::max(near, d.depth);
      far = std::min(far, d.depth);
      drawn.push_back(d);
    }
  // Painter's algorithm: farthest first; ties keep pattern order so the output is stable.
  std::stable_sort(drawn.begin(), drawn.end(), [](const Drawn& x, const Drawn& y) { return x.depth < y.depth; });
  const Eigen::Vector2d extent = (hi - lo).cwiseMax(1e-300);
  const double scale = (options.size - 40.0) / std::max(extent.x(), extent.y());
  const double width = extent.x() * scale + 40.0, height = extent.y() * scale + 40.0 + (options.caption.empty() ? 0 : 20);
  std::ostringstream svg;
  svg.setf(std::ios::fixed);
  svg.precision(2);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height << "\" viewBox=\"0 0 "
      << width << ' ' << height << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  const double span = near > far ? near - far : 1.0;
  for (const Drawn& d : drawn) {
    svg << "<polygon points=\"";
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d p = (d.corners[k] - lo) * scale + Eigen::Vector2d(20, 20);
      svg << (k ? " " : "") << p.x() << ',' << p.y();
    }
    svg << "\" fill=\"" << grey(0.55 * (d.depth - far) / span + 0.45 * d.facing, d.marked) << "\" stroke=\"#222\" stroke-width=\"0.6\" stroke-linejoin=\"round\"/>\n";
  }
  if (!options.caption.empty())
    svg << "<text x=\"20\" y=\"" << height - 10 << "\" font-family=\"sans-serif\" font-size=\"14\">" << escape(options.caption)
        << "</text>\n";
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace foldkit::simulation
