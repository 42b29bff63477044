#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/geometry/projection.hpp"

namespace {

using namespace foldkit::geometry;
namespace gen = generators;

Vec3 lift(const Vec2& p) { return Vec3(p.x(), p.y(), 0); }

Vec3 centroid(const CreasePattern& p, int actor) {
  Vec3 c = Vec3::Zero();
  int n = 0;
  for (const auto& t : p.actors()[actor].triangles)
    for (int v : t.v) c += lift(p.vertices()[v]), ++n;
  return c / n;
}

// Largest distance between where the two actors of a joint put its ends: zero exactly when the
// folded sheet holds together at every crease.
double crease_gap(const CreasePattern& p, const std::vector<Eigen::Isometry3d>& pose) {
  double gap = 0;
  for (const Joint& j : p.joints())
    for (int v : j.v) gap = std::max(gap, (pose[j.actors[0]] * lift(p.vertices()[v]) - pose[j.actors[1]] * lift(p.vertices()[v])).norm());
  return gap;
}

TEST(Kinematics, MountainFacetsFallBelowTheCrease) {
  for (bool reversed : {false, true}) {
    PatternSpec s = gen::strip(2);
    if (reversed) {  // the sign must not depend on the order of Coords or ActorIDs
      std::swap(s.joints[0].coords[0], s.joints[0].coords[1]);
      std::swap(s.joints[0].actor_ids[0], s.joints[0].actor_ids[1]);
    }
    const CreasePattern p = build_or_throw(s);
    for (int root : {0, 1}) {
      const KinematicTree tree = make_tree(p, root);
      FoldState mountain = FoldState::flat(p);
      mountain.angles[0] = M_PI / 2;
      const int moving = 1 - root;
      EXPECT_LT((facet_poses(p, tree, mountain)[moving] * centroid(p, moving)).z(), -0.4);
      FoldState valley = mountain;
      valley.angles[0] = -M_PI / 2;
      EXPECT_GT((facet_poses(p, tree, valley)[moving] * centroid(p, moving)).z(), 0.4);
    }
  }
}

TEST(Kinematics, RigidMotionsKeepDistances) {
  const CreasePattern p = build_or_throw(gen::strip(5));
  const KinematicTree tree = make_tree(p, 2);
  FoldState s = FoldState::flat(p);
  s.angles << 0.3, -2.0, 1.0, 3.0;
  const auto pose = facet_poses(p, tree, s);
  EXPECT_LT(crease_gap(p, pose), 1e-14);  // a strip has no loops: every state holds together
  for (const auto& T : pose) EXPECT_NEAR((T.linear().transpose() * T.linear() - Eigen::Matrix3d::Identity()).norm(), 0, 1e-14);
  EXPECT_TRUE(pose[2].isApprox(Eigen::Isometry3d::Identity()));
}

TEST(Kinematics, ClosedStatesHoldTogetherAtEveryCrease) {
  // The closure residual and forward kinematics are computed independently: a state with zero
  // residual must put both sides of every crease (tree or not) in the same place.
  std::mt19937 rng(5);
  for (const PatternSpec& spec : {gen::miura(4, 5), gen::boat(), gen::waterbomb(2, 2), gen::single_vertex({1, 2, 1.5, 2 * M_PI - 4.5})}) {
    const CreasePattern p = build_or_throw(spec);
    const ClosureSystem sys(p);
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    FoldState s = FoldState::flat(p);
    for (Eigen::Index i = 0; i < s.angles.size(); ++i) s.angles[i] = u(rng);
    const ProjectionResult r = project(sys, s, {1e-13, 300, false, {}});
    ASSERT_TRUE(r.status.ok()) << spec.title << ": " << r.status.message;
    for (int root = 0; root < static_cast<int>(p.actors().size()); root += 3)
      EXPECT_LT(crease_gap(p, facet_poses(p, make_tree(p, root), r.state)), 1e-10) << spec.title;
    EXPECT_GT(crease_gap(p, facet_poses(p, make_tree(p, 0), s)), 1e-4) << spec.title << ": the unprojected state must not close";
  }
}

}  // namespace
