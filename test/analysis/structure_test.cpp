// Connection detection on folded sheets, checked against counts worked out by hand.
#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "foldkit/analysis/structure.hpp"
#include "foldkit/geometry/generators.hpp"

namespace {

using namespace foldkit;
using analysis::ConnectionKind;

std::map<ConnectionKind, int> count(const analysis::Structure& s) {
  std::map<ConnectionKind, int> c;
  for (const auto& k : s.connections) ++c[k.kind];
  return c;
}

// One net of Fig. 8a with its five creases at −90° (valley, as assigned).
geometry::FoldState cube_state(const geometry::CreasePattern& p, int nets) {
  geometry::FoldState s = geometry::FoldState::flat(p);
  for (int n = 0; n < nets; ++n)
    for (int j = 0; j < 5; ++j) s.angles[6 * n + j] = -M_PI / 2;
  return s;
}

TEST(Structure, FlatSheetHasOnlyHinges) {
  const auto p = geometry::build_or_throw(geometry::generators::grid(3, 4));
  const auto s = analysis::build_structure(p, geometry::FoldState::flat(p));
  auto c = count(s);
  EXPECT_EQ(c[ConnectionKind::Hinged], static_cast<int>(p.joints().size()));
  EXPECT_EQ(c[ConnectionKind::Face], 0);
  EXPECT_EQ(c[ConnectionKind::Edge], 0);
  EXPECT_NEAR(s.tile, 1.0, 1e-12);
}

TEST(Structure, FoldedCubeHasFiveHingesAndSevenEdges) {
  const double tile = 0.01;
  const auto p = geometry::build_or_throw(geometry::generators::cube_sheet(1, tile));
  const auto s = analysis::build_structure(p, cube_state(p, 1));
  auto c = count(s);
  EXPECT_EQ(c[ConnectionKind::Hinged], 5);
  EXPECT_EQ(c[ConnectionKind::Edge], 7);  // a cube has 12 edges
  EXPECT_EQ(c[ConnectionKind::Face], 0);
  for (const auto& k : s.connections) {
    // Frames: orthonormal, right-handed; e3 along the edge (whose length is the tile), e1 in a's
    // plane pointing into a.
    EXPECT_NEAR((k.axes.transpose() * k.axes - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-12);
    EXPECT_NEAR(k.axes.determinant(), 1.0, 1e-12);
    EXPECT_NEAR(k.extent, tile, 1e-12);
    const auto& a = s.modules[static_cast<std::size_t>(k.a)];
    EXPECT_NEAR(k.axes.col(0).dot(a.normal), 0.0, 1e-12);
    EXPECT_NEAR((a.centroid - k.origin).dot(k.axes.col(0)), tile / 2, 1e-12);
    EXPECT_NEAR((a.centroid - k.origin).dot(k.axes.col(2)), 0.0, 1e-12);
  }
  // Every tile meets four others, and the centroids are the six face centres of the cube.
  std::map<int, int> degree;
  for (const auto& k : s.connections) ++degree[k.a], ++degree[k.b];
  for (const auto& [m, d] : degree) EXPECT_EQ(d, 4) << m;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& m : s.modules) mean += m.centroid / 6.0;
  for (const auto& m : s.modules) EXPECT_NEAR((m.centroid - mean).norm(), tile / 2, 1e-12);
}

TEST(Structure, TilesFoldedFlatOntoEachOtherTouchFaceToFace) {
  const auto p = geometry::build_or_throw(geometry::generators::strip(3));
  geometry::FoldState s = geometry::FoldState::flat(p);
  s.angles[0] = M_PI;  // the first tile onto the second
  const auto st = analysis::build_structure(p, s);
  auto c = count(st);
  EXPECT_EQ(c[ConnectionKind::Hinged], 2);
  EXPECT_EQ(c[ConnectionKind::Face], 1);
  EXPECT_EQ(c[ConnectionKind::Edge], 1);  // the first tile's far edge now lies on the second crease
  for (const auto& k : st.connections)
    if (k.kind == ConnectionKind::Face) {
      EXPECT_NEAR(k.extent, 1.0, 1e-12);  // the whole unit tile
      EXPECT_NEAR((k.origin - st.modules[1].centroid).norm(), 0.0, 1e-12);
    }
  // Slightly open: no longer touching within the tolerance.
  s.angles[0] = M_PI - 1e-3;
  EXPECT_EQ(count(analysis::build_structure(p, s))[ConnectionKind::Face], 0);
  analysis::DetectOptions loose;
  loose.tolerance = 1e-2;
  EXPECT_EQ(count(analysis::build_structure(p, s, loose))[ConnectionKind::Face], 1);
}

TEST(Structure, DefaultStiffnessIsEquationSix) {
  const auto h = analysis::default_stiffness(ConnectionKind::Hinged);
  const auto f = analysis::default_stiffness(ConnectionKind::Face);
  EXPECT_EQ(f.diagonal().head<3>(), Eigen::Vector3d::Constant(1e6));
  EXPECT_EQ(f.diagonal().tail<3>(), Eigen::Vector3d::Constant(1e1));
  EXPECT_EQ(f, analysis::default_stiffness(ConnectionKind::Edge));
  EXPECT_EQ(h(5, 5), 1.0);
  EXPECT_EQ(h(4, 4), 1e1);
  EXPECT_EQ((h - f).cwiseAbs().sum(), 9.0);
}

}  // namespace
