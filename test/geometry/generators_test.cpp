// Generators are checked against facts that do not come from their code: closed-form counts,
// areas, Euler's formula, and the flat-foldability and rigid-folding conditions of origami.
#include "foldkit/geometry/generators.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <Eigen/Geometry>
#include <boost/graph/connected_components.hpp>

#include "foldkit/geometry/crease_pattern.hpp"

namespace foldkit::geometry {
namespace {

namespace gen = generators;

constexpr double kPi = 3.14159265358979323846;
constexpr double kTol = 1e-9;

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

CreasePattern build(const PatternSpec& spec) {
  BuildResult r = build_pattern(spec);
  for (const Diagnostic& d : r.diagnostics) ADD_FAILURE() << spec.title << ": " << format(d, spec.title);
  if (!r.pattern) throw std::runtime_error("build_pattern rejected " + spec.title);
  return std::move(*r.pattern);
}

double triangle_area(const CreasePattern& p) {
  double area = 0.0;
  for (const Actor& a : p.actors())
    for (const Triangle& t : a.triangles) {
      const Vec2 &p0 = p.vertices()[t.v[0]], &p1 = p.vertices()[t.v[1]], &p2 = p.vertices()[t.v[2]];
      area += std::abs(cross2(p1 - p0, p2 - p0)) / 2;
    }
  return area;
}

bool facet_graph_connected(const CreasePattern& p) {
  const FacetGraph& g = p.facet_graph();
  std::vector<int> component(boost::num_vertices(g));
  return boost::connected_components(g, component.data()) == 1;
}

bool ids_are_consecutive(const CreasePattern& p) {
  for (std::size_t i = 0; i < p.actors().size(); ++i)
    if (p.actors()[i].id != static_cast<int>(i) + 1) return false;
  for (std::size_t i = 0; i < p.joints().size(); ++i)
    if (p.joints()[i].id != static_cast<int>(i) + 1) return false;
  return true;
}

double sector_sum(const VertexStar& s) {
  double sum = 0.0;
  for (double a : s.sectors) sum += a;
  return sum;
}

double alternating_sum(const VertexStar& s) {
  double sum = 0.0;
  for (std::size_t k = 0; k < s.sectors.size(); ++k) sum += k % 2 == 0 ? s.sectors[k] : -s.sectors[k];
  return sum;
}

// What every generator owes: a clean build, the expected counts, the sheet's area, one piece,
// creases closing around every interior vertex, and Euler's formula for a disc-shaped sheet
// (each independent cycle of the facet graph circles exactly one interior vertex).
CreasePattern check_pattern(const PatternSpec& spec, std::size_t actors, std::size_t joints, std::size_t interior,
                            double area) {
  const CreasePattern p = build(spec);
  EXPECT_EQ(p.actors().size(), actors) << spec.title;
  EXPECT_EQ(p.joints().size(), joints) << spec.title;
  EXPECT_EQ(p.interior_vertices().size(), interior) << spec.title;
  EXPECT_NEAR(triangle_area(p), area, kTol * std::max(1.0, area)) << spec.title;
  EXPECT_TRUE(facet_graph_connected(p)) << spec.title;
  EXPECT_TRUE(ids_are_consecutive(p)) << spec.title;
  EXPECT_EQ(p.joints().size() + 1, p.actors().size() + p.interior_vertices().size()) << spec.title;
  for (const VertexStar& s : p.interior_vertices()) EXPECT_NEAR(sector_sum(s), 2 * kPi, kTol) << spec.title;
  return p;
}

void expect_kawasaki(const CreasePattern& p) {
  for (const VertexStar& s : p.interior_vertices()) {
    ASSERT_EQ(s.sectors.size() % 2, 0u) << p.title();
    EXPECT_NEAR(alternating_sum(s), 0.0, kTol) << p.title() << " at " << p.vertices()[s.vertex].transpose();
  }
}

std::vector<Assignment> star_assignments(const CreasePattern& p, const VertexStar& s) {
  std::vector<Assignment> out;
  for (int j : s.joints) out.push_back(p.joints()[j].assignment);
  return out;
}

void expect_maekawa(const CreasePattern& p) {
  for (const VertexStar& s : p.interior_vertices()) {
    const auto as = star_assignments(p, s);
    const auto m = std::count(as.begin(), as.end(), Assignment::Mountain);
    const auto v = std::count(as.begin(), as.end(), Assignment::Valley);
    ASSERT_EQ(static_cast<std::size_t>(m + v), as.size()) << "unassigned crease at " << p.vertices()[s.vertex].transpose();
    EXPECT_EQ(std::abs(m - v), 2) << p.title() << " at " << p.vertices()[s.vertex].transpose();
  }
}

// Sectors of the star starting at the crease with joint ID `first`.
std::vector<double> sectors_from(const CreasePattern& p, const VertexStar& s, int first) {
  const int start = *p.joint_index(first);
  const auto at = std::find(s.joints.begin(), s.joints.end(), start);
  EXPECT_NE(at, s.joints.end());
  std::vector<double> out(s.sectors.begin() + (at - s.joints.begin()), s.sectors.end());
  out.insert(out.end(), s.sectors.begin(), s.sectors.begin() + (at - s.joints.begin()));
  return out;
}

// ---------------------------------------------------------------------------------------------
// single_vertex

// The sheet is fanned from the vertex by its boundary: every boundary corner on the circle,
// no boundary edge seen from the vertex under more than π/2, and the fan's area the sheet's.
void check_single_vertex(const std::vector<double>& sectors, double radius) {
  const std::size_t n = sectors.size();
  const CreasePattern p = build(gen::single_vertex(sectors, radius));
  ASSERT_EQ(p.actors().size(), n);
  ASSERT_EQ(p.joints().size(), n);
  ASSERT_EQ(p.interior_vertices().size(), 1u);
  const VertexStar& star = p.interior_vertices()[0];
  EXPECT_LT(p.vertices()[star.vertex].norm(), kTol);
  ASSERT_EQ(star.sectors.size(), n);
  const std::vector<double> got = sectors_from(p, star, 1);
  for (std::size_t k = 0; k < n; ++k) EXPECT_NEAR(got[k], sectors[k], 1e-12) << "sector " << k << " of " << n;
  EXPECT_TRUE(facet_graph_connected(p));
  EXPECT_TRUE(ids_are_consecutive(p));

  double fan_area = 0.0;
  for (const auto& [a, b] : p.boundary_edges()) {
    const Vec2 &pa = p.vertices()[a], &pb = p.vertices()[b];
    EXPECT_NEAR(pa.norm(), radius, kTol * radius);
    EXPECT_LE(std::atan2(std::abs(cross2(pa, pb)), pa.dot(pb)), kPi / 2 + kTol);
    fan_area += std::abs(cross2(pa, pb)) / 2;
  }
  EXPECT_NEAR(triangle_area(p), fan_area, kTol * radius * radius);
  EXPECT_LE(fan_area, kPi * radius * radius);
}

TEST(SingleVertex, ReproducesGivenSectors) {
  check_single_vertex({kPi / 2, kPi / 2, kPi / 2, kPi / 2}, 1.0);
  check_single_vertex({0.6, 1.1, kPi - 0.6, kPi - 1.1}, 2.5);
  check_single_vertex(std::vector<double>(8, kPi / 4), 1.0);  // the paper's Fig. 2
  check_single_vertex({0.5, 0.5, 2 * kPi - 1.0}, 0.1);        // one sector wider than π
  check_single_vertex({kPi, kPi}, 1.0);
  check_single_vertex({1e-6, kPi - 1e-6, 1e-6, kPi - 1e-6}, 1.0);
}

TEST(SingleVertex, FlatFoldableDegreeFourSatisfiesKawasaki) {
  const CreasePattern p = build(gen::single_vertex({0.6, 1.1, kPi - 0.6, kPi - 1.1}));
  expect_kawasaki(p);
}

TEST(SingleVertex, RandomSectorsOfDegreeFourToSixtyFourBuildCleanly) {
  std::mt19937 rng(20100815);
  std::uniform_real_distribution<double> weight(0.05, 1.0);
  std::bernoulli_distribution sliver(0.2);
  constexpr double kSliver = 1e-6;
  int slivers = 0;
  for (int n = 4; n <= 64; ++n) {
    std::vector<double> sectors(n);
    std::vector<bool> thin(n);
    double total = 0.0;
    int thin_count = 0;
    for (int k = 0; k < n; ++k) {
      thin[k] = sliver(rng);
      sectors[k] = weight(rng);
      if (thin[k]) ++thin_count;
      else total += sectors[k];
    }
    if (thin_count == n) continue;
    for (int k = 0; k < n; ++k)
      sectors[k] = thin[k] ? kSliver : sectors[k] / total * (2 * kPi - thin_count * kSliver);
    slivers += thin_count;
    SCOPED_TRACE("degree " + std::to_string(n));
    check_single_vertex(sectors, 1.0 + n / 10.0);
  }
  EXPECT_GT(slivers, 50);
}

TEST(SingleVertex, PassesJointDefaults) {
  const CreasePattern p = build(gen::single_vertex({kPi / 2, kPi / 2, kPi}, 1.0, {2.5, 0.25}));
  for (const Joint& j : p.joints()) {
    EXPECT_EQ(j.spring, 2.5);
    EXPECT_EQ(j.damping, 0.25);
  }
}

// ---------------------------------------------------------------------------------------------
// strip, grid, circular_lattice

TEST(Strip, CountsAndArea) {
  for (int n : {1, 2, 7}) {
    const CreasePattern p = check_pattern(gen::strip(n, 0.5, 2.0), n, n - 1, 0, n * 0.5 * 2.0);
    for (const Joint& j : p.joints())
      EXPECT_EQ(std::abs(p.actors()[j.actors[0]].id - p.actors()[j.actors[1]].id), 1);  // a chain of panels
  }
}

TEST(Grid, CountsAreaAndRightAngles) {
  for (auto [rows, cols] : std::vector<std::pair<int, int>>{{1, 1}, {1, 4}, {2, 3}, {5, 5}, {4, 7}}) {
    const CreasePattern p = check_pattern(gen::grid(rows, cols, 0.5), rows * cols,
                                          rows * (cols - 1) + cols * (rows - 1), (rows - 1) * (cols - 1),
                                          rows * cols * 0.25);
    expect_kawasaki(p);
    for (const VertexStar& s : p.interior_vertices())
      for (double a : s.sectors) EXPECT_NEAR(a, kPi / 2, kTol);
  }
}

TEST(CircularLattice, CountsAndArea) {
  for (auto [rings, spokes] : std::vector<std::pair<int, int>>{{1, 3}, {1, 5}, {2, 6}, {3, 8}, {4, 7}}) {
    const double w = 0.75, outer = rings * w;
    // The sheet is the regular spokes-gon of circumradius rings·w.
    const double area = spokes / 2.0 * outer * outer * std::sin(2 * kPi / spokes);
    const CreasePattern p = check_pattern(gen::circular_lattice(rings, spokes, w), rings * spokes,
                                          spokes * (2 * rings - 1), 1 + (rings - 1) * spokes, area);
    for (const VertexStar& s : p.interior_vertices()) {
      const bool centre = p.vertices()[s.vertex].norm() < kTol;
      EXPECT_EQ(s.sectors.size(), centre ? static_cast<std::size_t>(spokes) : 4u);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// miura

// In a degree-4 vertex with sectors (γ, γ, π − γ, π − γ) the rigid folding mode has
// tan(ρ₁/2) = −cos γ·tan(ρ₀/2) (Tachi; shared/reference/NOTES.md): the crease between the two
// sectors of γ folds against the other three.
void expect_miura_rigid_mode(const CreasePattern& p, double angle) {
  for (const VertexStar& s : p.interior_vertices()) {
    const auto as = star_assignments(p, s);
    for (std::size_t k = 0; k < 4; ++k) {
      const bool between_acute =
          std::abs(s.sectors[(k + 3) % 4] - angle) < kTol && std::abs(s.sectors[k] - angle) < kTol;
      const auto same = std::count(as.begin(), as.end(), as[k]);
      EXPECT_EQ(same == 1, between_acute) << "crease " << k << " at " << p.vertices()[s.vertex].transpose();
    }
  }
}

TEST(Miura, CountsAreaAndVertexGeometry) {
  struct Case {
    int rows, cols;
    double a, b, angle;
  };
  for (const Case& c : {Case{1, 1, 1, 1, 1.0}, Case{2, 3, 1, 1, kPi / 3}, Case{4, 4, 1, 1, kPi / 3},
                        Case{3, 5, 1.5, 0.7, 0.3}, Case{5, 2, 0.2, 3.0, 1.4}, Case{3, 3, 1, 1, kPi / 2}}) {
    SCOPED_TRACE(std::to_string(c.rows) + "x" + std::to_string(c.cols) + " angle " + std::to_string(c.angle));
    const CreasePattern p =
        check_pattern(gen::miura(c.rows, c.cols, c.a, c.b, c.angle), c.rows * c.cols,
                      c.rows * (c.cols - 1) + c.cols * (c.rows - 1), (c.rows - 1) * (c.cols - 1), c.rows * c.cols * c.a * c.b);
    expect_kawasaki(p);
    expect_maekawa(p);
    for (const VertexStar& s : p.interior_vertices()) {
      ASSERT_EQ(s.sectors.size(), 4u);
      std::vector<double> sorted = s.sectors;
      std::sort(sorted.begin(), sorted.end());
      const std::vector<double> expected{c.angle, c.angle, kPi - c.angle, kPi - c.angle};
      for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(sorted[k], expected[k], kTol);
    }
    if (c.angle < kPi / 2) expect_miura_rigid_mode(p, c.angle);
  }
}

TEST(Miura, FortyByForty) {
  const CreasePattern p = check_pattern(gen::miura(40, 40), 1600, 3120, 39 * 39, 1600.0);
  expect_kawasaki(p);
  expect_maekawa(p);
}

// ---------------------------------------------------------------------------------------------
// waterbomb

TEST(Waterbomb, CountsAreaAndDegreeSixVertices) {
  for (auto [units, rows] : std::vector<std::pair<int, int>>{{1, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}}) {
    SCOPED_TRACE(std::to_string(units) + " units, " + std::to_string(rows) + " rows");
    // Interior vertices: x = 2..2u−2 even on even rows, x = 1..2u−1 odd on odd rows.
    const int interior = (rows - 1) / 2 * (units - 1) + rows / 2 * units;
    // Diagonals: 2u per band; horizontals: u on interior even rows, u + 1 on odd rows.
    const int joints = 2 * units * rows + (rows - 1) / 2 * units + rows / 2 * (units + 1);
    const CreasePattern p =
        check_pattern(gen::waterbomb(units, rows), rows * (2 * units + 1), joints, interior, 2.0 * units * rows);
    expect_kawasaki(p);
    expect_maekawa(p);
    for (const VertexStar& s : p.interior_vertices()) {
      ASSERT_EQ(s.sectors.size(), 6u);
      std::vector<double> sorted = s.sectors;
      std::sort(sorted.begin(), sorted.end());
      for (std::size_t k = 0; k < 6; ++k) EXPECT_NEAR(sorted[k], k < 4 ? kPi / 4 : kPi / 2, kTol);
    }
    for (const Joint& j : p.joints()) {
      const bool horizontal = std::abs(p.vertices()[j.v[0]].y() - p.vertices()[j.v[1]].y()) < kTol;
      EXPECT_EQ(j.assignment, horizontal ? Assignment::Valley : Assignment::Mountain);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// boat

TEST(Boat, ThreeFlatFoldableVerticesOnTheKeel) {
  for (auto [length, half_width, bow] : std::vector<std::tuple<double, double, double>>{{4.0, 1.0, 1.0}, {10.0, 1.5, 3.0}, {3.0, 2.0, 0.25}}) {
    const CreasePattern p = check_pattern(gen::boat(length, half_width, bow), 8, 10, 3, length * 2 * half_width);
    expect_kawasaki(p);
    std::vector<double> xs;
    for (const VertexStar& s : p.interior_vertices()) {
      EXPECT_EQ(s.sectors.size(), 4u);
      EXPECT_NEAR(p.vertices()[s.vertex].y(), 0.0, kTol);
      xs.push_back(p.vertices()[s.vertex].x());
    }
    std::sort(xs.begin(), xs.end());
    EXPECT_NEAR(xs[0], bow, kTol);
    EXPECT_NEAR(xs[1], length / 2, kTol);
    EXPECT_NEAR(xs[2], length - bow, kTol);
  }
}

// ---------------------------------------------------------------------------------------------
// cube_sheet

TEST(CubeSheet, NetsOfSixTilesHingedInARow) {
  for (int k : {1, 2, 8}) {
    const double tile = 0.5;
    const CreasePattern p = check_pattern(gen::cube_sheet(k, tile), 6 * k, 5 * k + (k - 1), 0, 6 * k * tile * tile);
    const FacetGraph& g = p.facet_graph();
    for (const Actor& a : p.actors()) {
      double area = 0.0;
      for (const Triangle& t : a.triangles)
        area += std::abs(cross2(p.vertices()[t.v[1]] - p.vertices()[t.v[0]], p.vertices()[t.v[2]] - p.vertices()[t.v[0]])) / 2;
      EXPECT_NEAR(area, tile * tile, kTol);
    }
    // A tree (Euler gave no cycles): the middle tile of each net carries the caps above and below.
    for (int n = 0; n < k; ++n) EXPECT_EQ(boost::degree(*p.actor_index(6 * n + 2), g), 4u);
  }
}

// The documented numbering (docs/GENERATORS.md), tile by tile and hinge by hinge, written out
// from the text: net n's row at x ∈ [3n, 3n+3]·t, its caps on the middle tile.
TEST(CubeSheet, TilesAndHingesWhereTheDocumentationPutsThem) {
  const double t = 0.5;
  const int k = 3;
  const CreasePattern p = build_or_throw(gen::cube_sheet(k, t));
  const auto box = [&](int id) {
    Eigen::AlignedBox2d b;
    for (const Triangle& tri : p.actors()[*p.actor_index(id)].triangles)
      for (int v : tri.v) b.extend(p.vertices()[v]);
    return b;
  };
  const auto expect_tile = [&](int id, double x0, double y0) {
    const Eigen::AlignedBox2d b = box(id);
    EXPECT_NEAR(b.min().x(), x0 * t, kTol) << id;
    EXPECT_NEAR(b.min().y(), y0 * t, kTol) << id;
    EXPECT_NEAR(b.max().x(), (x0 + 1) * t, kTol) << id;
    EXPECT_NEAR(b.max().y(), (y0 + 1) * t, kTol) << id;
  };
  // Joint `id` joins actors a and b along the segment (x0, y0)–(x1, y1), in tiles.
  const auto expect_joint = [&](int id, int a, int b, double x0, double y0, double x1, double y1, Assignment assignment) {
    const Joint* j = nullptr;
    for (const Joint& c : p.joints())
      if (c.id == id) j = &c;
    ASSERT_NE(j, nullptr) << id;
    std::array<int, 2> ids{p.actors()[j->actors[0]].id, p.actors()[j->actors[1]].id};
    std::sort(ids.begin(), ids.end());
    EXPECT_EQ(ids, (std::array<int, 2>{std::min(a, b), std::max(a, b)})) << id;
    Eigen::AlignedBox2d seg;
    seg.extend(p.vertices()[j->v[0]]).extend(p.vertices()[j->v[1]]);
    EXPECT_NEAR(seg.min().x(), std::min(x0, x1) * t, kTol) << id;
    EXPECT_NEAR(seg.max().x(), std::max(x0, x1) * t, kTol) << id;
    EXPECT_NEAR(seg.min().y(), std::min(y0, y1) * t, kTol) << id;
    EXPECT_NEAR(seg.max().y(), std::max(y0, y1) * t, kTol) << id;
    EXPECT_EQ(j->assignment, assignment) << id;
  };
  for (int n = 0; n < k; ++n) {
    const int a = 6 * n, x = 3 * n;
    expect_tile(a + 1, x, 0);       // first tile of the row
    expect_tile(a + 2, x + 1, 0);   // middle tile
    expect_tile(a + 3, x + 2, 0);   // last tile
    expect_tile(a + 4, x + 1, -2);  // far cap
    expect_tile(a + 5, x + 1, 1);   // cap above
    expect_tile(a + 6, x + 1, -1);  // cap below
    expect_joint(a + 1, a + 1, a + 2, x + 1, 0, x + 1, 1, Assignment::Valley);
    expect_joint(a + 2, a + 2, a + 3, x + 2, 0, x + 2, 1, Assignment::Valley);
    expect_joint(a + 3, a + 6, a + 4, x + 1, -1, x + 2, -1, Assignment::Valley);
    expect_joint(a + 4, a + 2, a + 5, x + 1, 1, x + 2, 1, Assignment::Valley);
    expect_joint(a + 5, a + 2, a + 6, x + 1, 0, x + 2, 0, Assignment::Valley);
    if (n + 1 < k) expect_joint(a + 6, a + 3, a + 7, x + 3, 0, x + 3, 1, Assignment::Unassigned);
  }
}

// ---------------------------------------------------------------------------------------------
// bad parameters

TEST(Generators, RejectBadParameters) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const std::vector<std::function<PatternSpec()>> bad{
      [] { return gen::single_vertex({}); },
      [] { return gen::single_vertex({2 * kPi}); },
      [] { return gen::single_vertex({kPi, kPi, 0.0}); },
      [] { return gen::single_vertex({kPi + 1, kPi, -1.0}); },
      [&] { return gen::single_vertex({kPi, kPi, nan}); },
      [] { return gen::single_vertex({kPi, kPi + 1e-6}); },
      [] { return gen::single_vertex({kPi, kPi}, 0.0); },
      [&] { return gen::single_vertex({kPi, kPi}, nan); },
      [] { return gen::single_vertex({kPi, kPi}, 1.0, {-1.0, 0.1}); },
      [&] { return gen::single_vertex({kPi, kPi}, 1.0, {1.0, nan}); },
      [] { return gen::strip(0); },
      [] { return gen::strip(3, -1.0); },
      [&] { return gen::strip(3, 1.0, inf); },
      [] { return gen::grid(0, 3); },
      [] { return gen::grid(3, -2); },
      [&] { return gen::grid(2, 2, nan); },
      [] { return gen::circular_lattice(0, 6); },
      [] { return gen::circular_lattice(2, 2); },
      [] { return gen::circular_lattice(2, 6, 0.0); },
      [] { return gen::miura(0, 4); },
      [] { return gen::miura(4, 0); },
      [] { return gen::miura(4, 4, 0.0); },
      [] { return gen::miura(4, 4, 1.0, -1.0); },
      [] { return gen::miura(4, 4, 1.0, 1.0, 0.0); },
      [] { return gen::miura(4, 4, 1.0, 1.0, -0.5); },
      [] { return gen::miura(4, 4, 1.0, 1.0, kPi / 2 + 1e-6); },
      [&] { return gen::miura(4, 4, 1.0, 1.0, nan); },
      [] { return gen::waterbomb(0, 2); },
      [] { return gen::waterbomb(2, 0); },
      [] { return gen::boat(0.0); },
      [] { return gen::boat(4.0, -1.0); },
      [] { return gen::boat(4.0, 1.0, 0.0); },
      [] { return gen::boat(4.0, 1.0, 2.0); },
      [&] { return gen::boat(nan); },
      [] { return gen::cube_sheet(0); },
      [] { return gen::cube_sheet(2, 0.0); },
  };
  for (std::size_t k = 0; k < bad.size(); ++k) EXPECT_THROW(bad[k](), std::invalid_argument) << "case " << k;
}

TEST(Generators, MessagesNameTheGeneratorAndParameter) {
  try {
    gen::miura(4, 4, 1.0, 1.0, 2.0);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("miura"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("angle"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace foldkit::geometry
