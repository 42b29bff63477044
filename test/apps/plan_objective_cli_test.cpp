// foldkit plan --objective / --cost-threshold (issue 38, item 2): the JSON's objective, cost and
// best cost over time, the cost checked against the travel of the written CMML (read back, not
// the planner's numbers), the threshold stopping early, and bad input as usage errors with
// nothing written.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "test_time.hpp"
#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/projection.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/pmml.hpp"

namespace {

using foldkit::test::foldkit;
using foldkit::test::temp_dir;
namespace geo = foldkit::geometry;

struct Case {
  std::string dir = temp_dir() + "/plan-objective-cli", pattern = dir + "/vertex.pmml", goal = dir + "/goal.cmml";
  geo::CreasePattern p = geo::build_or_throw(geo::generators::single_vertex({M_PI / 2, M_PI / 3, M_PI / 2, M_PI / 3, M_PI / 3}));
  geo::FoldState goal_state;
  Case() {
    std::filesystem::create_directories(dir);
    std::ofstream(pattern) << foldkit::io::write_pmml(p.to_spec());
    Eigen::VectorXd guess(5);
    guess << 0.9, -0.7, 0.9, 0.5, -0.5;
    geo::ProjectionOptions po;
    po.tolerance = 1e-12;
    goal_state = geo::project(geo::ClosureSystem(p), geo::FoldState{guess}, po).state;
    std::ofstream(goal) << foldkit::io::write_cmml(geo::sequence_to(p, goal_state, 0.5));
  }
};

// Σ|Δθ| of a CMML from flat: every event moves its creases straight to their targets.
double travel(const geo::CreasePattern& p, const geo::FoldSequence& seq) {
  std::map<int, double> angle;
  for (const auto& j : p.joints()) angle[j.id] = 0.0;
  double sum = 0.0;
  for (const auto& e : seq.events)
    for (const auto& f : e.folds) {
      sum += std::abs(f.angle - angle[f.joint_id]);
      angle[f.joint_id] = f.angle;
    }
  return sum;
}

TEST(PlanObjectiveCli, JsonReportsTheObjectiveItsCostAndTheBestCostOverTime) {
  const Case c;
  const std::string out = c.dir + "/rotation.cmml";
  // --no-fallback: on a single vertex the planner would have a quarter of --time inside the fallback.
  const auto r = foldkit({"plan", c.pattern, "--goal", c.goal, "--planner", "RRT*", "--objective", "rotation",
                          "--cost-threshold", "0", "--time", foldkit::test::scaled_arg(1.0), "--no-fallback", "-o", out,
                          "--json"});
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["objective"], "rotation");
  const double cost = j["cost"].get<double>();
  EXPECT_NEAR(cost, travel(c.p, foldkit::io::read_cmml(out)), 1e-6 * cost);
  EXPECT_GE(cost, c.goal_state.angles.lpNorm<1>() - 1e-9);  // no way from flat travels less than the straight one
  ASSERT_TRUE(j["cost_history"].is_array());
  ASSERT_FALSE(j["cost_history"].empty());
  double last_t = -1.0, last_c = INFINITY;
  for (const auto& point : j["cost_history"]) {
    ASSERT_EQ(point.size(), 2u);
    EXPECT_GT(point[0].get<double>(), last_t);
    EXPECT_LT(point[1].get<double>(), last_c);
    last_t = point[0].get<double>();
    last_c = point[1].get<double>();
  }
  EXPECT_LE(last_t, j["seconds"].get<double>() + 0.5);
  EXPECT_NE(r.err.find("objective rotation"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("cost "), std::string::npos) << r.err;
}

TEST(PlanObjectiveCli, LooseThresholdStopsLongBeforeTheTimeLimit) {
  const Case c;
  const auto r = foldkit({"plan", c.pattern, "--goal", c.goal, "--planner", "RRT*", "--objective", "length:1,rotation:1",
                          "--cost-threshold", "100", "--time", foldkit::test::scaled_arg(40.0), "--no-fallback", "-o",
                          c.dir + "/loose.cmml", "--json"});
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["objective"], "length:1,rotation:1");
  EXPECT_LT(j["seconds"].get<double>(), 0.25 * foldkit::test::scaled_seconds(40.0));
}

TEST(PlanObjectiveCli, BadObjectiveOrThresholdIsAUsageErrorAndWritesNothing) {
  const Case c;
  const std::string out = c.dir + "/never.cmml";
  for (const char* bad : {"speed", "length:-1", "length:x", "length,", "length,length"}) {
    const auto r = foldkit({"plan", c.pattern, "--goal", c.goal, "--objective", bad, "--time", "1", "-o", out});
    EXPECT_EQ(r.exit, 2) << bad;
    EXPECT_NE(r.err.find("--objective"), std::string::npos) << r.err;
    if (std::string(bad) != "length,length") {
      EXPECT_NE(r.err.find("length, rotation, clearance"), std::string::npos) << r.err;
    }
  }
  const auto sum = foldkit({"plan", c.pattern, "--goal", c.goal, "--objective", "clearance,length", "-o", out});
  EXPECT_EQ(sum.exit, 2);
  EXPECT_NE(sum.err.find("maximin"), std::string::npos) << sum.err;
  for (const char* bad : {"-1", "nan", "inf"}) {
    const auto r = foldkit({"plan", c.pattern, "--goal", c.goal, "--cost-threshold", bad, "--time", "1", "-o", out});
    EXPECT_EQ(r.exit, 2) << bad << ": " << r.err;
  }
  const auto informed = foldkit({"plan", c.pattern, "--goal", c.goal, "--planner", "BIT*", "--objective", "clearance", "-o", out});
  EXPECT_EQ(informed.exit, 2);
  EXPECT_NE(informed.err.find("no informed sampler"), std::string::npos) << informed.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace

namespace {

// `foldkit bench --list` lists the objective table: names in order, which can be summed, which
// informed planners can sample.
TEST(PlanObjectiveCli, BenchListsTheObjectivesWithTheirSamplers) {
  const auto r = foldkit({"bench", "--list", "--json"});
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto objectives = nlohmann::json::parse(r.out)["objectives"];
  ASSERT_EQ(objectives.size(), 3u);
  EXPECT_EQ(objectives[0]["name"], "length");
  EXPECT_EQ(objectives[2]["name"], "clearance");
  EXPECT_TRUE(objectives[1]["additive"].get<bool>() && objectives[1]["informed_sampler"].get<bool>());
  EXPECT_FALSE(objectives[2]["additive"].get<bool>() || objectives[2]["informed_sampler"].get<bool>());
}

}  // namespace
