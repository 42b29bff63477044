// Projected-velocity folding. Oracles that do not share its code: the Miura-ori closed form
// (NOTES.md), the closure residual evaluated afresh, geometry::mobility, the simulator's replay,
// the strip's collision angle by elementary geometry, and OrigamiSimulator's square twist.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/mobility.hpp"
#include "foldkit/folding/projected_folding.hpp"
#include "test_paths.hpp"

namespace {

namespace geo = foldkit::geometry;
namespace gen = foldkit::geometry::generators;
using foldkit::geometry::StatusCode;
using foldkit::folding::fold_projected;
using foldkit::folding::ProjectedFoldingOptions;
using foldkit::folding::ProjectedFoldingResult;

constexpr double kPi = 3.14159265358979323846;

double sign_of(geo::Assignment a) { return a == geo::Assignment::Mountain ? 1.0 : a == geo::Assignment::Valley ? -1.0 : 0.0; }

// The loop error at the midpoint of the chord from state i − 1 to state i.
double chord_error(const geo::ClosureSystem& system, const ProjectedFoldingResult& r, std::size_t i) {
  return system.max_error(geo::FoldState{0.5 * (r.states[i - 1].angles + r.states[i].angles)});
}

// Closed at every state (evaluated here, not taken from the result), no crease jumps, every
// chord within the chord tolerance, and the simulator replays the CMML without a problem.
void expect_valid_path(const geo::CreasePattern& p, const ProjectedFoldingResult& r, const ProjectedFoldingOptions& o) {
  const geo::ClosureSystem system(p);
  ASSERT_FALSE(r.states.empty());
  EXPECT_EQ(r.states.front().angles.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(r.steps + 1, static_cast<int>(r.states.size()));
  double largest_chord = 0.0;
  for (std::size_t i = 0; i < r.states.size(); ++i) {
    EXPECT_LE(system.max_error(r.states[i]), 1e-10) << "state " << i;
    if (i > 0) {
      EXPECT_LE((r.states[i].angles - r.states[i - 1].angles).cwiseAbs().maxCoeff(), 1.5 * o.max_step) << "state " << i;
      const double chord = chord_error(system, r, i);
      if (o.chord_tolerance > 0.0) {
        EXPECT_LE(chord, o.chord_tolerance) << "state " << i;
      }
      largest_chord = std::max(largest_chord, chord);
    }
  }
  EXPECT_NEAR(r.max_chord_error, largest_chord, 1e-12);
  EXPECT_LE(r.max_closure_error, 1e-10);
  ASSERT_TRUE(r.replay.has_value());
  EXPECT_TRUE(r.replay->status.ok()) << (r.replay->problems.empty() ? "" : r.replay->problems.front());
  EXPECT_EQ(geo::end_state(p, r.sequence).angles, r.states.back().angles);
}

// Every crease stays on the side of its assignment (0 allowed for flat/unassigned).
void expect_assignment_kept(const geo::CreasePattern& p, const ProjectedFoldingResult& r) {
  for (const auto& s : r.states)
    for (std::size_t j = 0; j < p.joints().size(); ++j)
      EXPECT_GE(s.angles[static_cast<Eigen::Index>(j)] * sign_of(p.joints()[j].assignment), 0.0) << "joint " << p.joints()[j].id;
}

TEST(ProjectedFolding, MiuraFollowsTheClosedFormToTheTarget) {
  const double phi = kPi / 3;
  const geo::CreasePattern p = geo::build_or_throw(gen::miura(4, 4, 1.0, 1.0, phi));
  ProjectedFoldingOptions o;
  o.target_fraction = 0.9;
  const ProjectedFoldingResult r = fold_projected(p, o);
  ASSERT_EQ(r.status.code, StatusCode::Success) << r.status.message;
  EXPECT_NEAR(r.fraction, 0.9, 1e-9);
  EXPECT_NEAR(r.states.back().angles.cwiseAbs().maxCoeff(), 0.9 * kPi, 1e-9);
  expect_valid_path(p, r, o);
  expect_assignment_kept(p, r);
  EXPECT_EQ(r.dof, 1);
  // Straight creases are the vertical ones; tan(ρ_straight/2) = cos φ · tan(ρ_zigzag/2) at every
  // vertex, so every crease of a kind has the same |angle|.
  for (std::size_t i = 1; i < r.states.size(); ++i) {
    double straight = -1.0, zigzag = -1.0;
    for (std::size_t j = 0; j < p.joints().size(); ++j) {
      const auto& joint = p.joints()[j];
      const double a = std::abs(r.states[i].angles[static_cast<Eigen::Index>(j)]);
      const bool vertical = std::abs(p.vertices()[joint.v[0]].x() - p.vertices()[joint.v[1]].x()) < 1e-12;
      double& kind = vertical ? straight : zigzag;
      if (kind < 0.0) kind = a;
      EXPECT_NEAR(a, kind, 1e-8) << "state " << i << " joint " << joint.id;
    }
    EXPECT_NEAR(std::tan(straight / 2), std::cos(phi) * std::tan(zigzag / 2), 1e-8 * (1 + std::tan(zigzag / 2))) << "state " << i;
  }
}

TEST(ProjectedFolding, WaterbombFoldsAlongItsAssignment) {
  const geo::CreasePattern p = geo::build_or_throw(gen::waterbomb(2, 2));
  const ProjectedFoldingResult r = fold_projected(p, {});
  ASSERT_EQ(r.status.code, StatusCode::Success) << r.status.message;
  expect_valid_path(p, r, {});
  expect_assignment_kept(p, r);
  EXPECT_NEAR(r.fraction, 0.9, 1e-9);
}

TEST(ProjectedFolding, BoatFoldsWithAGivenVelocityAndEndsWithOneDof) {
  const geo::CreasePattern p = geo::build_or_throw(gen::boat());
  ProjectedFoldingOptions o;
  // Keel ends mountain, keel middle valley, diagonals and transverse creases valley.
  o.velocity.resize(10);
  o.velocity << 1, -1, -1, 1, -1, -1, -1, -1, -1, -1;
  o.target_fraction = 0.5;
  const ProjectedFoldingResult r = fold_projected(p, o);
  ASSERT_EQ(r.status.code, StatusCode::Success) << r.status.message;
  expect_valid_path(p, r, o);
  const geo::ClosureSystem system(p);
  EXPECT_EQ(geo::mobility(system, r.states.back()).dof, 1);  // NOTES.md: the folded boat has 1 DOF
  EXPECT_EQ(r.dof, 1);
}

TEST(ProjectedFolding, ThrowsForAPatternWithoutAssignmentAndBadOptions) {
  const geo::CreasePattern boat = geo::build_or_throw(gen::boat());
  EXPECT_THROW(fold_projected(boat, {}), std::invalid_argument);
  ProjectedFoldingOptions o;
  o.velocity = Eigen::VectorXd::Ones(3);
  EXPECT_THROW(fold_projected(boat, o), std::invalid_argument);
  o.velocity = Eigen::VectorXd::Zero(10);
  EXPECT_THROW(fold_projected(boat, o), std::invalid_argument);
  const geo::CreasePattern miura = geo::build_or_throw(gen::miura(2, 2));
  for (double f : {0.0, -0.5, 1.5, std::nan("")}) {
    ProjectedFoldingOptions bad;
    bad.target_fraction = f;
    EXPECT_THROW(fold_projected(miura, bad), std::invalid_argument) << f;
  }
  ProjectedFoldingOptions bad;
  bad.max_step = 0.0;
  EXPECT_THROW(fold_projected(miura, bad), std::invalid_argument);
  for (double t : {-1e-5, 1e-10, 0.2, std::nan("")}) {
    ProjectedFoldingOptions chord;
    chord.chord_tolerance = t;
    EXPECT_THROW(fold_projected(miura, chord), std::invalid_argument) << t;
  }
}

// Steps sized by the chord tolerance: every chord's midpoint stays within it (expect_valid_path,
// evaluated afresh), the largest chord comes close to it (the steps are not needlessly short),
// the steps grow where the Miura-ori's path is straight (near flat and near folded) and shrink
// where it bends, and a tighter tolerance takes more steps, about as 1/√tolerance. Fixed steps
// (chord tolerance 0) keep to max_step.
TEST(ProjectedFolding, StepsFollowTheChordTolerance) {
  const geo::CreasePattern p = geo::build_or_throw(gen::miura(4, 4));
  std::map<double, int> steps;
  for (double tolerance : {1e-5, 2.5e-6}) {
    ProjectedFoldingOptions o;
    o.chord_tolerance = tolerance;
    const ProjectedFoldingResult r = fold_projected(p, o);
    SCOPED_TRACE(tolerance);
    ASSERT_EQ(r.status.code, StatusCode::Success) << r.status.message;
    expect_valid_path(p, r, o);
    EXPECT_GE(r.max_chord_error, 0.7 * tolerance);
    steps[tolerance] = r.steps;
    double shortest = 1.0, longest = 0.0;
    for (std::size_t i = 12; i + 1 < r.states.size(); ++i) {  // after the lead-in, before the landing
      const double h = (r.states[i].angles - r.states[i - 1].angles).cwiseAbs().maxCoeff();
      shortest = std::min(shortest, h), longest = std::max(longest, h);
    }
    EXPECT_GT(longest, 1.5 * shortest);
  }
  EXPECT_NEAR(static_cast<double>(steps[2.5e-6] - 10) / (steps[1e-5] - 10), 2.0, 0.2);
  ProjectedFoldingOptions fixed;
  fixed.max_step = 0.01;
  fixed.chord_tolerance = 0.0;
  const ProjectedFoldingResult r = fold_projected(p, fixed);
  ASSERT_EQ(r.status.code, StatusCode::Success) << r.status.message;
  expect_valid_path(p, r, fixed);
  EXPECT_GT(r.steps, steps[1e-5]);
  for (std::size_t i = 1; i < r.states.size(); ++i)
    EXPECT_LE((r.states[i].angles - r.states[i - 1].angles).cwiseAbs().maxCoeff(), 0.0105) << "state " << i;  // h, then corrected
}

// The second-order predictor walks the same curve as the first-order one (a 1-DOF Miura-ori
// ends in the same state) with about one Newton iteration per step instead of two (at short
// steps, where the O(h³) term is small).
TEST(ProjectedFolding, SecondOrderPredictorSavesNewtonIterations) {
  const geo::CreasePattern p = geo::build_or_throw(gen::miura(5, 4, 1.0, 1.2, 1.1));
  ProjectedFoldingOptions o;
  o.target_fraction = 0.8;
  o.chord_tolerance = 1e-5;
  o.replay = false;
  const ProjectedFoldingResult second = fold_projected(p, o);
  o.second_order_predictor = false;
  const ProjectedFoldingResult first = fold_projected(p, o);
  ASSERT_TRUE(second.status.ok()) << second.status.message;
  ASSERT_TRUE(first.status.ok()) << first.status.message;
  EXPECT_LE((second.states.back().angles - first.states.back().angles).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_LE(second.newton_iterations, 1.3 * second.steps);
  EXPECT_GE(first.newton_iterations, 1.7 * first.steps);
}

TEST(ProjectedFolding, SquareTwistIsReportedNotRigidlyFoldable) {
  for (double twist : {kPi / 3, kPi / 4, kPi / 6}) {
    const geo::CreasePattern p = geo::build_or_throw(gen::square_twist(1.0, twist, 1.0));
    const ProjectedFoldingResult r = fold_projected(p, {});
    EXPECT_EQ(r.status.code, StatusCode::NotRigidlyFoldable) << twist << ": " << r.status.message;
    EXPECT_EQ(r.states.size(), 1u);  // only the flat sheet: no garbage states
    EXPECT_EQ(r.fraction, 0.0);
    EXPECT_NE(r.status.message.find("does not fold rigidly"), std::string::npos) << r.status.message;
    EXPECT_TRUE(r.sequence.events.empty());
  }
}

// The generator: Kawasaki and Maekawa at the four corners, the sector angles of its doc, the
// counts of Euler's formula.
TEST(ProjectedFolding, SquareTwistGeneratorIsTheClassicTwist) {
  const double twist = 0.4;
  const geo::CreasePattern p = geo::build_or_throw(gen::square_twist(2.0, twist, 1.5));
  EXPECT_EQ(p.actors().size(), 9u);
  EXPECT_EQ(p.joints().size(), 12u);
  ASSERT_EQ(p.interior_vertices().size(), 4u);
  for (const auto& star : p.interior_vertices()) {
    ASSERT_EQ(star.joints.size(), 4u);
    std::vector<double> sectors = star.sectors;
    EXPECT_NEAR(sectors[0] + sectors[2], kPi, 1e-12);
    std::sort(sectors.begin(), sectors.end());
    EXPECT_NEAR(sectors[0], kPi / 2 - twist, 1e-12);
    EXPECT_NEAR(sectors[1], kPi / 2, 1e-12);
    EXPECT_NEAR(sectors[2], kPi / 2, 1e-12);
    EXPECT_NEAR(sectors[3], kPi / 2 + twist, 1e-12);
    double sum = 0.0;
    for (int j : star.joints) sum += sign_of(p.joints()[static_cast<std::size_t>(j)].assignment);
    EXPECT_EQ(std::abs(sum), 2.0);
  }
  // The square's sides (both ends interior) all fold the same way: the classic assignment.
  int sides = 0;
  for (const auto& j : p.joints())
    if (!p.is_boundary_vertex(j.v[0]) && !p.is_boundary_vertex(j.v[1])) {
      ++sides;
      EXPECT_EQ(j.assignment, geo::Assignment::Valley);
    }
  EXPECT_EQ(sides, 4);
  EXPECT_THROW(gen::square_twist(1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(gen::square_twist(1.0, kPi / 2), std::invalid_argument);
  EXPECT_THROW(gen::square_twist(-1.0), std::invalid_argument);
}

// OrigamiSimulator's single square twist (red mountain, blue valley, black border): the same
// sector angles and the same 3 : 1 split with the square's sides alike, at its twist of 60°.
TEST(ProjectedFolding, SquareTwistMatchesOrigamiSimulatorsTwist) {
  if (!foldkit::test::fixtures_available()) GTEST_SKIP() << "no shared fixtures";
  std::ifstream in(foldkit::test::fixture_path("svg/OrigamiSimulator__singlesquaretwist.svg"));
  ASSERT_TRUE(in.good());
  std::stringstream text;
  text << in.rdbuf();
  const std::string svg = text.str();
  struct Segment {
    double x0, y0, x1, y1;
    int sign;
  };
  std::vector<Segment> creases;
  const std::regex path(R"re(stroke="#([0-9A-F]{6})"[^>]*\sd="([^"]*)")re");
  const std::regex number(R"(-?[0-9]*\.?[0-9]+)");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), path); it != std::sregex_iterator(); ++it) {
    const std::string colour = (*it)[1], d = (*it)[2];
    if (colour == "000000") continue;
    std::vector<double> v;
    for (auto n = std::sregex_iterator(d.begin(), d.end(), number); n != std::sregex_iterator(); ++n) v.push_back(std::stod(n->str()));
    ASSERT_EQ(v.size() % 4, 0u);
    for (std::size_t k = 0; k < v.size(); k += 4)
      creases.push_back({v[k], v[k + 1], v[k] + v[k + 2], v[k + 1] + v[k + 3], colour == "FF0000" ? 1 : -1});
  }
  ASSERT_EQ(creases.size(), 12u);
  // Interior vertices: points where four creases meet (to the SVG's 0.01 px rounding).
  std::map<std::pair<long, long>, std::vector<std::pair<double, int>>> stars;
  for (const auto& c : creases)
    for (int end = 0; end < 2; ++end) {
      const double x = end ? c.x1 : c.x0, y = end ? c.y1 : c.y0, ox = end ? c.x0 : c.x1, oy = end ? c.y0 : c.y1;
      stars[{std::lround(x * 20), std::lround(y * 20)}].push_back({std::atan2(oy - y, ox - x), c.sign});
    }
  const geo::CreasePattern ours = geo::build_or_throw(gen::square_twist());
  std::vector<double> expected = ours.interior_vertices()[0].sectors;
  std::sort(expected.begin(), expected.end());
  int corners = 0;
  for (auto& [at, star] : stars) {
    if (star.size() != 4) continue;
    ++corners;
    std::sort(star.begin(), star.end());
    std::vector<double> sectors;
    int sum = 0;
    for (std::size_t k = 0; k < 4; ++k) {
      sectors.push_back(std::fmod(star[(k + 1) % 4].first - star[k].first + 2 * kPi, 2 * kPi));
      sum += star[k].second;
    }
    std::sort(sectors.begin(), sectors.end());
    for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(sectors[k], expected[k], 2e-3);
    EXPECT_EQ(std::abs(sum), 2);
  }
  EXPECT_EQ(corners, 4);
}

// Three panels, both creases mountain: the outer panels fold under the middle one and their free
// edges meet at 120° (|cos θ| = 1/2 for equal widths); the path must stop there.
TEST(ProjectedFolding, StripStopsAtTheCollision) {
  const geo::CreasePattern p = geo::build_or_throw(gen::strip(3));
  ProjectedFoldingOptions o;
  o.velocity = Eigen::VectorXd::Ones(2);
  const ProjectedFoldingResult r = fold_projected(p, o);
  ASSERT_EQ(r.status.code, StatusCode::Collision) << r.status.message;
  EXPECT_GT(r.fraction, 119.0 / 180.0);
  EXPECT_LE(r.fraction, 120.5 / 180.0);
  ASSERT_TRUE(r.replay.has_value());
  EXPECT_TRUE(r.replay->status.ok());  // the path up to the stop is collision-free
  // Without collision checks the same motion goes on to the target.
  o.collisions = false;
  EXPECT_EQ(fold_projected(p, o).status.code, StatusCode::Success);
}

// The chord corrector (one factorisation per step) and the corrector that refactors at every
// Newton iterate stop at the same tolerance. On a 1-DOF pattern (Miura-ori of several shapes) the
// closed states form one curve, so both walk it (every state closed to 1e-10), each leaving the
// prediction in its own direction and so spacing its states a little differently along it (by a
// quarter of a step after 300 steps), and both end where it reaches the target fraction. On a
// many-DOF pattern (waterbomb) each lands on its own nearby closed states; both paths must be
// valid.
TEST(ProjectedFolding, ChordCorrectorWalksTheSameCurve) {
  struct Case {
    geo::PatternSpec spec;
    double fraction;
    double tolerance;  // largest difference of the two paths' end states; < 0: not compared
  };
  std::vector<Case> cases = {{gen::miura(3, 5), 0.9, 1e-8},
                             {gen::miura(8, 8, 1.0, 1.5, 0.9), 0.8, 1e-8},
                             {gen::miura(12, 6, 0.7, 1.0, 1.3), 0.6, 1e-8},
                             {gen::waterbomb(2, 2), 0.3, -1.0}};
  for (const Case& c : cases) {
    const geo::CreasePattern p = geo::build_or_throw(c.spec);
    ProjectedFoldingOptions o;
    o.target_fraction = c.fraction;
    const ProjectedFoldingResult chord = fold_projected(p, o);
    o.chord_corrector = false;
    const ProjectedFoldingResult full = fold_projected(p, o);
    SCOPED_TRACE(p.title());
    ASSERT_EQ(chord.status.code, full.status.code) << chord.status.message << " / " << full.status.message;
    ASSERT_TRUE(chord.status.ok()) << chord.status.message;
    expect_valid_path(p, chord, o);
    expect_assignment_kept(p, chord);
    expect_valid_path(p, full, o);
    if (c.tolerance < 0.0) continue;
    EXPECT_LE(std::abs(chord.steps - full.steps), 1);
    EXPECT_LE((chord.states.back().angles - full.states.back().angles).cwiseAbs().maxCoeff(), c.tolerance);
  }
}

TEST(ProjectedFolding, SameInputSameOutput) {
  const geo::CreasePattern p = geo::build_or_throw(gen::miura(3, 3));
  ProjectedFoldingOptions o;
  o.target_fraction = 0.5;
  o.replay = false;
  const ProjectedFoldingResult a = fold_projected(p, o), b = fold_projected(p, o);
  ASSERT_EQ(a.states.size(), b.states.size());
  for (std::size_t i = 0; i < a.states.size(); ++i) EXPECT_EQ(a.states[i].angles, b.states[i].angles);
  EXPECT_EQ(a.newton_iterations, b.newton_iterations);
  EXPECT_EQ(a.sequence.events.size(), b.sequence.events.size());
}

// Folded all the way (fraction 1) the Miura-ori lies flat again, a singular state (the Jacobian
// drops rank there): the last step lands on it exactly, closed, and the simulator accepts the
// facets stacked flat.
TEST(ProjectedFolding, MiuraFoldsAllTheWayFlat) {
  const geo::CreasePattern p = geo::build_or_throw(gen::miura(3, 3));
  ProjectedFoldingOptions o;
  o.target_fraction = 1.0;
  const ProjectedFoldingResult r = fold_projected(p, o);
  ASSERT_EQ(r.status.code, StatusCode::Success) << r.status.message;
  EXPECT_NEAR(r.fraction, 1.0, 1e-9);
  expect_valid_path(p, r, o);
  // Flat-folded: every crease at ±π.
  EXPECT_NEAR(r.states.back().angles.cwiseAbs().minCoeff(), kPi, 1e-6);
}

// A singular stop is reported with the state where it happened and a path that is closed up to
// it (forced here by a conditioning threshold the Miura-ori crosses on its way: σ_min/σ_max falls
// as the sheet folds towards flat-folded).
TEST(ProjectedFolding, SingularStopKeepsAClosedPathAndSaysWhere) {
  const geo::CreasePattern p = geo::build_or_throw(gen::miura(3, 3));
  ProjectedFoldingOptions o;
  o.target_fraction = 1.0;
  o.replay = false;
  const ProjectedFoldingResult free_run = fold_projected(p, o);
  ASSERT_EQ(free_run.status.code, StatusCode::Success);
  o.singular_ratio = 2.0 * free_run.min_pivot_ratio;
  const ProjectedFoldingResult r = fold_projected(p, o);
  ASSERT_EQ(r.status.code, StatusCode::Singular) << r.status.message;
  EXPECT_NE(r.status.message.find("nearly singular"), std::string::npos) << r.status.message;
  EXPECT_LT(r.fraction, 1.0);
  EXPECT_GT(r.fraction, 0.0);
  const geo::ClosureSystem system(p);
  for (const auto& s : r.states) EXPECT_LE(system.max_error(s), 1e-10);
}

// Toward target angles: the Miura's closed-form state at a zigzag angle of 120 degrees. The fold
// stops when its largest angle reaches the fraction of the targets' largest, and there (the
// Miura has one DOF) every crease is at its target.
TEST(ProjectedFolding, TowardTheMiurasClosedFormReachesIt) {
  const double phi = kPi / 3;
  const geo::CreasePattern p = geo::build_or_throw(gen::miura(4, 4, 1.0, 1.0, phi));
  const auto target = [&](double zigzag) {
    const double straight = 2 * std::atan(std::cos(phi) * std::tan(zigzag / 2));
    Eigen::VectorXd angles(static_cast<Eigen::Index>(p.joints().size()));
    for (std::size_t j = 0; j < p.joints().size(); ++j) {
      const auto& joint = p.joints()[j];
      const bool vertical = std::abs(p.vertices()[joint.v[0]].x() - p.vertices()[joint.v[1]].x()) < 1e-12;
      angles[static_cast<Eigen::Index>(j)] = sign_of(joint.assignment) * (vertical ? straight : zigzag);
    }
    return angles;
  };
  ProjectedFoldingOptions o;
  o.toward = target(2 * kPi / 3);
  o.target_fraction = 1.0;
  const ProjectedFoldingResult r = fold_projected(p, o);
  ASSERT_EQ(r.status.code, StatusCode::Success) << r.status.message;
  expect_valid_path(p, r, o);
  ASSERT_TRUE(r.target_distance.has_value());
  EXPECT_LT(*r.target_distance, 1e-8);
  EXPECT_NEAR(r.fraction, 2.0 / 3.0, 1e-9);
  // Half way by the largest angle is the closed form at 60 degrees, not half of each target.
  o.target_fraction = 0.5;
  const ProjectedFoldingResult half = fold_projected(p, o);
  ASSERT_EQ(half.status.code, StatusCode::Success) << half.status.message;
  EXPECT_LT((half.states.back().angles - target(kPi / 3)).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_NEAR(*half.target_distance, (target(2 * kPi / 3) - target(kPi / 3)).cwiseAbs().maxCoeff(), 1e-8);
  // Without targets there is no distance.
  EXPECT_FALSE(fold_projected(p, {}).target_distance.has_value());
}

TEST(ProjectedFolding, TowardRefusesBadTargets) {
  const geo::CreasePattern p = geo::build_or_throw(gen::miura(2, 2));
  const auto n = static_cast<Eigen::Index>(p.joints().size());
  ProjectedFoldingOptions o;
  o.toward = Eigen::VectorXd::Zero(n);
  EXPECT_THROW(fold_projected(p, o), std::invalid_argument);  // flat: nothing to fold toward
  o.toward = Eigen::VectorXd::Constant(n, 4.0);
  EXPECT_THROW(fold_projected(p, o), std::invalid_argument);  // beyond 180 degrees
  o.toward = Eigen::VectorXd::Constant(n + 1, 1.0);
  EXPECT_THROW(fold_projected(p, o), std::invalid_argument);  // one per crease
  o.toward = Eigen::VectorXd::Constant(n, std::nan(""));
  EXPECT_THROW(fold_projected(p, o), std::invalid_argument);
  o.toward = Eigen::VectorXd::Constant(n, 1.0);
  o.velocity = Eigen::VectorXd::Constant(n, 1.0);
  EXPECT_THROW(fold_projected(p, o), std::invalid_argument);  // velocity or targets, not both
}

}  // namespace
