// Mass properties against the closed forms of a rectangle and a right triangle.
#include <gtest/gtest.h>

#include "foldkit/dynamics/mass_properties.hpp"
#include "foldkit/geometry/generators.hpp"

using namespace foldkit;

namespace {

geometry::CreasePattern one_actor(const std::vector<geometry::TriangleSpec>& triangles) {
  geometry::PatternSpec s;
  s.actors.push_back({1, triangles});
  return geometry::build_or_throw(s);
}

}  // namespace

TEST(MassProperties, RectangleMatchesClosedForm) {
  const double w = 3.0, h = 1.5, x0 = 2.0, y0 = -1.0, rho = 0.7, scale = 0.1;
  const auto p = one_actor({{{{{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}}}}, {{{{x0, y0}, {x0 + w, y0 + h}, {x0, y0 + h}}}}});
  const auto m = dynamics::mass_properties(p, 0, rho, scale);
  const double W = w * scale, H = h * scale, M = rho * W * H;
  EXPECT_NEAR(m.mass, M, 1e-15);
  EXPECT_NEAR(m.centroid.x(), (x0 + w / 2) * scale, 1e-14);
  EXPECT_NEAR(m.centroid.y(), (y0 + h / 2) * scale, 1e-14);
  EXPECT_EQ(m.centroid.z(), 0.0);
  EXPECT_NEAR(m.inertia(0, 0), M * H * H / 12, 1e-15);
  EXPECT_NEAR(m.inertia(1, 1), M * W * W / 12, 1e-15);
  EXPECT_NEAR(m.inertia(2, 2), M * (W * W + H * H) / 12, 1e-15);
  EXPECT_NEAR(m.inertia(0, 1), 0.0, 1e-15);
  EXPECT_NEAR(m.inertia(0, 2), 0.0, 1e-15);
  EXPECT_NEAR(m.inertia(1, 2), 0.0, 1e-15);
}

TEST(MassProperties, RightTriangleMatchesClosedForm) {
  // Legs a along x and b along y from the corner (1, 1): centroid a/3, b/3 from it; central
  // moments m b²/18, m a²/18; product of inertia −∫xy dm = +m a b/36.
  const double a = 2.0, b = 0.5, rho = 3.0;
  const auto p = one_actor({{{{{1, 1}, {1 + a, 1}, {1, 1 + b}}}}});
  const auto m = dynamics::mass_properties(p, 0, rho);
  const double M = rho * a * b / 2;
  EXPECT_NEAR(m.mass, M, 1e-14);
  EXPECT_NEAR(m.centroid.x(), 1 + a / 3, 1e-14);
  EXPECT_NEAR(m.centroid.y(), 1 + b / 3, 1e-14);
  EXPECT_NEAR(m.inertia(0, 0), M * b * b / 18, 1e-14);
  EXPECT_NEAR(m.inertia(1, 1), M * a * a / 18, 1e-14);
  EXPECT_NEAR(m.inertia(2, 2), M * (a * a + b * b) / 18, 1e-14);
  EXPECT_NEAR(m.inertia(0, 1), M * a * b / 36, 1e-14);
  EXPECT_NEAR(m.inertia(1, 0), M * a * b / 36, 1e-14);
}

TEST(MassProperties, SheetMassIsDensityTimesArea) {
  const auto p = geometry::build_or_throw(geometry::generators::miura(3, 4, 1.0, 1.0));
  double total = 0.0;
  for (std::size_t a = 0; a < p.actors().size(); ++a) total += dynamics::mass_properties(p, static_cast<int>(a), 2.0).mass;
  // A Miura sheet of 4 columns of width 1 and 3 rows of height 1 covers 12 unit parallelograms.
  EXPECT_NEAR(total, 2.0 * 12.0, 1e-12);
}
