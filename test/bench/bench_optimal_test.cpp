// The `optimal` suite (issue 38, item 3): its planners and scenes, the suite's own objective, each
// run's best cost against time in the log (non-increasing, closed by the solution's cost), and
// scripts/plot_bench.py drawing the cost against time from such logs.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "foldkit/bench/deterministic_planner.hpp"
#include "foldkit/bench/log.hpp"
#include "foldkit/bench/run.hpp"
#include "foldkit/bench/scenes.hpp"
#include "cli_runner.hpp"
#include "test_paths.hpp"
#include "test_time.hpp"

namespace {

namespace fb = foldkit::bench;
using foldkit::test::slurp;

std::size_t index_of(const std::vector<std::string>& names, const std::string& prefix) {
  return static_cast<std::size_t>(std::find_if(names.begin(), names.end(),
                                               [&](const std::string& n) { return n.rfind(prefix, 0) == 0; }) -
                                  names.begin());
}

// The finite best costs of one run's progress line ("v,v,…,;v,v,…,;…"), in time order.
std::vector<double> best_costs(const fb::BenchLog::Planner& p, std::size_t run) {
  const std::size_t at = index_of(p.progress_properties, "best cost ");
  std::vector<double> out;
  std::stringstream samples(p.progress_runs.at(run));
  for (std::string sample; std::getline(samples, sample, ';');) {
    std::stringstream values(sample);
    std::string v;
    for (std::size_t k = 0; k <= at && std::getline(values, v, ','); ++k)
      if (k == at && std::isfinite(std::atof(v.c_str())) && !v.empty()) out.push_back(std::atof(v.c_str()));
  }
  return out;
}

// A python3 with matplotlib (the configured one is Debian's; PATH may hold another), or "".
std::string python_with_matplotlib() {
  for (const char* py : {"/usr/bin/python3", "python3"})
    if (std::system((std::string(py) + " -c 'import matplotlib' >/dev/null 2>&1").c_str()) == 0) return py;
  return "";
}

TEST(BenchOptimal, SuiteNamesTheOptimisingPlannersOnItsScenesWithRotation) {
  const fb::BenchSuite& s = fb::bench_suite("optimal");
  EXPECT_EQ(s.planners, (std::vector<std::string>{"RRT*", "PRM*", "BIT*", "ABIT*", "AIT*", "RRT#", "FMT", "CForest"}));
  EXPECT_EQ(s.scenes, (std::vector<std::string>{"miura10x10", "waterbomb4x4", "resch", "vertex12-random"}));
  EXPECT_EQ(s.objective, "rotation");
  EXPECT_EQ(fb::make_bench_scene("vertex12-random", 1).pattern->joints().size(), 12u);
  for (const auto& other : fb::bench_suites()) {
    if (other.name != "optimal") {
      EXPECT_TRUE(other.objective.empty()) << other.name;
    }
  }
}

// The suite's objective applies unless the options name one; every run of an optimising planner
// logs its best cost over time, never rising, and its solution's cost, which ends the curve.
TEST(BenchOptimal, LogsBestCostAgainstTimeThatNeverRises) {
  const std::string dir = foldkit::test::temp_dir() + "/optimal";
  fb::BenchOptions o;
  o.suite = "optimal";
  // The degree-12 vertex: the suite's cheapest scene to set up and to measure (the Resch pattern,
  // where the cost falls, takes ten times as long).
  o.scenes = {"vertex12-random"};
  o.planners = {"RRT*", "FMT"};
  o.time = foldkit::test::scaled_seconds(0.5);
  o.runs = 2;
  o.output_dir = dir;
  const auto results = fb::run_bench(o);
  ASSERT_EQ(results.size(), 1u);
  const fb::BenchLog log = fb::parse_bench_log(slurp(results[0].log), results[0].log);
  ASSERT_NE(log.parameter("objective STRING"), nullptr);
  EXPECT_EQ(*log.parameter("objective STRING"), "rotation");
  ASSERT_EQ(log.planners.size(), 2u);
  const fb::BenchLog::Planner& star = log.planners[0];
  ASSERT_EQ(star.progress_runs.size(), 2u);
  const std::size_t solution = index_of(star.properties, "solution cost REAL"),
                    approximate = index_of(star.properties, "approximate solution BOOLEAN");
  ASSERT_LT(solution, star.properties.size());
  std::size_t curves = 0;
  for (std::size_t r = 0; r < 2; ++r) {
    const std::vector<double> best = best_costs(star, r);
    for (std::size_t i = 1; i < best.size(); ++i) EXPECT_LE(best[i], best[i - 1]) << "run " << r;
    if (best.empty() || star.runs[r][approximate] == "1") continue;
    ++curves;
    // The last sample is at most 0.05 s old: the solution costs what it said, or less (OMPL
    // writes the progress samples with 6 decimals).
    EXPECT_LE(std::atof(star.runs[r][solution].c_str()), best.back() + 1e-6 * (1.0 + std::abs(best.back())));
  }
  EXPECT_EQ(curves, 2u) << "RRT* found no path on the vertex";
  // FMT reports no best cost while it runs: its solution's cost (when it has one) is its curve.
  EXPECT_TRUE(log.planners[1].progress_properties.empty());
  EXPECT_LT(index_of(log.planners[1].properties, "solution cost REAL"), log.planners[1].properties.size());

  // The plot script reads the log: a figure per scene, and the summary row of each planner.
  const std::string py = python_with_matplotlib();
  if (py.empty()) GTEST_SKIP() << "no python3 with matplotlib (Debian: python3-matplotlib)";
  const std::string script = foldkit::test::data_path("../../scripts/plot_bench.py");
  const std::string cmd = py + " '" + script + "' '" + dir + "' -o '" + dir + "/plots' --summary >'" + dir + "/summary.txt' 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(dir + "/summary.txt");
  EXPECT_TRUE(std::filesystem::exists(dir + "/plots/vertex12-random.cost.svg"));
  const std::string summary = slurp(dir + "/summary.txt");
  EXPECT_NE(summary.find("| vertex12-random | RRT* | 2/2 | "), std::string::npos) << summary;
  EXPECT_NE(summary.find("| vertex12-random | FMT | "), std::string::npos) << summary;
  // A log cut short is refused with its line, and no figure is drawn from it.
  const std::string text = slurp(results[0].log);
  std::filesystem::create_directories(dir + "/cut");
  std::ofstream(dir + "/cut/vertex12-random.log") << text.substr(0, text.find("geometric_FMT"));
  const std::string bad = py + " '" + script + "' '" + dir + "/cut' >'" + dir + "/cut.txt' 2>&1";
  EXPECT_NE(std::system(bad.c_str()), 0);
  EXPECT_NE(slurp(dir + "/cut.txt").find("vertex12-random.log:"), std::string::npos) << slurp(dir + "/cut.txt");
  EXPECT_FALSE(std::filesystem::exists(dir + "/cut/vertex12-random.cost.svg"));
}

// --objective (BenchOptions::objective) wins over the suite's.
TEST(BenchOptimal, TheOptionsObjectiveReplacesTheSuites) {
  fb::BenchOptions o;
  o.suite = "optimal";
  o.scenes = {"vertex12-random"};
  o.planners = {"RRT*"};
  o.objective = "length";
  o.time = 0.05;
  o.runs = 1;
  o.output_dir = foldkit::test::temp_dir() + "/length";
  const auto results = fb::run_bench(o);
  ASSERT_EQ(results.size(), 1u);
  const fb::BenchLog log = fb::parse_bench_log(slurp(results[0].log), results[0].log);
  ASSERT_NE(log.parameter("objective STRING"), nullptr);
  EXPECT_EQ(*log.parameter("objective STRING"), "length");
}

// AIT* asks OMPL's rejection sampler for an informed state with an unbounded number of draws and
// (OMPL 1.5.2) does not look at the time limit while it draws: with `rotation` on a vertex whose
// first path meets the heuristic's bound, one 0.5 s run drew for over ten minutes. The draws are
// now bounded (planners/src/path_length.hpp), and the run ends near its limit.
TEST(BenchOptimal, InformedTreesWithRotationEndNearTheirLimit) {
  fb::BenchOptions o;
  o.suite = "optimal";
  o.scenes = {"vertex8-random"};
  o.planners = {"AIT*", "ABIT*"};
  o.time = foldkit::test::scaled_seconds(0.3);
  o.runs = 1;
  o.output_dir = foldkit::test::temp_dir() + "/informed";
  const auto t0 = std::chrono::steady_clock::now();
  const auto results = fb::run_bench(o);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].solved, 2u);
  EXPECT_LT(seconds, foldkit::test::scaled_seconds(20.0));
}

}  // namespace
