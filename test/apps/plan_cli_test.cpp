// foldkit plan: exit codes, JSON keys, byte-identical output for one seed, and the simulator's
// verdict on the written CMML (oracle: `foldkit simulate`, a separate verb).
#include <algorithm>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "resch_states.hpp"
#include "test_time.hpp"
#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/pmml.hpp"

namespace {

using foldkit::test::foldkit;
using foldkit::test::slurp;
using foldkit::test::temp_dir;
namespace geo = foldkit::geometry;

struct Case {
  std::string dir, pattern, goal, bad_goal;
};

Case make_case() {
  Case c{temp_dir() + "/plan-cli", "", "", ""};
  std::filesystem::create_directories(c.dir);
  const double pi = 3.14159265358979323846;
  const geo::CreasePattern p = geo::build_or_throw(geo::generators::single_vertex({pi / 2, pi / 3, pi / 2, pi / 3, pi / 3}));
  c.pattern = c.dir + "/vertex.pmml";
  std::ofstream(c.pattern) << foldkit::io::write_pmml(p.to_spec());
  // A mildly folded closed goal: a guess projected onto the closure manifold, signs kept.
  Eigen::VectorXd guess(5);
  guess << 0.5, -0.4, 0.5, 0.3, -0.3;
  geo::ProjectionOptions po;
  po.tolerance = 1e-12;
  const auto r = geo::project(geo::ClosureSystem(p), geo::FoldState{guess}, po);
  EXPECT_TRUE(r.status.ok());
  c.goal = c.dir + "/goal.cmml";
  std::ofstream(c.goal) << foldkit::io::write_cmml(geo::sequence_to(p, r.state, 0.5));
  c.bad_goal = c.dir + "/open.cmml";
  std::ofstream(c.bad_goal) << foldkit::io::write_cmml(geo::sequence_to(p, geo::FoldState{guess}, 0.5));
  return c;
}

TEST(PlanCli, PlansFromFlatAndTheSimulatorAcceptsThePlan) {
  const Case c = make_case();
  const std::string out = c.dir + "/plan.cmml";
  const auto r = foldkit({"plan", c.pattern, "--goal", c.goal, "--planner", "RRTConnect", "--time", "2", "--seed", "4",
                          "-o", out, "--json"});
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"solved", "planner", "space", "fallback", "time", "path_length", "max_closure_error", "waypoints"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_TRUE(j["solved"].get<bool>());
  EXPECT_FALSE(j["fallback"].get<bool>());
  EXPECT_LT(j["max_closure_error"].get<double>(), 1e-3);
  const auto sim = foldkit({"simulate", c.pattern, out, "--json"});
  EXPECT_EQ(sim.exit, 0) << sim.err;
}

TEST(PlanCli, SameSeedGivesTheSameFile) {
  const Case c = make_case();
  const std::string a = c.dir + "/a.cmml", b = c.dir + "/b.cmml";
  for (const auto& out : {a, b})
    ASSERT_EQ(foldkit({"plan", c.pattern, "--goal", c.goal, "--planner", "RRTConnect", "--time", "2", "--seed", "9",
                       "--no-collision", "-o", out})
                  .exit,
              0);
  EXPECT_EQ(slurp(a), slurp(b));
}

TEST(PlanCli, BadInputAndUsage) {
  const Case c = make_case();
  const std::string out = c.dir + "/never.cmml";
  EXPECT_EQ(foldkit({"plan", c.pattern, "--goal", c.goal, "--planner", "NoSuchPlanner", "-o", out}).exit, 2);
  EXPECT_EQ(foldkit({"plan", c.pattern, "--goal", c.goal, "--space", "nonsense", "-o", out}).exit, 2);
  EXPECT_EQ(foldkit({"plan", c.pattern, "--goal", c.bad_goal, "--time", "1", "-o", out}).exit, 1);
  EXPECT_EQ(foldkit({"plan", c.pattern, "--goal", c.dir + "/missing.cmml", "-o", out}).exit, 1);
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace

namespace {

// A goal given by two creases' angles: the plan ends with those creases exactly there, closed
// (the simulator replays it), and impossible or malformed angle lists are refused.
TEST(PlanCli, GoalAnglesForSomeCreases) {
  const Case c = make_case();
  const std::string out = c.dir + "/angles.cmml";
  const auto r = foldkit({"plan", c.pattern, "--goal-angles", "1:30,3:-20", "--planner", "RRTConnect", "--time", "2",
                          "--seed", "4", "--no-collision", "-o", out, "--json"});
  ASSERT_EQ(r.exit, 0) << r.err;
  EXPECT_TRUE(nlohmann::json::parse(r.out)["solved"].get<bool>());
  const auto sim = foldkit({"simulate", c.pattern, out, "--json", "--no-collision"});
  ASSERT_EQ(sim.exit, 0) << sim.err;
  const auto angles = nlohmann::json::parse(sim.out)["final_angles"];
  EXPECT_NEAR(angles[0]["angle"].get<double>(), 30.0, 1e-9);
  EXPECT_NEAR(angles[2]["angle"].get<double>(), -20.0, 1e-9);
  for (const char* bad : {"1:30,9:10", "1:30,1:20", "1:200", "one:30", "1=30"})
    EXPECT_EQ(foldkit({"plan", c.pattern, "--goal-angles", bad, "--time", "1", "-o", out}).exit, 2) << bad;
  EXPECT_EQ(foldkit({"plan", c.pattern, "--goal", c.goal, "--goal-angles", "1:30", "--time", "1", "-o", out}).exit, 2);
  EXPECT_EQ(foldkit({"plan", c.pattern, "--time", "1", "-o", out}).exit, 2);
  // Four of five creases held near 180 degrees: one free crease cannot close three loop equations.
  std::filesystem::remove(out);
  const auto none = foldkit({"plan", c.pattern, "--goal-angles", "1:179,2:-179,3:179,4:-179", "--time", "1", "-o", out, "--json"});
  EXPECT_EQ(none.exit, 4) << none.err;
  const auto j = nlohmann::json::parse(none.out);
  EXPECT_FALSE(j["solved"].get<bool>());
  EXPECT_EQ(j["status"], "no-progress");
  EXPECT_EQ(j["message"].get<std::string>().rfind("no closed goal state", 0), 0u);
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace

namespace {

// The demo's folded Miura-ori as a goal, through the projected space with a search margin: OMPL
// 1.5.2's own Newton projection aborted inside Eigen's SVD here (regression).
TEST(PlanCli, MiuraFromTheDemoThroughTheProjectedSpace) {
  const std::string dir = temp_dir();
  ASSERT_EQ(foldkit({"demo", "-o", dir}).exit, 0);
  const std::string out = dir + "/miura-plan.cmml";
  const auto r = foldkit({"plan", dir + "/miura-4x4.pmml", "--goal", dir + "/miura-4x4-folded.cmml", "--space", "projected",
                          "--search-margin", "0.2", "--time", "5", "--seed", "2", "-o", out, "--json"});
  ASSERT_EQ(r.exit, 0) << r.err;
  EXPECT_EQ(foldkit({"simulate", dir + "/miura-4x4.pmml", out}).exit, 0);
}

}  // namespace

namespace {

// Planner parameters by OMPL's names (--param NAME=VALUE): a known one plans, an unknown one or a
// malformed one is a usage error (exit 2) that names what the planner has, and writes nothing.
TEST(PlanCli, PlannerParametersByName) {
  const Case c = make_case();
  const std::string out = c.dir + "/param.cmml";
  std::filesystem::remove(out);
  const auto ok = foldkit({"plan", c.pattern, "--goal", c.goal, "--param", "range=0.3", "--param", "intermediate_states=1",
                           "--time", "2", "--seed", "4", "-o", out, "--json"});
  ASSERT_EQ(ok.exit, 0) << ok.err;
  EXPECT_TRUE(nlohmann::json::parse(ok.out)["solved"].get<bool>()) << ok.out;  // stdout holds the JSON alone
  EXPECT_TRUE(std::filesystem::exists(out));
  std::filesystem::remove(out);
  const auto unknown = foldkit({"plan", c.pattern, "--goal", c.goal, "--param", "nonsense=1", "-o", out});
  EXPECT_EQ(unknown.exit, 2);
  EXPECT_NE(unknown.err.find("no parameter 'nonsense'"), std::string::npos) << unknown.err;
  EXPECT_NE(unknown.err.find("range"), std::string::npos) << unknown.err;
  const auto refused = foldkit({"plan", c.pattern, "--goal", c.goal, "--param", "range=fast", "-o", out});
  EXPECT_EQ(refused.exit, 2) << refused.err;
  const auto malformed = foldkit({"plan", c.pattern, "--goal", c.goal, "--param", "range", "-o", out});
  EXPECT_EQ(malformed.exit, 2);
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace

namespace {

// A start or goal that does not close is named by its own file, at the line where its sequence
// ends (the last fold of its last event), not always by the goal file at line 0; nothing written.
TEST(PlanCli, AnEndThatDoesNotCloseIsNamedByItsFileAndLine) {
  const Case c = make_case();
  const std::string out = c.dir + "/never.cmml";
  std::filesystem::remove(out);
  // The line of the file's last <Fold> element, counted here from the text.
  const std::string text = slurp(c.bad_goal);
  const std::size_t at = text.rfind("<Fold>");
  ASSERT_NE(at, std::string::npos);
  const std::string where = c.bad_goal + ":" + std::to_string(1 + std::count(text.begin(), text.begin() + static_cast<long>(at), '\n')) + ":";
  const auto goal = foldkit({"plan", c.pattern, "--goal", c.bad_goal, "-o", out});
  EXPECT_EQ(goal.exit, 1);
  EXPECT_NE(goal.err.find(where + " plan: the goal is not closed"), std::string::npos) << where << '\n' << goal.err;
  const auto start = foldkit({"plan", c.pattern, "--goal", c.goal, "--start", c.bad_goal, "-o", out});
  EXPECT_EQ(start.exit, 1);
  EXPECT_NE(start.err.find(where + " plan: the start is not closed"), std::string::npos) << where << '\n' << start.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// The single-vertex fallback (issue 16, item 4): RRTConnect held to steps of 1e-7 rad finds
// nothing in its quarter of --time, and Carpenter's path is the plan, which the simulator accepts;
// --no-fallback turns it off (exit 4, nothing written). Both end on time: RRTConnect's connect
// loop, which does not look at the clock, ran for hours at this range before FoldValidity's time
// limit (the ctest timeout catches a regression).
TEST(PlanCli, SingleVertexFallbackAndNoFallback) {
  const Case c = make_case();
  const std::string out = c.dir + "/fallback.cmml";
  std::filesystem::remove(out);
  // The search keeps to --time, Carpenter's path included: scaled for sanitizer builds.
  const auto r = foldkit({"plan", c.pattern, "--goal", c.goal, "--planner", "RRTConnect", "--param", "range=1e-7", "--time",
                          foldkit::test::scaled_arg(0.4), "-o", out, "--json"});
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["fallback"].get<bool>());
  EXPECT_NE(j["message"].get<std::string>().find("Carpenter"), std::string::npos);
  EXPECT_EQ(foldkit({"simulate", c.pattern, out}).exit, 0);
  std::filesystem::remove(out);
  const auto none = foldkit(
      {"plan", c.pattern, "--goal", c.goal, "--planner", "RRTConnect", "--param", "range=1e-7", "--time", "0.4", "--no-fallback", "-o",
       out, "--json"});
  EXPECT_EQ(none.exit, 4) << none.err;
  EXPECT_FALSE(nlohmann::json::parse(none.out)["fallback"].get<bool>());
  EXPECT_LT(nlohmann::json::parse(none.out)["time"].get<double>(), 4.0);  // 0.4 s asked; 10× slack for sanitizers
  EXPECT_FALSE(std::filesystem::exists(out));
}

// A folded start and a goal on a sheet no motion of one driving space reaches (Resch A → B,
// test/support/resch_states.hpp): the plan goes through flat (JSON via_flat), the start's CMML
// comes first and `foldkit simulate` accepts the whole file; with --no-fallback it is exit 4
// within its time and nothing is written.
TEST(PlanCli, FoldedStartPlansThroughFlat) {
  const std::string dir = temp_dir() + "/plan-via-flat", a = dir + "/a.cmml", b = dir + "/b.cmml", out = dir + "/plan.cmml";
  std::filesystem::create_directories(dir);
  const std::string resch = foldkit::test::resch_path();
  ASSERT_EQ(foldkit({"fold", resch, "--fraction", "0.5", "--velocity", foldkit::test::kReschVelocityA, "-o", a}).exit, 0);
  ASSERT_EQ(foldkit({"fold", resch, "--fraction", "0.5", "--velocity", foldkit::test::kReschVelocityB, "-o", b}).exit, 0);
  std::filesystem::remove(out);
  const auto r = foldkit({"plan", resch, "--start", a, "--goal", b, "--time", "2", "-o", out, "--json"});
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["via_flat"].get<bool>());
  EXPECT_TRUE(j["fallback"].get<bool>());
  EXPECT_NE(j["message"].get<std::string>().find("via flat"), std::string::npos) << j["message"];
  const auto sim = foldkit({"simulate", resch, out, "--json"});
  EXPECT_EQ(sim.exit, 0) << sim.err;
  // The plan starts with the start's own sequence (the fold of A), event for event.
  const auto start = foldkit::io::read_cmml(a), plan = foldkit::io::read_cmml(out);
  ASSERT_GT(plan.events.size(), start.events.size());
  for (std::size_t e = 0; e < start.events.size(); ++e) {
    ASSERT_EQ(plan.events[e].folds.size(), start.events[e].folds.size()) << "event " << e;
    for (std::size_t k = 0; k < start.events[e].folds.size(); ++k) {
      EXPECT_EQ(plan.events[e].folds[k].joint_id, start.events[e].folds[k].joint_id);
      EXPECT_DOUBLE_EQ(plan.events[e].folds[k].angle, start.events[e].folds[k].angle);
    }
  }
  std::filesystem::remove(out);
  const auto none = foldkit({"plan", resch, "--start", a, "--goal", b, "--time", "0.5", "--no-fallback", "-o", out, "--json"});
  EXPECT_EQ(none.exit, 4) << none.err;
  EXPECT_FALSE(nlohmann::json::parse(none.out)["via_flat"].get<bool>());
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
