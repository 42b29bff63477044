// Spherical Carpenter's rule: every frame is checked against oracles that do not share its code —
// crease directions from geometry::facet_poses, closure from geometry::ClosureSystem, and the
// folding CMML replayed by the simulator (FCL self-collision).
#include <cmath>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/folding/carpenter_spherical.hpp"
#include "foldkit/simulation/collision_world.hpp"
#include "foldkit/simulation/simulate.hpp"
#include "foldkit/statespaces/single_vertex_chain.hpp"
#include "random_vertex_state.hpp"
#include "spec_helpers.hpp"

namespace {

namespace gen = foldkit::geometry::generators;
using foldkit::geometry::build_or_throw;
using foldkit::geometry::ClosureSystem;
using foldkit::geometry::CreasePattern;
using foldkit::geometry::FoldState;
using foldkit::folding::CarpenterSphericalResult;
using foldkit::folding::flatten_single_vertex;
using foldkit::folding::CarpenterSphericalOptions;

// Unit direction of each crease (counter-clockwise) from the facet poses: the crease's far end
// carried by one of its facets.
std::vector<Eigen::Vector3d> directions(const CreasePattern& p, const FoldState& s) {
  const auto poses = foldkit::geometry::facet_poses(p, foldkit::geometry::make_tree(p), s);
  const auto& star = p.interior_vertices().front();
  const Eigen::Vector2d centre = p.vertices()[static_cast<std::size_t>(star.vertex)];
  std::vector<Eigen::Vector3d> u;
  for (int j : star.joints) {
    const auto& joint = p.joints()[static_cast<std::size_t>(j)];
    const int far = (p.vertices()[static_cast<std::size_t>(joint.v[0])] - centre).norm() > 1e-12 ? joint.v[0] : joint.v[1];
    const Eigen::Vector2d d = p.vertices()[static_cast<std::size_t>(far)] - centre;
    u.push_back((poses[static_cast<std::size_t>(joint.actors[1])].linear() * Eigen::Vector3d(d.x(), d.y(), 0.0)).normalized());
  }
  return u;
}

double arc(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

void expect_valid_flattening(const CreasePattern& p, const FoldState& folded, const CarpenterSphericalResult& r) {
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_GE(r.frames.size(), 2u);
  EXPECT_LT((r.frames.front().angles - folded.angles).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_EQ(r.frames.back().angles.cwiseAbs().maxCoeff(), 0.0);
  const ClosureSystem sys(p);
  const auto& star = p.interior_vertices().front();
  const std::size_t n = star.joints.size();
  std::vector<Eigen::Vector3d> previous;
  double worst_growth = 1e9, worst_sector = 0, worst_closure = 0, worst_jump = 0;
  for (std::size_t f = 0; f < r.frames.size(); ++f) {
    const FoldState& s = r.frames[f];
    worst_closure = std::max(worst_closure, sys.max_error(s));
    const auto u = directions(p, s);
    if (f > 0) {
      for (std::size_t i = 0; i < n; ++i) worst_sector = std::max(worst_sector, std::abs(arc(u[i], u[(i + 1) % n]) - star.sectors[i]));
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 1; j < n; ++j) worst_growth = std::min(worst_growth, arc(u[i], u[j]) - arc(previous[i], previous[j]));
      worst_jump = std::max(worst_jump, (s.angles - r.frames[f - 1].angles).cwiseAbs().maxCoeff());
    }
    previous = u;
  }
  EXPECT_LT(worst_closure, 1e-9);
  EXPECT_LT(worst_sector, 1e-9);
  EXPECT_GT(worst_growth, -1e-9) << "a pairwise spherical distance shrank";
  EXPECT_LT(worst_jump, 0.021);
  EXPECT_LT(r.max_closure_error, 1e-9);
  EXPECT_LT(r.max_sector_error, 1e-9);
  // Folding = the frames reversed; the simulator replays it from flat without a crossing.
  const auto report = foldkit::simulation::simulate(p, r.folding);
  EXPECT_TRUE(report.status.ok()) << (report.problems.empty() ? std::string() : report.problems.front());
  EXPECT_TRUE(report.collisions.empty());
  EXPECT_LT((report.final_state.angles - folded.angles).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(CarpenterSpherical, RandomVerticesOfDegree4To12FlattenExpansively) {
  std::mt19937 rng(606);
  for (int n = 4; n <= 12; ++n) {
    const CreasePattern p = build_or_throw(gen::single_vertex(foldkit::test::random_sectors(n, rng, 0.25)));
    for (unsigned k = 0; k < 2; ++k) {
      SCOPED_TRACE("degree " + std::to_string(n) + " sample " + std::to_string(k));
      const FoldState folded = foldkit::test::random_vertex_state(p, static_cast<unsigned>(1000 * n + k));
      ASSERT_LT(ClosureSystem(p).max_error(folded), 1e-9);
      const CarpenterSphericalResult r = flatten_single_vertex(p, folded);
      expect_valid_flattening(p, folded, r);
    }
  }
}

// The paper's Fig. 4: 0.01 rad short of the closed corner (as in plan_test.cpp).
TEST(CarpenterSpherical, CornerCubeUnfoldsAndItsReverseFoldsTheCorner) {
  const double h = M_PI / 2, q = M_PI / 4;
  const CreasePattern p = build_or_throw(gen::single_vertex({h, h, h, q, q}));
  Eigen::VectorXd guess(5);
  guess << 0.778, -h + 0.01, -h + 0.01, 0.778, -M_PI + 0.02;
  foldkit::geometry::ProjectionOptions po;
  po.tolerance = 1e-12;
  const auto goal = foldkit::geometry::project(ClosureSystem(p), FoldState{guess}, po);
  ASSERT_TRUE(goal.status.ok());
  const CarpenterSphericalResult r = flatten_single_vertex(p, goal.state);
  expect_valid_flattening(p, goal.state, r);
  EXPECT_GT(r.steps, 0);
}

// The corner shut exactly: creases 0 and 3 on one direction (distance 0, which no first-order
// motion grows; the LP leaves that pair alone and the others open it).
TEST(CarpenterSpherical, CornerCubeShutExactlyUnfoldsToo) {
  const double h = M_PI / 2, q = M_PI / 4;
  const CreasePattern p = build_or_throw(gen::single_vertex({h, h, h, q, q}));
  Eigen::VectorXd shut(5);
  shut << q, -h, -h, q, -M_PI;
  ASSERT_LT(ClosureSystem(p).max_error(FoldState{shut}), 1e-12);
  expect_valid_flattening(p, FoldState{shut}, flatten_single_vertex(p, FoldState{shut}));
}

TEST(CarpenterSpherical, RefusesWhatItCannotFlatten) {
  const double h = M_PI / 2;
  const CreasePattern v4 = build_or_throw(gen::single_vertex({h, h, h, h}));
  // Not one vertex.
  const CreasePattern miura = build_or_throw(gen::miura(3, 3));
  EXPECT_THROW(flatten_single_vertex(miura, FoldState::flat(miura)), std::invalid_argument);
  // Wrong size, not closed.
  EXPECT_THROW(flatten_single_vertex(v4, FoldState{Eigen::VectorXd::Zero(3)}), std::invalid_argument);
  Eigen::VectorXd open(4);
  open << 0.5, 0.0, 0.0, 0.0;
  EXPECT_THROW(flatten_single_vertex(v4, FoldState{open}), std::invalid_argument);
  // A sector wider than 180°.
  const CreasePattern wide = build_or_throw(gen::single_vertex({3.5, 1.0, 1.0, 2 * M_PI - 5.5}));
  try {
    flatten_single_vertex(wide, FoldState::flat(wide));
    ADD_FAILURE() << "a sector over 180 degrees was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("below 180 degrees"), std::string::npos) << e.what();
  }
  // Folded exactly in half: the layers' distances do not change to first order as the fold opens.
  const CreasePattern miura_vertex = build_or_throw(gen::single_vertex({1.0, M_PI - 1.0, 1.0, M_PI - 1.0}));
  Eigen::VectorXd half(4);
  half << M_PI, 0.0, M_PI, 0.0;
  ASSERT_LT(ClosureSystem(miura_vertex).max_error(FoldState{half}), 1e-12);
  const CarpenterSphericalResult stacked = flatten_single_vertex(miura_vertex, FoldState{half});
  EXPECT_FALSE(stacked.status.ok());
  EXPECT_NE(stacked.status.message.find("folded flat"), std::string::npos) << stacked.status.message;
  // A state whose sectors cross (rejected by the FCL world too) is refused.
  const CreasePattern v5 = build_or_throw(gen::single_vertex({1.0, 1.2, 1.4, 1.3, 2 * M_PI - 4.9}));
  const foldkit::statespaces::SingleVertexChain chain(v5);
  foldkit::simulation::CollisionWorld world(v5);
  std::mt19937 pick(11);
  std::uniform_real_distribution<double> angle(-3.0, 3.0);
  int crossing = 0;
  for (int k = 0; k < 4000 && crossing < 5; ++k) {
    FoldState f = FoldState::flat(v5);
    for (int j : chain.active_joints()) f.angles[j] = angle(pick);
    if (!chain.solve(f, pick() % 2 == 0 ? 1 : -1) || f.angles.cwiseAbs().maxCoeff() > M_PI - 0.01) continue;
    world.reset();
    if (world.check(foldkit::geometry::facet_poses(v5, foldkit::geometry::make_tree(v5), f), f).empty()) continue;
    ++crossing;
    try {
      flatten_single_vertex(v5, f);
      ADD_FAILURE() << "a crossing state was accepted: " << f.angles.transpose();
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("crosses itself"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(crossing, 5);
  // The step limit stops the method with a message (no endless loop).
  std::mt19937 rng(7);
  const CreasePattern v6 = build_or_throw(gen::single_vertex(foldkit::test::random_sectors(6, rng, 0.3)));
  CarpenterSphericalOptions one;
  one.max_steps = 1;
  const CarpenterSphericalResult r = flatten_single_vertex(v6, foldkit::test::random_vertex_state(v6, 5), one);
  EXPECT_FALSE(r.status.ok());
  EXPECT_NE(r.status.message.find("max_steps"), std::string::npos) << r.status.message;
  EXPECT_EQ(r.steps, 1);
}

// `stop` is asked before every step (a planner's time limit, issue 32): it ends the method with
// LimitReached after exactly the steps it allowed, and the frames reached so far stay closed.
TEST(CarpenterSpherical, StopEndsTheMethodBeforeTheNextStep) {
  std::mt19937 rng(7);
  const CreasePattern v = build_or_throw(gen::single_vertex(foldkit::test::random_sectors(12, rng, 0.2)));
  const FoldState folded = foldkit::test::random_vertex_state(v, 5);
  const CarpenterSphericalResult whole = flatten_single_vertex(v, folded);
  ASSERT_TRUE(whole.status.ok()) << whole.status.message;
  ASSERT_GT(whole.steps, 3);
  CarpenterSphericalOptions options;
  int asked = 0;
  options.stop = [&asked] { return ++asked > 3; };
  const CarpenterSphericalResult r = flatten_single_vertex(v, folded, options);
  EXPECT_EQ(r.status.code, foldkit::geometry::StatusCode::LimitReached);
  EXPECT_NE(r.status.message.find("asked to stop"), std::string::npos) << r.status.message;
  EXPECT_EQ(r.steps, 3);
  EXPECT_EQ(asked, 4);
  const ClosureSystem sys(v);
  for (const FoldState& f : r.frames) EXPECT_LT(sys.max_error(f), 1e-9);
  EXPECT_GT(r.frames.back().angles.cwiseAbs().maxCoeff(), 1e-3);  // not flat: stopped midway
}

// The flat state is its own flattening: no step, one frame besides the input.
TEST(CarpenterSpherical, FlatInputIsAlreadyFlat) {
  std::mt19937 rng(3);
  const CreasePattern p = build_or_throw(gen::single_vertex(foldkit::test::random_sectors(7, rng, 0.3)));
  const CarpenterSphericalResult r = flatten_single_vertex(p, FoldState::flat(p));
  EXPECT_TRUE(r.status.ok());
  EXPECT_EQ(r.steps, 0);
  EXPECT_EQ(r.frames.back().angles.cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace
