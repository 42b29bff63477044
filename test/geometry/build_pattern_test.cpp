#include <cmath>
#include <algorithm>
#include <limits>

#include <boost/graph/connected_components.hpp>
#include <gtest/gtest.h>

#include "foldkit/geometry/crease_pattern.hpp"
#include "spec_helpers.hpp"

namespace {

using namespace foldkit::geometry;
using foldkit::test::joint;
using foldkit::test::square_actor;
using foldkit::test::two_by_two;

// True when some error diagnostic contains `fragment`.
bool reports(const BuildResult& r, const std::string& fragment) {
  for (const auto& d : r.diagnostics)
    if (d.severity == Severity::Error && d.message.find(fragment) != std::string::npos) return true;
  return false;
}

std::string all_messages(const BuildResult& r) {
  std::string out;
  for (const auto& d : r.diagnostics) out += format(d, "spec") + "\n";
  return out;
}

TEST(BuildPattern, TwoByTwoHasOneDegreeFourVertex) {
  const BuildResult r = build_pattern(two_by_two());
  ASSERT_TRUE(r.pattern) << all_messages(r);
  const CreasePattern& p = *r.pattern;
  EXPECT_EQ(p.actors().size(), 4u);
  EXPECT_EQ(p.joints().size(), 4u);
  EXPECT_EQ(p.vertices().size(), 9u);
  EXPECT_EQ(p.boundary_vertex_count(), 8u);
  EXPECT_EQ(p.boundary_edges().size(), 8u);
  ASSERT_EQ(p.interior_vertices().size(), 1u);
  const VertexStar& star = p.interior_vertices()[0];
  EXPECT_EQ(p.vertices()[star.vertex], Vec2(1, 1));
  ASSERT_EQ(star.joints.size(), 4u);
  for (double s : star.sectors) EXPECT_NEAR(s, M_PI / 2, 1e-15);
  // Counter-clockwise by polar angle in (−π, π]: down (1), right (2), up (3), left (4).
  EXPECT_EQ(p.joints()[star.joints[0]].id, 1);
  EXPECT_EQ(p.joints()[star.joints[1]].id, 2);
  EXPECT_EQ(p.joints()[star.joints[2]].id, 3);
  EXPECT_EQ(p.joints()[star.joints[3]].id, 4);
  EXPECT_EQ(boost::num_vertices(p.facet_graph()), 4u);
  EXPECT_EQ(boost::num_edges(p.facet_graph()), 4u);
  EXPECT_EQ(*p.actor_index(3), 2);
  EXPECT_FALSE(p.joint_index(99));
}

TEST(BuildPattern, WeldsCornersWithinTolerance) {
  PatternSpec s = two_by_two();
  s.actors[2].triangles[0].corners[0] += Vec2(3e-10, -2e-10);  // (1,1) drawn slightly off
  const BuildResult r = build_pattern(s);
  ASSERT_TRUE(r.pattern) << all_messages(r);
  EXPECT_EQ(r.pattern->vertices().size(), 9u);
}

TEST(BuildPattern, CornersBeyondToleranceStayApart) {
  PatternSpec s = two_by_two();
  BuildOptions o;
  o.merge_tolerance = 1e-12;
  s.actors[2].triangles[0].corners[0] += Vec2(1e-6, 0);
  const BuildResult r = build_pattern(s, o);
  EXPECT_FALSE(r.pattern);
}

TEST(BuildPattern, OrientsTrianglesCounterClockwise) {
  PatternSpec s = two_by_two();
  std::swap(s.actors[0].triangles[0].corners[1], s.actors[0].triangles[0].corners[2]);
  const BuildResult r = build_pattern(s);
  ASSERT_TRUE(r.pattern) << all_messages(r);
  for (const auto& a : r.pattern->actors())
    for (const auto& t : a.triangles) {
      const auto& V = r.pattern->vertices();
      const Vec2 u = V[t.v[1]] - V[t.v[0]], w = V[t.v[2]] - V[t.v[0]];
      EXPECT_GT(u.x() * w.y() - u.y() * w.x(), 0.0);
    }
}

TEST(BuildPattern, JointAlongTwoCollinearEdges) {
  const PatternSpec s = foldkit::test::straight_crease_through_vertex();
  const BuildResult r = build_pattern(s);
  ASSERT_TRUE(r.pattern) << all_messages(r);
  ASSERT_EQ(r.pattern->interior_vertices().size(), 1u);  // (1,1): the crease passes straight through
  const VertexStar& star = r.pattern->interior_vertices()[0];
  ASSERT_EQ(star.sectors.size(), 2u);
  EXPECT_NEAR(star.sectors[0], M_PI, 1e-15);
}

TEST(BuildPatternRules, EmptyPattern) { EXPECT_TRUE(reports(build_pattern(PatternSpec{}), "no actors")); }

TEST(BuildPatternRules, NonFiniteCoordinate) {
  PatternSpec s = two_by_two();
  s.actors[1].triangles[1].corners[2].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(reports(build_pattern(s), "not finite"));
  s = two_by_two();
  s.joints[0].coords[1].y() = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(reports(build_pattern(s), "not finite"));
}

TEST(BuildPatternRules, DuplicateIds) {
  PatternSpec s = two_by_two();
  s.actors[3].id = 1;
  EXPECT_TRUE(reports(build_pattern(s), "duplicate actor ID 1"));
  s = two_by_two();
  s.joints[2].id = 1;
  EXPECT_TRUE(reports(build_pattern(s), "duplicate joint ID 1"));
}

TEST(BuildPatternRules, SpringAndDampingConstants) {
  PatternSpec s = two_by_two();
  s.joints[0].spring = -1;
  EXPECT_TRUE(reports(build_pattern(s), "spring constant"));
  s = two_by_two();
  s.joints[0].damping = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(reports(build_pattern(s), "damping constant"));
  for (double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    s = two_by_two();
    s.joints[1].max_torque = bad;
    EXPECT_TRUE(reports(build_pattern(s), "maximum torque must be positive and finite")) << bad;
  }
  s = two_by_two();
  s.joints[1].max_torque = 2.5;
  const auto built = build_pattern(s);
  ASSERT_TRUE(built.pattern.has_value());
  EXPECT_EQ(built.pattern->joints()[1].max_torque, 2.5);
  EXPECT_EQ(built.pattern->joints()[0].max_torque, std::nullopt);
  EXPECT_EQ(built.pattern->to_spec().joints[1].max_torque, 2.5);
}

TEST(BuildPatternRules, JointNamesUnknownOrSameActor) {
  PatternSpec s = two_by_two();
  s.joints[0].actor_ids = {1, 9};
  EXPECT_TRUE(reports(build_pattern(s), "names actor 9, which does not exist"));
  s = two_by_two();
  s.joints[0].actor_ids = {2, 2};
  EXPECT_TRUE(reports(build_pattern(s), "to itself"));
}

TEST(BuildPatternRules, DegenerateTriangle) {
  PatternSpec s = two_by_two();
  s.actors[0].triangles.push_back({{Vec2(0, 0), Vec2(0.5, 0), Vec2(1, 0)}, 42});
  const BuildResult r = build_pattern(s);
  EXPECT_TRUE(reports(r, "degenerate triangle"));
  EXPECT_EQ(r.diagnostics.front().line, 42);
  s = two_by_two();
  s.actors[0].triangles.push_back({{Vec2(0, 0), Vec2(0, 0), Vec2(1, 0)}, 0});
  EXPECT_TRUE(reports(build_pattern(s), "degenerate triangle"));
}

TEST(BuildPatternRules, OverlappingTriangles) {
  PatternSpec s = two_by_two();
  s.actors.push_back(square_actor(5, 0.5, 0.5, 0.2));
  EXPECT_TRUE(reports(build_pattern(s), "overlaps a triangle of actor"));
}

TEST(BuildPatternRules, TouchingIsNotOverlapping) {
  PatternSpec s;
  s.actors = {square_actor(1, 0, 0), square_actor(2, 1, 0.5)};  // share half an edge: T-junctions
  const BuildResult r = build_pattern(s);
  EXPECT_FALSE(reports(r, "overlaps"));
  EXPECT_TRUE(reports(r, "T-junction"));
}

TEST(BuildPatternRules, ActorNotConnected) {
  PatternSpec s;
  ActorSpec a = square_actor(1, 0, 0);
  const ActorSpec far = square_actor(1, 5, 0);
  a.triangles.insert(a.triangles.end(), far.triangles.begin(), far.triangles.end());
  s.actors = {a};
  EXPECT_TRUE(reports(build_pattern(s), "actor 1 is not connected"));
}

TEST(BuildPatternRules, JointThatIsNotASharedEdge) {
  PatternSpec s = two_by_two();
  s.joints[0].coords = {Vec2(0, 0), Vec2(1, 0)};  // boundary edge of actor 1 only
  const BuildResult r = build_pattern(s);
  EXPECT_TRUE(reports(r, "is not an edge shared by actors 1 and 2"));
  s = two_by_two();
  s.joints[0].coords[0] = Vec2(1, 0.3);  // not a corner at all
  EXPECT_TRUE(reports(build_pattern(s), "is not a vertex"));
}

TEST(BuildPatternRules, TwoJointsOnOneEdge) {
  PatternSpec s = two_by_two();
  s.joints.push_back(joint(9, Vec2(1, 1), Vec2(1, 0), 2, 1));
  EXPECT_TRUE(reports(build_pattern(s), "joint 9"));
}

TEST(BuildPatternRules, SharedEdgeWithoutJoint) {
  PatternSpec s = two_by_two();
  s.joints.pop_back();
  const BuildResult strict = build_pattern(s);
  EXPECT_TRUE(reports(strict, "shared by actor 4 and actor 1 but has no joint") ||
              reports(strict, "shared by actor 1 and actor 4 but has no joint"))
      << all_messages(strict);
  BuildOptions o;
  o.auto_joints = true;
  const BuildResult lenient = build_pattern(s, o);
  ASSERT_TRUE(lenient.pattern) << all_messages(lenient);
  EXPECT_EQ(lenient.pattern->joints().size(), 4u);
  EXPECT_EQ(lenient.pattern->joints().back().id, 4);
  ASSERT_EQ(lenient.diagnostics.size(), 1u);
  EXPECT_EQ(lenient.diagnostics[0].severity, Severity::Warning);
}

TEST(BuildPatternRules, EdgeUsedByThreeTriangles) {
  PatternSpec s;
  s.actors = {{1, {{{Vec2(0, 0), Vec2(1, 0), Vec2(0.5, 1)}, 0}}, 0},
              {2, {{{Vec2(0, 0), Vec2(1, 0), Vec2(0.5, -1)}, 0}}, 0},
              {3, {{{Vec2(0, 0), Vec2(1, 0), Vec2(0.5, -2)}, 0}}, 0}};
  EXPECT_TRUE(reports(build_pattern(s), "used by 3 triangles"));
}

TEST(BuildPatternRules, SectorAnglesMustSumTo360) {
  // A closed fan that winds twice around the origin: every edge is shared, but the facet angles
  // at the centre add up to 720°.
  ActorSpec fan{1, {}, 0};
  for (int k = 0; k < 8; ++k) {
    const double r0 = k < 4 ? 1.0 : 2.0, r1 = (k + 1) % 8 < 4 ? 1.0 : 2.0;
    const double a0 = k * M_PI / 2, a1 = (k + 1) * M_PI / 2;
    fan.triangles.push_back({{Vec2(0, 0), r0 * Vec2(std::cos(a0), std::sin(a0)), r1 * Vec2(std::cos(a1), std::sin(a1))}, 0});
  }
  PatternSpec s;
  s.actors = {fan};
  const BuildResult r = build_pattern(s);
  EXPECT_TRUE(reports(r, "facet angles sum to 720 degrees")) << all_messages(r);
}

TEST(BuildPatternRules, ReportsEveryProblemInOneRun) {
  PatternSpec s = two_by_two();
  s.joints.pop_back();
  s.actors.push_back(square_actor(5, 0.5, 0.5, 0.2));
  const BuildResult r = build_pattern(s);
  EXPECT_TRUE(reports(r, "overlaps"));
  EXPECT_TRUE(reports(r, "has no joint"));
}

TEST(BuildPattern, ToSpecRebuildsTheSamePattern) {
  const CreasePattern p = build_or_throw(two_by_two());
  const CreasePattern q = build_or_throw(p.to_spec());
  EXPECT_EQ(p.vertices(), q.vertices());
  ASSERT_EQ(p.joints().size(), q.joints().size());
  for (std::size_t j = 0; j < p.joints().size(); ++j) EXPECT_EQ(p.joints()[j].v, q.joints()[j].v);
}

TEST(BuildPattern, BuildOrThrowListsErrors) {
  PatternSpec s = two_by_two();
  s.joints[0].actor_ids = {1, 9};
  EXPECT_THROW(build_or_throw(s), std::invalid_argument);
}

}  // namespace

namespace {

// Review findings: each case once passed or crashed.
TEST(BuildPatternReview, TJunctionWithinToleranceOfTheLine) {
  for (double offset : {0.0, 1e-10, -1e-12}) {
    PatternSpec s;
    s.actors = {{1, {{{Vec2(0, 0), Vec2(2, 0), Vec2(1, 1)}, 3}}, 2},
                {2, {{{Vec2(0, 0), Vec2(1, -1), Vec2(1, offset)}, 5}, {{Vec2(1, offset), Vec2(1, -1), Vec2(2, 0)}, 6}}, 4}};
    const BuildResult r = build_pattern(s);
    EXPECT_TRUE(reports(r, "T-junction")) << offset;
    for (const auto& d : r.diagnostics) {
      if (d.message.find("T-junction") != std::string::npos) {
        EXPECT_GT(d.line, 0);
      }
    }
  }
}

TEST(BuildPatternReview, CoordinateRange) {
  auto scaled = [](double f) {
    PatternSpec s = two_by_two();
    for (auto& a : s.actors)
      for (auto& t : a.triangles)
        for (auto& c : t.corners) c *= f;
    for (auto& j : s.joints)
      for (auto& c : j.coords) c *= f;
    return s;
  };
  for (double f : {1e-90, 1e-20, 1e20, 1e90}) {
    const BuildResult r = build_pattern(scaled(f));
    ASSERT_TRUE(r.pattern) << f << "\n" << all_messages(r);
    EXPECT_EQ(r.pattern->vertices().size(), 9u) << f;
    ASSERT_EQ(r.pattern->interior_vertices().size(), 1u) << f;
  }
  EXPECT_TRUE(reports(build_pattern(scaled(1e160)), "outside ±1e100"));
  EXPECT_TRUE(reports(build_pattern(scaled(1e-170)), "below 1e-100"));
}

TEST(BuildPatternReview, AutoJointIdsNeverOverflowOrCollide) {
  PatternSpec s = two_by_two();
  s.joints[0].id = std::numeric_limits<int>::max();
  s.joints[1].id = 1;
  s.joints.pop_back();
  s.joints.pop_back();
  BuildOptions o;
  o.auto_joints = true;
  const BuildResult r = build_pattern(s, o);
  ASSERT_TRUE(r.pattern) << all_messages(r);
  std::vector<int> ids;
  for (const Joint& j : r.pattern->joints()) ids.push_back(j.id);
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(std::adjacent_find(ids.begin(), ids.end()), ids.end());
  EXPECT_EQ(ids, (std::vector<int>{1, 2, 3, std::numeric_limits<int>::max()}));
}

TEST(BuildPatternReview, NegativeZeroKeepsDirectionsInRange) {
  // The corner (−1, −0) is welded first: its crease must point at π, not −π.
  PatternSpec s;
  s.actors = {{1, {{{Vec2(0, 0), Vec2(-1, -0.0), Vec2(0, -1)}, 0}, {{Vec2(0, 0), Vec2(0, -1), Vec2(1, 0)}, 0}}, 0},
              {2, {{{Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)}, 0}, {{Vec2(0, 0), Vec2(0, 1), Vec2(-1, 0)}, 0}}, 0}};
  s.joints = {joint(1, Vec2(0, 0), Vec2(-1, 0), 1, 2), joint(2, Vec2(0, 0), Vec2(1, 0), 1, 2)};
  const CreasePattern p = build_or_throw(s);
  ASSERT_EQ(p.interior_vertices().size(), 1u);
  const auto& dirs = p.interior_vertices()[0].directions;
  EXPECT_EQ(dirs.back(), M_PI);
  EXPECT_FALSE(std::signbit(p.vertices()[1].y()));
}

TEST(BuildPatternReview, HighDegreeVertex) {
  // Joints at a vertex of degree 1,000 are found by edge lookup, not by scanning the centre's
  // edges for each. (The overlap check stays quadratic for such a fan: every sliver's bounding
  // box holds the centre, so the size stays modest for the sanitizer build.)
  const int n = 1000;
  PatternSpec s;
  for (int k = 0; k < n; ++k) {
    const double a0 = 2 * M_PI * k / n, a1 = 2 * M_PI * (k + 1) / n;
    s.actors.push_back({k + 1, {{{Vec2(0, 0), Vec2(std::cos(a0), std::sin(a0)), Vec2(std::cos(a1), std::sin(a1))}, 0}}, 0});
    s.joints.push_back(joint(k + 1, Vec2(0, 0), Vec2(std::cos(a1), std::sin(a1)), k + 1, (k + 1) % n + 1));
  }
  const BuildResult r = build_pattern(s);
  ASSERT_TRUE(r.pattern) << all_messages(r).substr(0, 500);
  EXPECT_EQ(r.pattern->interior_vertices()[0].joints.size(), static_cast<std::size_t>(n));
}

}  // namespace
