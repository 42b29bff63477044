// Planning from one folded state to another on a multi-DOF pattern (issue 16, item 2): the Resch
// tessellation (robbykraft/Origami, bench/data), folded out of flat to half along four desired
// crease velocities (random, U(0.05, 1) times the assignment's sign, written out below). A and B
// lie on sheets of the closed states that meet only at singular states: RRTConnect, Projected
// and Atlas found no plan between them in 5 s each, with collisions or without, while from flat
// each is planned in milliseconds (docs/PLANNING.md, *Start anywhere*). The oracle of a plan is
// the simulator's replay with collisions on, closure at every waypoint, and its ends.
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "foldkit/folding/projected_folding.hpp"
#include "foldkit/geometry/closure.hpp"
#include "foldkit/io/fold_format.hpp"
#include "foldkit/planners/plan.hpp"
#include "test_paths.hpp"

namespace {

using foldkit::geometry::ClosureSystem;
using foldkit::geometry::CreasePattern;
using foldkit::geometry::FoldState;
using foldkit::planners::plan;
using foldkit::planners::PlanRequest;
using foldkit::planners::PlanResult;

// Desired velocities as ID:VALUE,… (the joint IDs of the imported pattern).
const char* const kVelocityA =
      "1:-0.137,2:0.844,3:-0.289,4:-0.626,5:1.000,6:0.813,7:0.567,8:0.527,11:-0.877,12:-0.492,13:-0.912,"
      "14:-0.897,15:-0.582,16:-0.269,17:-0.359,18:0.535,19:0.999,20:0.995,21:0.807,22:-0.800,23:-0.394,"
      "24:-0.203,25:-0.729,26:-0.672,27:-0.516,28:-0.526,29:-0.679,30:-0.905,31:-0.383,32:0.512,33:0.944,"
      "34:-0.883,38:0.784,39:0.344,40:-0.346,41:-0.514,44:-0.937";
const char* const kVelocityB =
      "1:-0.338,2:0.505,3:-0.113,4:-0.572,5:0.810,6:0.261,7:0.313,8:0.836,11:-0.254,12:-0.837,13:-0.810,"
      "14:-0.207,15:-0.646,16:-0.132,17:-0.688,18:0.219,19:0.316,20:0.057,21:0.594,22:-0.856,23:-0.443,"
      "24:-0.459,25:-0.272,26:-0.822,27:-0.127,28:-0.645,29:-0.543,30:-0.716,31:-0.997,32:0.113,33:0.653,"
      "34:-0.312,38:0.464,39:0.653,40:-0.909,41:-0.847,44:-0.314";
const char* const kVelocityC =
      "1:-0.511,2:0.085,3:-0.680,4:-0.967,5:0.353,6:0.309,7:0.743,8:0.915,11:-0.233,12:-0.680,13:-0.852,"
      "14:-0.991,15:-0.810,16:-0.473,17:-0.768,18:0.143,19:0.609,20:0.837,21:0.512,22:-0.539,23:-0.652,"
      "24:-0.622,25:-0.390,26:-0.135,27:-0.161,28:-0.347,29:-0.411,30:-0.181,31:-0.842,32:0.229,33:0.066,"
      "34:-0.580,38:0.406,39:0.325,40:-0.101,41:-0.614,44:-0.141";
const char* const kVelocityD =
      "1:-0.633,2:0.182,3:-0.371,4:-0.903,5:0.367,6:0.742,7:0.718,8:0.954,11:-0.199,12:-0.099,13:-0.531,"
      "14:-0.785,15:-0.800,16:-0.923,17:-0.691,18:0.895,19:0.916,20:0.317,21:0.240,22:-0.885,23:-0.901,"
      "24:-0.182,25:-0.453,26:-0.966,27:-0.165,28:-0.901,29:-0.364,30:-0.177,31:-0.526,32:0.561,33:0.449,"
      "34:-0.233,38:0.716,39:0.214,40:-0.101,41:-0.758,44:-0.165";

CreasePattern resch() {
  return foldkit::io::read_fold(std::string(FOLDKIT_TEST_DATA) + "/../../bench/data/robbykraft_resch-tess.fold").pattern;
}

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

PlanRequest between(const CreasePattern& p, const foldkit::folding::ProjectedFoldingResult& from,
                    const foldkit::folding::ProjectedFoldingResult& to) {
  PlanRequest req;
  req.pattern = &p;
  req.start = foldkit::geometry::end_state(p, from.sequence);
  req.start_sequence = from.sequence;
  req.goal = foldkit::geometry::end_state(p, to.sequence);
  req.time = 4.0;
  return req;
}

void expect_valid_plan(const ClosureSystem& sys, const PlanRequest& req, const PlanResult& r) {
  ASSERT_TRUE(r.status.ok()) << r.status.message;
  ASSERT_TRUE(r.replay && r.replay->status.ok());
  for (const FoldState& w : r.waypoints) EXPECT_LE(sys.max_error(w), 1e-10);
  EXPECT_LT((r.waypoints.front().angles - req.start->angles).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((r.waypoints.back().angles - req.goal.angles).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(PlanViaFlat, FoldedStatesOnSheetsThatMeetOnlyAtFlat) {
  const CreasePattern p = resch();
  const ClosureSystem sys(p);
  const auto a = folded(p, kVelocityA), b = folded(p, kVelocityB);
  ASSERT_TRUE(a.status.ok() && b.status.ok()) << a.status.message << " / " << b.status.message;
  const PlanRequest req = between(p, a, b);
  const PlanResult r = plan(req);
  expect_valid_plan(sys, req, r);
  EXPECT_TRUE(r.via_flat);
  EXPECT_TRUE(r.fallback);
  EXPECT_EQ(r.space, "driving");
  EXPECT_LE(r.time, req.time + 0.5);
  double nearest_flat = 1.0;
  for (const FoldState& w : r.waypoints) nearest_flat = std::min(nearest_flat, w.angles.cwiseAbs().maxCoeff());
  EXPECT_EQ(nearest_flat, 0.0);
  RecordProperty("message", r.status.message);
}

// Before, this pair (start near a fold of the goal's chart) was found by RRTConnect in 5 ms and
// then refused as "the planned path jumps": OMPL's path.interpolate() spaced the densified path
// by the driving distance, too coarsely where the passives move fast. Now the space's own
// motions are halved to the waypoint step; the plan is direct, not via flat.
TEST(PlanViaFlat, NearAFoldOfTheChartTheDirectPlanIsDensifiedAlongTheSpace) {
  const CreasePattern p = resch();
  const ClosureSystem sys(p);
  const auto c = folded(p, kVelocityC), d = folded(p, kVelocityD);
  ASSERT_TRUE(c.status.ok() && d.status.ok()) << c.status.message << " / " << d.status.message;
  PlanRequest req = between(p, c, d);
  req.fallback = false;
  const PlanResult r = plan(req);
  expect_valid_plan(sys, req, r);
  EXPECT_FALSE(r.via_flat);
  for (std::size_t i = 1; i < r.waypoints.size(); ++i)
    EXPECT_LE((r.waypoints[i].angles - r.waypoints[i - 1].angles).cwiseAbs().maxCoeff(), 2.0 * req.waypoint_step + 1e-12);
}

}  // namespace
