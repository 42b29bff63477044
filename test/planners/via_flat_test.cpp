// Planning from one folded state to another on a multi-DOF pattern (issue 16, item 2): the Resch
// tessellation (robbykraft/Origami, bench/data), folded out of flat to half along four desired
// crease velocities (random, U(0.05, 1) times the assignment's sign, written out below). A and B
// lie on sheets of the closed states that meet only at singular states: RRTConnect, Projected
// and Atlas found no plan between them in 5 s each, with collisions or without, while from flat
// each is planned in milliseconds (docs/PLANNING.md, *Start anywhere*). The oracle of a plan is
// the simulator's replay with collisions on, closure at every waypoint, and its ends.
#include <future>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "foldkit/folding/projected_folding.hpp"
#include "foldkit/geometry/closure.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/fold_format.hpp"
#include "foldkit/planners/plan.hpp"
#include "foldkit/planners/plan_setup.hpp"
#include "resch_states.hpp"

namespace {

using foldkit::geometry::ClosureSystem;
using foldkit::geometry::CreasePattern;
using foldkit::geometry::FoldState;
using foldkit::planners::plan;
using foldkit::planners::PlanOptions;
using foldkit::planners::PlanResult;

using foldkit::test::kReschVelocityA;
using foldkit::test::kReschVelocityB;
using foldkit::test::kReschVelocityC;
using foldkit::test::kReschVelocityD;

CreasePattern resch() { return foldkit::io::read_fold(foldkit::test::resch_path()).pattern; }

// The pattern folded out of flat along `velocity` to half of 180°, with its sequence from flat.
foldkit::folding::ProjectedFoldingResult folded(const CreasePattern& p, const std::string& velocity) {
  foldkit::folding::ProjectedFoldingOptions o;
  o.velocity = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(p.joints().size()));
  std::istringstream in(velocity);
  std::string item;
  while (std::getline(in, item, ',')) {
    const int id = std::stoi(item.substr(0, item.find(':')));
    for (std::size_t j = 0; j < p.joints().size(); ++j)
      if (p.joints()[j].id == id) o.velocity[static_cast<Eigen::Index>(j)] = std::stod(item.substr(item.find(':') + 1));
  }
  o.target_fraction = 0.5;
  return foldkit::folding::fold_projected(p, o);
}

// Options for a plan from `from`'s end (its sequence first), within 4 s.
PlanOptions starting_at(const CreasePattern& p, const foldkit::folding::ProjectedFoldingResult& from) {
  PlanOptions req;
  req.start = foldkit::geometry::end_state(p, from.sequence);
  req.start_sequence = from.sequence;
  req.time = 4.0;
  return req;
}

void expect_valid_plan(const ClosureSystem& sys, const PlanOptions& req, const FoldState& goal, const PlanResult& r) {
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_TRUE(r.replay && r.replay->status.ok());
  for (const FoldState& w : r.waypoints) EXPECT_LE(sys.max_error(w), 1e-10);
  EXPECT_LT((r.waypoints.front().angles - req.start->angles).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((r.waypoints.back().angles - goal.angles).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(PlanViaFlat, FoldedStatesOnSheetsThatMeetOnlyAtFlat) {
  const CreasePattern p = resch();
  const ClosureSystem sys(p);
  const auto a = folded(p, kReschVelocityA), b = folded(p, kReschVelocityB);
  ASSERT_TRUE(a.status.ok() && b.status.ok()) << a.status.message << " / " << b.status.message;
  const PlanOptions req = starting_at(p, a);
  const FoldState goal = foldkit::geometry::end_state(p, b.sequence);
  EXPECT_FALSE(foldkit::planners::make_plan_setup(p, goal, req).continues_to_goal);
  // PlanOptions::sequence_ready: once, for the plan's own sequence (not the legs'), before the
  // replay reports any progress.
  PlanOptions watched = req;
  int ready = 0;
  bool replay_began = false, ready_before_replay = false;
  foldkit::geometry::FoldSequence handed;
  watched.progress = [&](const foldkit::geometry::Progress&) { replay_began = true; };
  watched.sequence_ready = [&](const foldkit::geometry::FoldSequence& s) {
    ++ready;
    ready_before_replay = !replay_began;
    // Read on another thread, as `foldkit plan` writes it: plan() waits for it.
    return std::async(std::launch::async, [&handed, &s] { handed = s; });
  };
  const PlanResult r = plan(p, goal, watched);
  expect_valid_plan(sys, req, goal, r);
  EXPECT_EQ(ready, 1);
  EXPECT_TRUE(ready_before_replay);
  EXPECT_EQ(foldkit::io::write_cmml(handed), foldkit::io::write_cmml(r.sequence));
  EXPECT_TRUE(r.via_flat);
  EXPECT_TRUE(r.fallback);
  EXPECT_EQ(r.space, "driving");
  EXPECT_LE(r.seconds, req.time + 0.5);
  double nearest_flat = 1.0;
  for (const FoldState& w : r.waypoints) nearest_flat = std::min(nearest_flat, w.angles.cwiseAbs().maxCoeff());
  EXPECT_EQ(nearest_flat, 0.0);
  RecordProperty("message", r.status.message);
  // Out of time on the way through flat: a status that names the leg, not an exception.
  PlanOptions hurried = req;
  hurried.time = 1e-3;
  const PlanResult late = plan(p, goal, hurried);
  EXPECT_EQ(late.status.code, foldkit::geometry::StatusCode::LimitReached) << late.status.message;
  EXPECT_NE(late.status.message.find("via flat: no plan from flat to the start"), std::string::npos) << late.status.message;
  EXPECT_FALSE(late.via_flat);
}

// Before, this pair (start near a fold of the goal's chart) was found by RRTConnect in 5 ms and
// then refused as "the planned path jumps": OMPL's path.interpolate() spaced the densified path
// by the driving distance, too coarsely where the passives move fast. Now the space's own
// motions are halved to the waypoint step; the plan is direct, not via flat.
TEST(PlanViaFlat, NearAFoldOfTheChartTheDirectPlanIsDensifiedAlongTheSpace) {
  const CreasePattern p = resch();
  const ClosureSystem sys(p);
  const auto c = folded(p, kReschVelocityC), d = folded(p, kReschVelocityD);
  ASSERT_TRUE(c.status.ok() && d.status.ok()) << c.status.message << " / " << d.status.message;
  PlanOptions req = starting_at(p, c);
  const FoldState goal = foldkit::geometry::end_state(p, d.sequence);
  req.fallback = false;
  const PlanResult r = plan(p, goal, req);
  expect_valid_plan(sys, req, goal, r);
  EXPECT_FALSE(r.via_flat);
  for (std::size_t i = 1; i < r.waypoints.size(); ++i)
    EXPECT_LE((r.waypoints[i].angles - r.waypoints[i - 1].angles).cwiseAbs().maxCoeff(), 2.0 * req.waypoint_step + 1e-12);
}

}  // namespace
