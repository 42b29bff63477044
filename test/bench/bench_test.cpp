// foldkit bench, library side: scenes (goals checked by the closure system and the simulator's
// collision world, not by the code that drew them), the shard split, OMPL logs (parsed back,
// merged), the deterministic-planner wrapper and the clearance measure (closed forms).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/bench/deterministic_planner.hpp"
#include "foldkit/bench/log.hpp"
#include "foldkit/bench/run.hpp"
#include "foldkit/bench/scenes.hpp"
#include "foldkit/planners/carpenter_fallback.hpp"
#include "foldkit/simulation/collision_world.hpp"
#include "foldkit/statespaces/single_vertex_space.hpp"
#include "test_paths.hpp"

namespace {

namespace fp = foldkit::bench;
using foldkit::geometry::ClosureSystem;
using foldkit::geometry::FoldState;

std::string temp_folder(const std::string& name) {
  const auto dir = std::filesystem::path(foldkit::test::temp_dir()) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

TEST(BenchSuite, EveryScenesGoalIsClosedValidAndDrawnFromTheSeed) {
  for (const std::string& name : fp::bench_scene_names()) {
    SCOPED_TRACE(name);
    const fp::BenchScene a = fp::make_bench_scene(name, 5), b = fp::make_bench_scene(name, 5);
    ASSERT_EQ(a.goal.angles.size(), static_cast<Eigen::Index>(a.pattern->joints().size()));
    EXPECT_EQ(a.goal.angles, b.goal.angles);  // same seed, same goal, bit for bit
    EXPECT_LT(ClosureSystem(*a.pattern).max_error(a.goal), 1e-9);
    EXPECT_GT(a.goal.angles.cwiseAbs().maxCoeff(), 0.1);  // folded, not flat
    foldkit::simulation::CollisionWorld world(*a.pattern);
    EXPECT_TRUE(world.check(foldkit::geometry::facet_poses(*a.pattern, foldkit::geometry::make_tree(*a.pattern), a.goal),
                            a.goal)
                    .empty());
    if (name != "corner-cube" && name.find("-80") == std::string::npos) {
      const fp::BenchScene c = fp::make_bench_scene(name, 6);
      EXPECT_NE(a.goal.angles, c.goal.angles);  // another seed, another goal
    }
  }
  EXPECT_THROW(fp::make_bench_scene("vertex5-random", 1), std::invalid_argument);
}

// The Miura sheets of issue 16's targets: every zig-zag crease at ±80° (the goal is the closed
// form of docs/GENERATORS.md, polished), the straight ones by tan(ρ/2) = cos(60°)·tan(40°).
TEST(BenchSuite, MiuraScaleGoalsFollowTheClosedForm) {
  const fp::BenchScene s = fp::make_bench_scene("miura10x10-80", 1);
  const double zigzag = 80.0 * M_PI / 180.0, straight = 2.0 * std::atan(0.5 * std::tan(zigzag / 2.0));
  const std::size_t n_straight = 10 * 9;
  ASSERT_EQ(s.pattern->joints().size(), 180u);
  for (std::size_t j = 0; j < s.pattern->joints().size(); ++j)
    EXPECT_NEAR(std::abs(s.goal.angles[static_cast<Eigen::Index>(j)]), j < n_straight ? straight : zigzag, 1e-9) << j;
  EXPECT_LT(ClosureSystem(*s.pattern).max_error(s.goal), 1e-12);
}

TEST(BenchSuite, SuitesNameKnownScenesAndPlanners) {
  const auto scenes = fp::bench_scene_names();
  EXPECT_EQ(scenes.size(), 27u);
  for (const auto& suite : fp::bench_suites()) {
    for (const auto& s : suite.scenes) EXPECT_NE(std::find(scenes.begin(), scenes.end(), s), scenes.end()) << s;
    for (const auto& p : suite.planners) EXPECT_EQ(fp::canonical_bench_planner(p), p);
  }
  std::vector<std::string> small;  // all but the three large Miura sheets and the unfiltered vertices
  for (const auto& s : scenes)
    if (s.find("-80") == std::string::npos && s.find("-any") == std::string::npos) small.push_back(s);
  EXPECT_EQ(small.size(), 20u);
  EXPECT_EQ(fp::bench_suite("full").scenes, small);
  EXPECT_EQ(fp::bench_suite("vertex-complete").scenes,
            (std::vector<std::string>{"vertex6-any", "vertex8-any", "vertex12-any", "vertex32-any"}));
  EXPECT_EQ(fp::bench_suite("miura-scale").scenes, std::vector<std::string>(scenes.end() - 3, scenes.end()));
  EXPECT_THROW(fp::bench_suite("nope"), std::invalid_argument);
  EXPECT_THROW(fp::canonical_bench_planner("nope"), std::invalid_argument);
  EXPECT_EQ(fp::canonical_bench_planner("projectedline"), "ProjectedLine");
  EXPECT_EQ(fp::canonical_bench_planner("rrtconnect+carpenter"), "RRTConnect+Carpenter");
  EXPECT_EQ(fp::canonical_bench_planner("rrtconnect@projected"), "RRTConnect@projected");
  EXPECT_EQ(fp::canonical_bench_planner("kpiece1+carpenter@single-vertex"), "KPIECE1+Carpenter@single-vertex");
  EXPECT_THROW(fp::canonical_bench_planner("RRTConnect@nowhere"), std::invalid_argument);
  EXPECT_THROW(fp::canonical_bench_planner("ProjectedLine+Carpenter"), std::invalid_argument);
}

TEST(BenchSuite, ShardsPartitionTheWorkList) {
  const auto all = fp::bench_work(3, 4, 5, 1, 1);
  ASSERT_EQ(all.size(), 60u);
  for (unsigned int n : {2u, 3u, 7u, 61u}) {
    std::multiset<std::tuple<std::size_t, std::size_t, unsigned int>> joined;
    for (unsigned int k = 1; k <= n; ++k)
      for (const auto& w : fp::bench_work(3, 4, 5, k, n)) joined.insert({w.scene, w.planner, w.run});
    std::multiset<std::tuple<std::size_t, std::size_t, unsigned int>> expected;
    for (const auto& w : all) expected.insert({w.scene, w.planner, w.run});
    EXPECT_EQ(joined, expected) << n << " shards";
  }
  EXPECT_THROW(fp::bench_work(1, 1, 1, 3, 2), std::invalid_argument);
  EXPECT_THROW(fp::bench_work(1, 1, 1, 0, 2), std::invalid_argument);
}

TEST(BenchSuite, LogsRoundTripAndShardsMerge) {
  fp::BenchLog log;
  log.experiment = "boat";
  log.parameters = {{"scene STRING", "boat"}, {"shard STRING", "1/2"}, {"planners STRING", "A,B"}};
  log.host = "h";
  log.start_time = "2026-01-01T00:00:00";
  log.setup = "setup\n";
  log.seed = "1";
  log.max_time = 1;
  log.max_mem = 4096;
  log.run_count = 2;
  log.total_duration = 1.5;
  log.enums = {"status|a|b"};
  fp::BenchLog::Planner a{"geometric_A", {"range = 1"}, {"run index INTEGER", "time REAL"}, {{"0", "0.5"}}, {}, {}};
  log.planners = {a};
  const std::string text = fp::write_bench_log(log);
  EXPECT_EQ(text.rfind("OMPL version 1.5.2\nExperiment boat\n", 0), 0u) << text;
  const fp::BenchLog back = fp::parse_bench_log(text, "x.log");
  EXPECT_EQ(fp::write_bench_log(back), text);

  fp::BenchLog second = log;
  second.parameters[1].second = "2/2";
  second.planners[0].runs = {{"1", "0.25"}};
  const fp::BenchLog merged = fp::merge_bench_logs({second, log}, {"b.log", "a.log"});
  ASSERT_EQ(merged.planners.size(), 1u);
  ASSERT_EQ(merged.planners[0].runs.size(), 2u);
  EXPECT_EQ(merged.planners[0].runs[0][0], "0");  // ordered by run index
  EXPECT_EQ(merged.planners[0].runs[1][0], "1");
  EXPECT_DOUBLE_EQ(merged.total_duration, 3.0);
  EXPECT_EQ(*merged.parameter("shard STRING"), "1/1");

  EXPECT_THROW(fp::merge_bench_logs({log}, {"a.log"}), std::invalid_argument);        // shard 2/2 missing
  EXPECT_THROW(fp::merge_bench_logs({log, log}, {"a.log", "c.log"}), std::invalid_argument);  // 1/2 twice
  fp::BenchLog other = second;
  other.planners[0].properties = {"run index INTEGER", "memory REAL"};
  try {
    fp::merge_bench_logs({log, other}, {"a.log", "b.log"});
    ADD_FAILURE() << "mismatched properties merged";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("other run properties"), std::string::npos) << e.what();
  }
  try {
    fp::parse_bench_log("OMPL version \nExperiment x\nRunning on h\nStarting at d\nnot a block\n", "bad.log");
    ADD_FAILURE() << "garbage parsed";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("bad.log:5:", 0), 0u) << e.what();
  }
}

std::vector<std::string> column(const fp::BenchLog::Planner& p, const std::string& property) {
  const auto it = std::find(p.properties.begin(), p.properties.end(), property);
  std::vector<std::string> v;
  if (it == p.properties.end()) return v;
  for (const auto& run : p.runs) v.push_back(run[static_cast<std::size_t>(it - p.properties.begin())]);
  return v;
}

// The quick suite end to end on one scene: logs as OMPL writes them, our properties in them, and
// the deterministic planner's straight line — reachable by construction of the scene's goal —
// solved exactly, closed and replayed without collision by the simulator.
TEST(BenchSuite, QuickSuiteOnTheBoatWritesLogsWithOurProperties) {
  fp::BenchOptions o;
  o.suite = "quick";
  o.scenes = {"boat"};
  o.time = 0.5;
  o.runs = 1;
  o.output_dir = temp_folder("bench_suite_boat");
  std::size_t reports = 0;
  o.progress = [&](const fp::BenchProgress& p) {
    ++reports;
    EXPECT_LE(p.done, p.total);
  };
  const auto results = fp::run_bench(o);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].runs, 2u);
  EXPECT_EQ(reports, 3u);  // two runs, one scene
  const fp::BenchLog log = fp::parse_bench_log(foldkit::io::read_file(results[0].log), results[0].log);
  EXPECT_EQ(log.experiment, "boat");
  ASSERT_EQ(log.planners.size(), 2u);
  EXPECT_EQ(log.planners[0].name, "geometric_RRTConnect");
  EXPECT_EQ(log.planners[1].name, "geometric_ProjectedLine");
  for (const auto& p : log.planners)
    for (const char* prop : {"final closure error REAL", "max closure error REAL", "min clearance REAL",
                             "replay collisions INTEGER", "joint path length REAL", "cmml events INTEGER", "run index INTEGER"})
      EXPECT_NE(std::find(p.properties.begin(), p.properties.end(), prop), p.properties.end()) << prop;
  const auto& line = log.planners[1];
  EXPECT_EQ(column(line, "solved BOOLEAN"), std::vector<std::string>{"1"});
  EXPECT_EQ(column(line, "replay valid BOOLEAN"), std::vector<std::string>{"1"});
  EXPECT_EQ(column(line, "replay collisions INTEGER"), std::vector<std::string>{"0"});
  EXPECT_LT(std::atof(column(line, "max closure error REAL")[0].c_str()), 1e-6);
  EXPECT_LT(std::atof(column(line, "goal distance REAL")[0].c_str()), 1e-6);
  EXPECT_GT(std::atof(column(line, "min clearance REAL")[0].c_str()), 0.0);
  EXPECT_GT(std::atof(column(line, "joint path length REAL")[0].c_str()), 0.5);
}

// Issue 16: several spaces side by side in ONE log per scene (entries PLANNER@SPACE), each run
// in its own space on the same goal, and the unfiltered single-vertex scenes with the fallback.
TEST(BenchSuite, SpacesSideBySideInOneLog) {
  fp::BenchOptions o;
  o.suite = "spaces";
  o.scenes = {"boat"};
  o.space = "driving,projected";
  o.time = 2.0;
  o.runs = 2;
  o.output_dir = temp_folder("bench_spaces");
  const auto results = fp::run_bench(o);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].runs, 4u);
  EXPECT_EQ(results[0].planners.count("RRTConnect@driving"), 1u);
  EXPECT_EQ(results[0].planners.count("RRTConnect@projected"), 1u);
  const fp::BenchLog log = fp::parse_bench_log(foldkit::io::read_file(results[0].log), results[0].log);
  ASSERT_EQ(log.planners.size(), 2u);
  EXPECT_EQ(log.planners[0].name, "geometric_RRTConnect@driving");
  EXPECT_EQ(log.planners[1].name, "geometric_RRTConnect@projected");
  for (const auto& p : log.planners) EXPECT_EQ(column(p, "solved BOOLEAN"), (std::vector<std::string>{"1", "1"})) << p.name;
  // The driving space's paths replay; a Projected path may jump where it is densified (the logs'
  // "path jumps" property), which is what the comparison is for.
  EXPECT_EQ(column(log.planners[0], "replay valid BOOLEAN"), (std::vector<std::string>{"1", "1"}));
  for (const auto& g : column(log.planners[0], "goal distance REAL")) EXPECT_LT(std::atof(g.c_str()), 1e-6);
  o.space = "driving,nowhere";
  EXPECT_THROW(fp::run_bench(o), std::invalid_argument);
}

TEST(BenchSuite, UnfilteredVertexScenesArePlannedWithTheFallback) {
  fp::BenchOptions o;
  o.suite = "vertex-complete";
  o.scenes = {"vertex8-any"};
  o.planners = {"RRTConnect+Carpenter", "SphericalCarpenter"};
  o.time = 1.0;
  o.runs = 2;
  o.output_dir = temp_folder("bench_vertex_complete");
  const auto results = fp::run_bench(o);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].solved, 4u);
  const fp::BenchLog log = fp::parse_bench_log(foldkit::io::read_file(results[0].log), results[0].log);
  ASSERT_EQ(log.planners.size(), 2u);
  EXPECT_EQ(log.planners[0].name, "geometric_RRTConnect+Carpenter");
  for (const auto& p : log.planners) {
    EXPECT_EQ(column(p, "replay valid BOOLEAN"), (std::vector<std::string>{"1", "1"})) << p.name;
    for (const auto& g : column(p, "goal distance REAL")) EXPECT_LT(std::atof(g.c_str()), 1e-6) << p.name;
  }
  // The fallback is Carpenter's rule on the sphere: a scene of several vertices is refused, before
  // anything is written (here after a single-vertex scene that would have run).
  o.scenes = {"vertex8-any", "boat"};
  o.planners = {"RRTConnect+Carpenter"};
  o.output_dir = temp_folder("bench_vertex_complete_refused") + "/out";
  EXPECT_THROW(fp::run_bench(o), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(o.output_dir));
}

// Issue 16, item 3: the imported FOLD patterns (bird base, 5 DOF; Resch, 10 DOF) and the 13-DOF
// waterbomb 4x4, planned from flat to their scene goals with default options and replayed by the
// simulator with collisions on.
TEST(BenchSuite, SeveralDofScenesPlanAndReplay) {
  for (const char* name : {"bird-base", "resch", "waterbomb4x4"}) {
    SCOPED_TRACE(name);
    fp::BenchScene s = fp::make_bench_scene(name, 1);
    s.options.replay = true;
    s.options.time = 20.0;
    const auto r = foldkit::planners::plan(*s.pattern, s.goal, s.options);
    ASSERT_TRUE(r.status.ok()) << r.status.message;
    EXPECT_EQ(r.space, "driving");
    ASSERT_TRUE(r.replay.has_value());
    EXPECT_TRUE(r.replay->collisions.empty());
    const ClosureSystem sys(*s.pattern);
    for (const auto& w : r.waypoints) EXPECT_LE(sys.max_error(w), 1e-10);
  }
}

// Regression: with the spherical LP by constraint generation, Clp's warm-started dual simplex
// answered t = 0 at the first step of this goal (the whole LP has t > 0), and Carpenter's rule
// stopped with "no strictly expansive motion"; such an answer is now checked on the whole LP.
TEST(BenchSuite, CarpenterFlattensTheDegree32GoalOfSeed11) {
  const fp::BenchScene s = fp::make_bench_scene("vertex32-any", 11);
  std::string why;
  const auto way = foldkit::planners::carpenter_path(*s.pattern, FoldState::flat(*s.pattern), s.goal, 0.02, &why);
  ASSERT_FALSE(way.empty()) << why;
  EXPECT_LT((way.back().angles - s.goal.angles).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(BenchSuite, ErrorVersusTimeRecordsEveryLimit) {
  fp::BenchOptions o;
  o.scenes = {"vertex4-random"};
  o.planners = {"ProjectedLine", "RRTConnect"};
  o.runs = 1;
  const auto rows = fp::run_error_vs_time(o, {0.05, 0.2});
  ASSERT_EQ(rows.size(), 4u);
  for (const auto& r : rows) {
    EXPECT_TRUE(r.solution == "exact" || r.solution == "none" || r.solution == "approximate") << r.solution;
    if (r.solution == "exact") {
      EXPECT_LT(r.goal_distance, 1e-6);
      EXPECT_LT(r.max_closure_error, 1e-6);
    }
  }
  const std::string csv = fp::error_vs_time_csv(rows);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);
  EXPECT_THROW(fp::run_error_vs_time(o, {}), std::invalid_argument);
}

}  // namespace

namespace {

// The deterministic methods of the other planners (projected-velocity folding, Carpenter's rule
// on the sphere) inside ompl::tools::Benchmark: on the corner cube both reach the goal, and the
// simulator replays their paths without a collision.
TEST(BenchSuite, DeterministicFoldingMethodsSolveTheCornerCube) {
  fp::BenchOptions o;
  o.suite = "full";
  o.scenes = {"corner-cube"};
  o.planners = {"ProjectedFolding", "SphericalCarpenter"};
  o.time = 30.0;  // a deterministic run ends when its method does; the limit only guards sanitizer builds
  o.runs = 1;
  o.output_dir = temp_folder("bench_suite_corner");
  const auto results = fp::run_bench(o);
  ASSERT_EQ(results.size(), 1u);
  const fp::BenchLog log = fp::parse_bench_log(foldkit::io::read_file(results[0].log), results[0].log);
  ASSERT_EQ(log.planners.size(), 2u);
  for (const auto& p : log.planners) {
    SCOPED_TRACE(p.name);
    EXPECT_EQ(column(p, "solved BOOLEAN"), std::vector<std::string>{"1"});
    EXPECT_EQ(column(p, "replay valid BOOLEAN"), std::vector<std::string>{"1"});
    EXPECT_EQ(column(p, "replay collisions INTEGER"), std::vector<std::string>{"0"});
    EXPECT_LT(std::atof(column(p, "goal distance REAL")[0].c_str()), 1e-9);
    EXPECT_LT(std::atof(column(p, "max closure error REAL")[0].c_str()), 1e-6);
  }
}

}  // namespace
