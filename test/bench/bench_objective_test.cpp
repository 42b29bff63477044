// foldkit bench with an objective (issue 38, items 2 and 3): the objective and each run's cost in
// the log, OMPL's progress properties (best cost over time) kept in the shard logs and through
// their merging, and an objective or threshold refused before anything is written.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "foldkit/bench/log.hpp"
#include "foldkit/bench/run.hpp"
#include "foldkit/planners/planner_factory.hpp"
#include "cli_runner.hpp"
#include "test_paths.hpp"
#include "test_time.hpp"

namespace {

namespace fb = foldkit::bench;
using foldkit::test::slurp;

fb::BenchOptions options(const std::string& dir) {
  fb::BenchOptions o;
  o.suite = "quick";
  o.scenes = {"vertex8-random"};
  o.planners = {"RRT*", "RRTConnect"};
  o.objective = "rotation";
  o.cost_threshold = 0.0;  // never met: RRT* optimises all of its time
  o.time = foldkit::test::scaled_seconds(0.3);
  o.runs = 2;
  o.output_dir = dir;
  return o;
}

std::size_t column(const fb::BenchLog::Planner& p, const std::string& name) {
  return static_cast<std::size_t>(std::find(p.properties.begin(), p.properties.end(), name) - p.properties.begin());
}

// Each progress line is "v,v,v,;v,v,v,;…" in the order of progress_properties: the best costs
// it holds, finite ones only.
std::vector<double> best_costs(const fb::BenchLog::Planner& p, const std::string& line) {
  const auto at = static_cast<std::size_t>(
      std::find(p.progress_properties.begin(), p.progress_properties.end(), "best cost REAL") - p.progress_properties.begin());
  std::vector<double> out;
  std::stringstream samples(line);
  for (std::string sample; std::getline(samples, sample, ';');) {
    std::stringstream values(sample);
    std::string v;
    for (std::size_t k = 0; k <= at && std::getline(values, v, ','); ++k)
      if (k == at && !v.empty() && std::isfinite(std::atof(v.c_str()))) out.push_back(std::atof(v.c_str()));
  }
  return out;
}

TEST(BenchObjective, LogsTheObjectiveItsCostAndTheBestCostOverTimeThroughMerging) {
  const std::string dir = foldkit::test::temp_dir() + "/bench-objective";
  std::filesystem::remove_all(dir);
  std::vector<fb::BenchLog> shards;
  for (unsigned int k = 1; k <= 2; ++k) {
    fb::BenchOptions o = options(dir);
    o.shard = k;
    o.shards = 2;
    const auto results = fb::run_bench(o);
    ASSERT_EQ(results.size(), 1u);
    shards.push_back(fb::parse_bench_log(slurp(results[0].log), results[0].log));
  }
  const fb::BenchLog merged = fb::merge_bench_logs(shards, {"shard 1", "shard 2"});
  ASSERT_NE(merged.parameter("objective STRING"), nullptr);
  EXPECT_EQ(*merged.parameter("objective STRING"), "rotation");
  ASSERT_EQ(merged.planners.size(), 2u);
  const fb::BenchLog::Planner& star = merged.planners[0];
  EXPECT_EQ(star.name, "geometric_RRT*");
  ASSERT_EQ(star.runs.size(), 2u);
  // RRT* declares its best cost as a progress property; the log keeps one line per run.
  ASSERT_NE(std::find(star.progress_properties.begin(), star.progress_properties.end(), "best cost REAL"),
            star.progress_properties.end());
  ASSERT_EQ(star.progress_runs.size(), 2u);
  const std::size_t cost = column(star, "objective cost REAL"), rotation = column(star, "joint rotation REAL");
  ASSERT_LT(cost, star.properties.size());
  for (std::size_t r = 0; r < 2; ++r) {
    const std::vector<double> best = best_costs(star, star.progress_runs[r]);
    ASSERT_FALSE(best.empty()) << star.progress_runs[r];
    for (std::size_t i = 1; i < best.size(); ++i) EXPECT_LE(best[i], best[i - 1]);
    // The run's cost, every crease counted, is its joint rotation.
    EXPECT_DOUBLE_EQ(std::atof(star.runs[r][cost].c_str()), std::atof(star.runs[r][rotation].c_str()));
  }
  // RRTConnect does not optimise: no progress properties, and none invented.
  EXPECT_TRUE(merged.planners[1].progress_properties.empty());
  // Written back and read again, the progress lines are the same.
  const std::string text = fb::write_bench_log(merged);
  const fb::BenchLog again = fb::parse_bench_log(text);
  EXPECT_EQ(again.planners[0].progress_runs, star.progress_runs);

  // OMPL's own reader takes the merged log, the progress lines into its `progress` table.
  if (std::system("command -v ompl_benchmark_statistics >/dev/null 2>&1 && python3 -c 'import sqlite3' 2>/dev/null") != 0)
    GTEST_SKIP() << "ompl_benchmark_statistics (Debian ompl-demos) is not installed";
  const std::string merged_dir = dir + "/merged";
  std::filesystem::create_directories(merged_dir);
  std::ofstream(merged_dir + "/vertex8-random.log") << text;
  const std::string cmd = "cd '" + merged_dir + "' && ompl_benchmark_statistics -d bench.db vertex8-random.log >stats.out 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(merged_dir + "/stats.out");
  const std::string query = "python3 -c \"import sqlite3; c = sqlite3.connect('" + merged_dir +
                            "/bench.db'); print(c.execute('select count(*), count(distinct runid), min(best_cost) from progress')"
                            ".fetchone()[1])\" > '" + merged_dir + "/query.out' 2>&1";
  ASSERT_EQ(std::system(query.c_str()), 0) << slurp(merged_dir + "/query.out");
  EXPECT_EQ(slurp(merged_dir + "/query.out"), "2\n");  // RRT*'s two runs have progress rows
}

TEST(BenchObjective, BadObjectiveThresholdOrCombinationWritesNothing) {
  const std::string dir = foldkit::test::temp_dir() + "/bench-objective-bad";
  std::filesystem::remove_all(dir);
  fb::BenchOptions o = options(dir);
  o.objective = "speed";
  EXPECT_THROW(fb::run_bench(o), std::invalid_argument);
  o = options(dir);
  o.cost_threshold = -1.0;
  EXPECT_THROW(fb::run_bench(o), std::invalid_argument);
  o = options(dir);
  o.objective = "clearance";
  o.planners = {"RRT*", "BIT*"};
  EXPECT_THROW(fb::run_bench(o), foldkit::planners::PlannerRefused);
  EXPECT_FALSE(std::filesystem::exists(dir));
}

}  // namespace
