// The FOLD importer cuts each face into triangles; a corner that is straight to within the
// pattern builder's merge tolerance must not become the tip of a triangle the builder then calls
// degenerate. Oracles: the shoelace area of the drawn polygon, and the builder's own
// definition of a degenerate triangle (height over its longest side within the tolerance).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "foldkit/io/fold_format.hpp"
#include "foldkit/io/parse_error.hpp"

namespace foldkit::io {
namespace {

using geometry::CreasePattern;
using geometry::Vec2;
using json = nlohmann::json;

// A FOLD sheet of one face, the polygon `ring` (counter-clockwise), every side a boundary edge.
std::string one_face(const std::vector<Vec2>& ring) {
  json doc;
  doc["file_spec"] = 1.2;
  json coords = json::array(), face = json::array(), edges = json::array(), letters = json::array();
  for (std::size_t i = 0; i < ring.size(); ++i) {
    coords.push_back({ring[i].x(), ring[i].y()});
    face.push_back(i);
    edges.push_back({i, (i + 1) % ring.size()});
    letters.push_back("B");
  }
  doc["vertices_coords"] = coords;
  doc["faces_vertices"] = json::array({face});
  doc["edges_vertices"] = edges;
  doc["edges_assignment"] = letters;
  return doc.dump();
}

double shoelace(const std::vector<Vec2>& ring) {
  double twice = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2& a = ring[i];
    const Vec2& b = ring[(i + 1) % ring.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * twice;
}

struct Measured {
  double area = 0.0;
  double lowest_height = 1e300;  // of any triangle over its longest side
};

Measured measure(const CreasePattern& p) {
  Measured m;
  for (const auto& actor : p.actors())
    for (const auto& t : actor.triangles) {
      const Vec2 a = p.vertices()[t.v[0]], b = p.vertices()[t.v[1]], c = p.vertices()[t.v[2]];
      const double twice = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
      const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
      m.area += 0.5 * twice;
      m.lowest_height = std::min(m.lowest_height, std::abs(twice) / longest);
    }
  return m;
}

// The fuzz find's shape: a square whose top side has a corner 1e-10 above it (under the default
// merge tolerance, 1e-9 of the diagonal, and far over the clipper's own 1e-12 of the area).
TEST(FoldTriangulation, CornerStraightWithinTheToleranceIsNoEarTip) {
  const std::vector<Vec2> ring{{0, 0}, {1, 0}, {1, 1}, {0.5, 1 + 1e-10}, {0, 1}};
  const FoldImport in = parse_fold(one_face(ring), "square.fold");
  const Measured m = measure(in.pattern);
  EXPECT_NEAR(m.area, shoelace(ring), 1e-12);
  EXPECT_GT(m.lowest_height, 1e-3);
  EXPECT_EQ(in.pattern.actors()[0].triangles.size(), ring.size() - 2);
}

// Random star-shaped polygons whose sides carry extra corners nudged off them by less than the
// tolerance, several on a side, some sides in a row: every face imports, covers the polygon's
// area, and no triangle is as thin as the builder's tolerance.
TEST(FoldTriangulation, RandomPolygonsWithNearlyStraightCornersImport) {
  std::mt19937 rng(20261126);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  constexpr double kPiD = 3.14159265358979323846;
  for (int trial = 0; trial < 300; ++trial) {
    // Corners around the origin, no two more than 0.9 pi apart as seen from it: star-shaped
    // about the origin, so simple.
    const int corners = 4 + static_cast<int>(unit(rng) * 10);
    std::vector<Vec2> hull;
    for (int i = 0; i < corners; ++i) {
      const double turn = (i + 0.8 * unit(rng)) / corners;
      const double r = 0.3 + 0.7 * unit(rng);
      hull.emplace_back(r * std::cos(2 * kPiD * turn), r * std::sin(2 * kPiD * turn));
    }
    std::vector<Vec2> ring;
    const double nudge = 1e-10;  // the diagonal is at most 2.9: the tolerance is at least 1e-9
    for (std::size_t i = 0; i < hull.size(); ++i) {
      const Vec2& a = hull[i];
      const Vec2& b = hull[(i + 1) % hull.size()];
      ring.push_back(a);
      const int extra = static_cast<int>(unit(rng) * 4);
      const Vec2 normal = Vec2(a.y() - b.y(), b.x() - a.x()).normalized();
      for (int k = 1; k <= extra; ++k)
        ring.push_back(a + (b - a) * (k / (extra + 1.0)) + normal * nudge * (2 * unit(rng) - 1));
    }
    SCOPED_TRACE("trial " + std::to_string(trial) + ", " + std::to_string(ring.size()) + " corners");
    try {
      const FoldImport in = parse_fold(one_face(ring), "random.fold");
      const Measured m = measure(in.pattern);
      EXPECT_NEAR(m.area, shoelace(ring), 1e-9);
      EXPECT_GT(m.lowest_height, 1e-8);
    } catch (const ParseError& e) {
      ADD_FAILURE() << e.what();
    }
  }
}

}  // namespace
}  // namespace foldkit::io
