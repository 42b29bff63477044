// CornerMotion against displacements computed directly from the poses: a rigid motion of the
// whole sheet does not count, the answer never exceeds the plain largest displacement, and it is
// the same whatever rigid motion is applied to either placement.
#include <random>

#include <gtest/gtest.h>

#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/simulation/corner_motion.hpp"

namespace foldkit::simulation {
namespace {

namespace gen = geometry::generators;
using geometry::FoldState;

double plain_largest(const geometry::CreasePattern& p, const std::vector<Eigen::Isometry3d>& from,
                     const std::vector<Eigen::Isometry3d>& to) {
  double most = 0.0;
  for (std::size_t a = 0; a < p.actors().size(); ++a)
    for (const auto& t : p.actors()[a].triangles)
      for (int v : t.v) {
        const Eigen::Vector3d x(p.vertices()[v].x(), p.vertices()[v].y(), 0.0);
        most = std::max(most, (to[a] * x - from[a] * x).norm());
      }
  return most;
}

std::vector<Eigen::Isometry3d> moved(const Eigen::Isometry3d& m, std::vector<Eigen::Isometry3d> poses) {
  for (auto& x : poses) x = m * x;
  return poses;
}

TEST(CornerMotion, ARigidMotionOfTheWholeSheetDoesNotCount) {
  const auto p = geometry::build_or_throw(gen::miura(6, 6));
  const auto tree = geometry::make_tree(p);
  const CornerMotion motion(p);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> angle(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    FoldState s = FoldState::flat(p), t = FoldState::flat(p);
    for (Eigen::Index j = 0; j < s.angles.size(); ++j) {
      s.angles[j] = angle(rng);
      t.angles[j] = s.angles[j] + 0.05 * angle(rng);
    }
    const auto from = geometry::facet_poses(p, tree, s), to = geometry::facet_poses(p, tree, t);
    const Eigen::Isometry3d m = Eigen::Translation3d(5.0 * angle(rng), 3.0, -2.0) *
                                Eigen::AngleAxisd(2.0 * angle(rng), Eigen::Vector3d(1, 2, 3).normalized());
    // The sheet as placed, moved as a whole: nothing moved.
    EXPECT_NEAR(motion.largest(from, moved(m, from)), 0.0, 1e-9);
    EXPECT_GT(plain_largest(p, from, moved(m, from)), 1.0);
    // A fold step: never more than the plain displacement, and, once the sheet is far from
    // where it was, blind to where (the same answer after two different rigid motions).
    EXPECT_LE(motion.largest(from, to), plain_largest(p, from, to) + 1e-15);
    const Eigen::Isometry3d m2 = Eigen::Translation3d(-4.0, 7.0, 1.0) * Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitX());
    EXPECT_NEAR(motion.largest(moved(m, from), to), motion.largest(moved(m2, from), to), 1e-9);
    EXPECT_NEAR(motion.largest(from, moved(m, to)), motion.largest(from, moved(m2, to)), 1e-9);
    EXPECT_LT(motion.largest(from, moved(m, to)), 0.5);
  }
  EXPECT_THROW(motion.largest({}, {}), std::invalid_argument);
}

// One flap turning by a small angle about its crease: its far corner moves by about the angle
// times its distance from the crease, and the aligned measure is of that order (the rest of the
// sheet, standing still, keeps the alignment near the identity).
TEST(CornerMotion, AFlapTurningMovesByItsLever) {
  const auto p = geometry::build_or_throw(gen::strip(8));
  const auto tree = geometry::make_tree(p);
  FoldState s = FoldState::flat(p), t = FoldState::flat(p);
  t.angles[t.angles.size() - 1] = 0.01;
  const auto from = geometry::facet_poses(p, tree, s), to = geometry::facet_poses(p, tree, t);
  const double plain = plain_largest(p, from, to);
  const double aligned = CornerMotion(p).largest(from, to);
  EXPECT_GT(plain, 0.005);
  EXPECT_LE(aligned, plain);
  EXPECT_GT(aligned, 0.5 * plain);
}

}  // namespace
}  // namespace foldkit::simulation
