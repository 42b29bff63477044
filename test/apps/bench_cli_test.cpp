// foldkit bench / bench-merge through the command line. The logs are read back by OMPL's own
// reader (ompl_benchmark_statistics into SQLite) when it is installed, else by a small parser
// written here, independent of the library's.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "test_paths.hpp"

namespace {

using foldkit::test::foldkit;
using foldkit::test::slurp;
namespace fs = std::filesystem;

std::string fresh(const std::string& name) {
  static const std::string root = foldkit::test::temp_dir();
  const fs::path p = fs::path(root) / name;
  fs::remove_all(p);
  return p.string();
}

// planner → its runs, each as property → value: the log's run table.
using Runs = std::map<std::string, std::vector<std::map<std::string, std::string>>>;

Runs read_runs(const std::string& path) {
  std::istringstream in(slurp(path));
  Runs out;
  std::string line;
  auto number = [](const std::string& l) { return std::stol(l.substr(0, l.find(' '))); };
  auto is_count = [](const std::string& l, const std::string& words) {
    return !l.empty() && std::isdigit(static_cast<unsigned char>(l[0])) && l.size() > words.size() &&
           l.compare(l.size() - words.size(), words.size(), words) == 0 && l.find(' ') == l.size() - words.size() - 1;
  };
  while (std::getline(in, line) && !is_count(line, "planners")) {
  }
  EXPECT_TRUE(is_count(line, "planners")) << path << " has no planner count";
  if (!is_count(line, "planners")) return out;
  const long planners = number(line);
  for (long p = 0; p < planners; ++p) {
    std::string name;
    std::getline(in, name);
    std::getline(in, line);
    for (long i = number(line); i > 0; --i) std::getline(in, line);
    std::getline(in, line);
    std::vector<std::string> props(static_cast<std::size_t>(number(line)));
    for (auto& prop : props) std::getline(in, prop);
    std::getline(in, line);
    auto& runs = out[name];
    for (long r = number(line); r > 0; --r) {
      std::getline(in, line);
      std::map<std::string, std::string> run;
      std::size_t b = 0;
      for (const auto& prop : props) {
        const std::size_t e = line.find("; ", b);
        EXPECT_NE(e, std::string::npos) << path << ": " << line;
        if (e == std::string::npos) break;
        run[prop] = line.substr(b, e - b);
        b = e + 2;
      }
      runs.push_back(run);
    }
    while (std::getline(in, line) && line != ".") {
    }
  }
  return out;
}

std::vector<std::string> column(const Runs& runs, const std::string& planner, const std::string& prop) {
  std::vector<std::string> v;
  for (const auto& r : runs.at(planner)) v.push_back(r.at(prop));
  return v;
}

TEST(BenchCli, QuickSuiteLogsAreAcceptedByOmplBenchmarkStatistics) {
  const std::string dir = fresh("quick");
  const auto r = foldkit({"bench", "quick", "--time", "0.2", "--runs", "1", "--scenes", "vertex4-random,boat", "-o", dir, "--json"});
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["runs"], 4);
  ASSERT_EQ(j["logs"].size(), 2u);
  for (const auto& log : j["logs"]) {
    const Runs runs = read_runs(log.get<std::string>());
    ASSERT_EQ(runs.size(), 2u) << log;
    for (const auto& [planner, rs] : runs) {
      ASSERT_EQ(rs.size(), 1u);
      for (const char* prop : {"final closure error REAL", "max closure error REAL", "min clearance REAL",
                               "replay collisions INTEGER", "joint path length REAL", "cmml events INTEGER", "time REAL"})
        EXPECT_EQ(rs[0].count(prop), 1u) << planner << ' ' << prop;
    }
  }
  EXPECT_EQ(slurp(j["logs"][1].get<std::string>()).rfind("OMPL version 1.5.2\nExperiment boat\n", 0), 0u);

  if (std::system("command -v ompl_benchmark_statistics >/dev/null 2>&1 && python3 -c 'import sqlite3' 2>/dev/null") != 0)
    GTEST_SKIP() << "ompl_benchmark_statistics (Debian ompl-demos) is not installed";
  const std::string db = dir + "/bench.db";
  const std::string cmd = "cd " + foldkit::test::shell_quote(dir) + " && ompl_benchmark_statistics -d bench.db *.log >stats.out 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << slurp(dir + "/stats.out");
  const std::string query = "python3 -c \"import sqlite3; c = sqlite3.connect('" + db +
                            "'); print(c.execute('select count(*), sum(replay_collisions is not null), "
                            "count(distinct experimentid) from runs').fetchone()); print(c.execute('select version from "
                            "experiments').fetchone()[0])\" > " + dir + "/query.out 2>&1";
  ASSERT_EQ(std::system(query.c_str()), 0) << slurp(dir + "/query.out");
  const std::string out = slurp(dir + "/query.out");
  // 4 runs in 2 experiments; the boat's are solved by both planners, so their paths were measured.
  EXPECT_EQ(out.substr(0, out.find('\n')).substr(0, 4), "(4, ") << out;
  EXPECT_NE(out.find(", 2)"), std::string::npos) << out;
  EXPECT_NE(out.find("OMPL 1.5.2"), std::string::npos) << out;
}

// The two shards, merged, hold exactly the unsharded run list: per planner the same run
// indices, and the deterministic planner's path (a function of the scene alone) unchanged.
TEST(BenchCli, ShardsMergedEqualTheUnshardedRunList) {
  const std::vector<std::string> common = {"bench", "quick", "--time", "0.2", "--runs", "3", "--scenes", "vertex4-random"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = common;
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  const std::string all = fresh("all"), s1 = fresh("s1"), s2 = fresh("s2"), merged = fresh("merged");
  ASSERT_EQ(foldkit(with({"-o", all})).exit, 0);
  ASSERT_EQ(foldkit(with({"--shard", "1/2", "-o", s1})).exit, 0);
  ASSERT_EQ(foldkit(with({"--shard", "2/2", "-o", s2})).exit, 0);
  ASSERT_TRUE(fs::exists(s1 + "/vertex4-random.shard-1-of-2.log"));
  const Runs part = read_runs(s1 + "/vertex4-random.shard-1-of-2.log");
  std::size_t part_runs = 0;
  for (const auto& [p, rs] : part) part_runs += rs.size();
  EXPECT_EQ(part_runs, 3u);  // 6 runs, every second one

  const auto m = foldkit({"bench-merge", s1, s2, "-o", merged, "--json"});
  ASSERT_EQ(m.exit, 0) << m.err;
  EXPECT_EQ(nlohmann::json::parse(m.out)["scenes"][0]["shards"], 2);
  const Runs a = read_runs(all + "/vertex4-random.log"), b = read_runs(merged + "/vertex4-random.log");
  ASSERT_EQ(a.size(), b.size());
  for (const auto& [planner, rs] : a) {
    ASSERT_EQ(b.count(planner), 1u) << planner;
    EXPECT_EQ(column(a, planner, "run index INTEGER"), (std::vector<std::string>{"0", "1", "2"})) << planner;
    EXPECT_EQ(column(b, planner, "run index INTEGER"), column(a, planner, "run index INTEGER")) << planner;
  }
  // Sampling planners may time out in one run and not in the other; the deterministic one may not.
  EXPECT_EQ(column(b, "geometric_ProjectedLine", "solved BOOLEAN"), column(a, "geometric_ProjectedLine", "solved BOOLEAN"));
  EXPECT_EQ(column(b, "geometric_ProjectedLine", "joint path length REAL"),
            column(a, "geometric_ProjectedLine", "joint path length REAL"));

  // A shard of another benchmark (another seed: other goals) is refused, and so is a lone shard.
  const std::string other = fresh("other");
  ASSERT_EQ(foldkit(with({"--shard", "2/2", "--seed", "2", "-o", other})).exit, 0);
  const auto bad = foldkit({"bench-merge", s1, other, "-o", fresh("bad")});
  EXPECT_EQ(bad.exit, 1);
  EXPECT_NE(bad.err.find("scene_seed"), std::string::npos) << bad.err;
  const auto lone = foldkit({"bench-merge", s1, "-o", fresh("lone")});
  EXPECT_EQ(lone.exit, 1);
  EXPECT_NE(lone.err.find("shard 2/2 of vertex4-random is missing"), std::string::npos) << lone.err;
}

// More shards than runs: the shards that drew none of a scene's runs write no log of it, and the
// merge of the others still holds every run.
TEST(BenchCli, ShardsWithoutRunsOfASceneDoNotBlockTheMerge) {
  const std::vector<std::string> common = {"bench", "quick", "--time", "0.2", "--runs", "1", "--scenes", "vertex4-random"};
  std::vector<std::string> dirs;
  for (int k = 1; k <= 4; ++k) {
    dirs.push_back(fresh("few" + std::to_string(k)));
    std::vector<std::string> a = common;
    a.insert(a.end(), {"--shard", std::to_string(k) + "/4", "-o", dirs.back()});
    ASSERT_EQ(foldkit(a).exit, 0) << k;
  }
  std::vector<std::string> merge = {"bench-merge"};
  merge.insert(merge.end(), dirs.begin(), dirs.end());
  const std::string merged = fresh("few-merged");
  merge.insert(merge.end(), {"-o", merged});
  const auto m = foldkit(merge);
  ASSERT_EQ(m.exit, 0) << m.err;
  std::size_t runs = 0;
  for (const auto& [p, rs] : read_runs(merged + "/vertex4-random.log")) runs += rs.size();
  EXPECT_EQ(runs, 2u);  // the quick suite's two planners, one run each
}

TEST(BenchCli, BadArgumentsExitTwo) {
  const std::string out = fresh("unused");
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"bench", "quick"},                                   // no -o
           {"bench", "-o", out},                                 // no suite
           {"bench", "nope", "-o", out},                         // unknown suite
           {"bench", "quick", "--scenes", "vertex5", "-o", out},  // unknown scene
           {"bench", "quick", "--planners", "Foo", "-o", out},   // unknown planner
           {"bench", "quick", "--shard", "0/2", "-o", out},
           {"bench", "quick", "--shard", "3/2", "-o", out},
           {"bench", "quick", "--shard", "1-2", "-o", out},
           {"bench", "quick", "--shard", "1/-3", "-o", out},        // not shard 1 of 4294967293
           {"bench", "quick", "--runs", "0", "-o", out},
           {"bench", "quick", "--time", "-1", "-o", out},
           {"bench", "quick", "--error-vs-time", "0.1,0", "-o", out},
           {"bench", "quick", "--error-vs-time", "0.1", "--shard", "1/2", "-o", out},
           {"bench", "quick", "--space", "nowhere", "-o", out},
           {"bench", "optimal", "--objective", "", "-o", out},  // an empty objective, not the suite's
           {"bench", "quick", "--space", "driving,nowhere", "-o", out},
           {"bench", "quick", "--planners", "RRTConnect@nowhere", "-o", out},
           // the Carpenter fallback on a scene that is not a single vertex (the first scene is one)
           {"bench", "vertex-complete", "--scenes", "vertex8-any,boat", "--planners", "RRTConnect+Carpenter", "-o", out},
           {"bench", "vertex-complete", "--scenes", "boat", "--planners", "RRTConnect+Carpenter", "--error-vs-time", "0.1",
            "-o", out},
           {"bench", "quick", "--scenes", "boat", "--planners", "RRTConnect", "--param", "nonsense=1", "-o", out},
           {"bench", "quick", "--param", "range", "-o", out},
           {"bench-merge", "-o", out},
           {"bench-merge", out + "/missing", "-o", out},
       }) {
    std::string joined;
    for (const auto& a : args) joined += a + ' ';
    const auto r = foldkit(args);
    EXPECT_EQ(r.exit, 2) << joined << '\n' << r.err;
  }
  EXPECT_FALSE(fs::exists(out));
}

// RRTConnect held to steps of 1e-7 rad: its connect loop never looks at the clock and ran for
// hours; FoldValidity's time limit (twice --time in the harness, each limit with --error-vs-time)
// now ends every run (a regression hangs until the ctest timeout).
TEST(BenchCli, RunsWithATinyRangeEnd) {
  const std::string out = fresh("tiny-range");
  const auto r = foldkit({"bench", "quick", "--scenes", "vertex8-any", "--planners", "RRTConnect", "--param", "range=1e-7",
                          "--runs", "2", "--time", "0.2", "-o", out, "--json"});
  ASSERT_EQ(r.exit, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(out + "/vertex8-any.log"));
  const auto e = foldkit({"bench", "quick", "--scenes", "vertex8-any", "--planners", "RRTConnect", "--param", "range=1e-7",
                          "--runs", "1", "--error-vs-time", "0.2", "-o", out, "--json"});
  ASSERT_EQ(e.exit, 0) << e.err;
  EXPECT_TRUE(std::filesystem::exists(out + "/error_vs_time.csv"));
}

TEST(BenchCli, ListNamesSuitesScenesAndPlanners) {
  const auto r = foldkit({"bench", "--list", "--json"});
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["suites"][0]["name"], "quick");
  EXPECT_EQ(j["scenes"].size(), 27u);
  std::vector<std::string> suites, objectives;
  for (const auto& s : j["suites"]) {
    suites.push_back(s["name"]);
    objectives.push_back(s["objective"]);
  }
  EXPECT_EQ(suites, (std::vector<std::string>{"quick", "full", "spaces", "vertex-complete", "miura-scale", "optimal"}));
  // Each suite's objective unless --objective names another: rotation for the optimal suite.
  EXPECT_EQ(objectives, (std::vector<std::string>{"length", "length", "length", "length", "length", "rotation"}));
  EXPECT_NE(std::find(j["planners"]["deterministic"].begin(), j["planners"]["deterministic"].end(), "ProjectedLine"),
            j["planners"]["deterministic"].end());
}

TEST(BenchCli, ErrorVersusTimeWritesOneRowPerRun) {
  const std::string dir = fresh("evt");
  const auto r = foldkit({"bench", "quick", "--scenes", "vertex4-random", "--runs", "2", "--error-vs-time", "0.05,0.1",
                          "-o", dir, "--json"});
  ASSERT_EQ(r.exit, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["runs"], 8);  // 2 planners × 2 limits × 2 runs
  const std::string csv = slurp(dir + "/error_vs_time.csv");
  EXPECT_EQ(csv.rfind("scene,planner,time_limit_s,run,solution,", 0), 0u) << csv;
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 9);
}

}  // namespace
