// The simulator at the edges of its inputs: long sequences, slivers, high degree, big sheets.
#include <cmath>

#include <gtest/gtest.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/simulation/simulate.hpp"

namespace foldkit::simulation {
namespace {

namespace gen = geometry::generators;
using geometry::build_or_throw;
using geometry::CreasePattern;
using geometry::FoldSequence;
using geometry::FoldState;

bool finite(const SimulationReport& r) {
  if (!std::isfinite(r.max_closure_error) || !std::isfinite(r.duration)) return false;
  for (const auto& c : r.collisions)
    if (!c.point.allFinite() || !std::isfinite(c.time)) return false;
  return r.final_state.angles.allFinite();
}

TEST(SimulateExtremes, TenThousandEvents) {
  const CreasePattern strip = build_or_throw(gen::strip(3));
  FoldSequence seq{"long", {}};
  for (int e = 0; e < 10000; ++e)
    seq.events.push_back({e, {{1 + e % 2, (e % 3 - 1) * 0.3, 100.0, 0}}});
  const SimulationReport r = simulate(strip, seq);
  EXPECT_TRUE(r.status.ok());
  EXPECT_EQ(r.events.size(), 10000u);
  EXPECT_TRUE(finite(r));
}

// Sectors of 1e-6 rad: the sweep bound stops at 1/1000 of the sheet, so the check count stays
// bounded, and the mode (NOTES.md closed form) still replays closed.
TEST(SimulateExtremes, SliverSectors) {
  const double alpha = 1e-6, beta = M_PI / 2;
  const CreasePattern p = build_or_throw(gen::single_vertex({alpha, beta, M_PI - alpha, M_PI - beta}));
  std::vector<FoldState> path;
  for (int i = 1; i <= 40; ++i) {
    const double t = 1.5 * i / 40;
    FoldState s = FoldState::flat(p);
    const double r1 = 2 * std::atan(-std::cos((alpha + beta) / 2) / std::cos((alpha - beta) / 2) * std::tan(t / 2));
    s.angles << t, r1, t, -r1;
    path.push_back(s);
  }
  const SimulationReport r = simulate(p, geometry::path_sequence(p, path, 1.0));
  EXPECT_TRUE(r.status.ok()) << (r.problems.empty() ? "" : r.problems.front());
  EXPECT_LT(r.checks, 200000u);
  EXPECT_TRUE(finite(r));
}

// A degree-256 vertex folded a little along a closed path: every fan pair is near every other.
TEST(SimulateExtremes, DegreeTwoFiftySix) {
  const CreasePattern p = build_or_throw(gen::single_vertex(std::vector<double>(256, 2 * M_PI / 256)));
  const geometry::ClosureSystem sys(p);
  FoldState rough = FoldState::flat(p);
  for (Eigen::Index j = 0; j < rough.angles.size(); ++j) rough.angles[j] = (j % 2 ? -0.02 : 0.02);
  const auto closed = geometry::project(sys, rough);
  ASSERT_TRUE(closed.status.ok());
  const SimulationReport r = simulate(p, geometry::path_sequence(p, {closed.state}, 0.5));
  EXPECT_TRUE(finite(r));
  EXPECT_LT(r.max_closure_error, 1e-3);
  EXPECT_TRUE(r.collisions.empty()) << "actors " << r.collisions.front().actors[0] << ", " << r.collisions.front().actors[1];
}

TEST(SimulateExtremes, HundredByHundredMiuraStep) {
  const CreasePattern miura = build_or_throw(gen::miura(100, 100));
  const geometry::ClosureSystem sys(miura);
  FoldState rough = FoldState::flat(miura);
  for (std::size_t j = 0; j < miura.joints().size(); ++j)
    rough.angles[static_cast<Eigen::Index>(j)] = miura.joints()[j].assignment == geometry::Assignment::Mountain ? 0.05 : -0.05;
  const auto closed = geometry::project(sys, rough);
  ASSERT_TRUE(closed.status.ok());
  SimulationOptions o;
  o.time_step = 1.0;
  const SimulationReport r = simulate(miura, geometry::path_sequence(miura, {closed.state}, 0.5), o);
  EXPECT_TRUE(r.status.ok()) << (r.problems.empty() ? "" : r.problems.front());
  EXPECT_TRUE(finite(r));
}

}  // namespace
}  // namespace foldkit::simulation
