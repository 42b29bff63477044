// foldkit plan --experience DB (issue 38, item 4): the database is made by the first plan, used
// by the next one (recalled and repaired) in another process, gives the same plan from the same
// database and seed, and a damaged or foreign database is refused (exit 1) with nothing written.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/io/pmml.hpp"

namespace {

using foldkit::test::foldkit;
using foldkit::test::temp_dir;
namespace fs = std::filesystem;
namespace geo = foldkit::geometry;

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A Miura-ori 4×4 and its folds to 0.8 and 0.7 (foldkit fold, closure only).
struct Case {
  std::string dir = temp_dir() + "/plan-experience-cli", pattern = dir + "/m4.pmml", g8 = dir + "/g8.cmml", g7 = dir + "/g7.cmml";
  Case() {
    fs::create_directories(dir);
    std::ofstream(pattern) << foldkit::io::write_pmml(geo::build_or_throw(geo::generators::miura(4, 4)).to_spec());
    EXPECT_EQ(foldkit({"fold", pattern, "--fraction", "0.8", "--no-collision", "-o", g8}).exit, 0);
    EXPECT_EQ(foldkit({"fold", pattern, "--fraction", "0.7", "--no-collision", "-o", g7}).exit, 0);
  }
  foldkit::test::CliResult plan(const std::string& goal, const std::string& db, const std::string& out, const char* seed = "1") const {
    // 20 s: recall gets a tenth (kRecallShare), ample even under the sanitizers.
    return foldkit({"plan", pattern, "--goal", goal, "--experience", db, "--seed", seed, "--time", "20", "-o", out, "--json"});
  }
};

TEST(PlanExperienceCli, FirstPlanMakesTheDatabaseTheNextRecallsFromIt) {
  const Case c;
  const std::string db = c.dir + "/first.db";
  fs::remove(db);
  const auto first = c.plan(c.g8, db, c.dir + "/p8.cmml");
  ASSERT_EQ(first.exit, 0) << first.err;
  const auto j1 = nlohmann::json::parse(first.out)["experience"];
  EXPECT_FALSE(j1["recalled"].get<bool>());
  EXPECT_EQ(j1["loaded"].get<int>(), 0);
  EXPECT_EQ(j1["paths"].get<int>(), 1);
  EXPECT_EQ(slurp(db).rfind("foldkit-experience 2\n", 0), 0u);
  EXPECT_EQ(j1["bytes"].get<std::size_t>(), fs::file_size(db));

  const auto second = c.plan(c.g7, db, c.dir + "/p7.cmml");
  ASSERT_EQ(second.exit, 0) << second.err;
  const auto j2 = nlohmann::json::parse(second.out)["experience"];
  EXPECT_TRUE(j2["recalled"].get<bool>());
  EXPECT_EQ(j2["loaded"].get<int>(), 1);
  EXPECT_EQ(j2["paths"].get<int>(), 2);
  // The recalled plan is checked by the simulator as any other: replayed again here.
  EXPECT_EQ(foldkit({"simulate", c.pattern, c.dir + "/p7.cmml"}).exit, 0);
}

TEST(PlanExperienceCli, SameDatabaseAndSeedSamePlan) {
  const Case c;
  const std::string db = c.dir + "/seeded.db";
  fs::remove(db);
  ASSERT_EQ(c.plan(c.g8, db, c.dir + "/s8.cmml").exit, 0);
  const std::string stored = slurp(db);
  std::string outs[2];
  for (int run = 0; run < 2; ++run) {
    std::ofstream(db, std::ios::binary) << stored;
    const std::string out = c.dir + "/s7-" + std::to_string(run) + ".cmml";
    const auto r = c.plan(c.g7, db, out, "4");
    ASSERT_EQ(r.exit, 0) << r.err;
    EXPECT_TRUE(nlohmann::json::parse(r.out)["experience"]["recalled"].get<bool>());  // the same way, by recall
    outs[run] = slurp(out);
  }
  EXPECT_FALSE(outs[0].empty());
  EXPECT_EQ(outs[0], outs[1]);
}

TEST(PlanExperienceCli, DamagedOrForeignDatabaseIsRefusedWithNothingWritten) {
  const Case c;
  const std::string db = c.dir + "/damaged.db", out = c.dir + "/never.cmml";
  fs::remove(db);
  ASSERT_EQ(c.plan(c.g8, db, c.dir + "/d8.cmml").exit, 0);
  std::string bytes = slurp(db);
  bytes[bytes.size() - 3] = static_cast<char>(bytes[bytes.size() - 3] ^ 0x10);
  std::ofstream(db, std::ios::binary) << bytes;
  fs::remove(out);
  const auto damaged = c.plan(c.g7, db, out);
  EXPECT_EQ(damaged.exit, 1);
  EXPECT_NE(damaged.err.find(db + ": damaged: the records do not match their CRC-32"), std::string::npos) << damaged.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(slurp(db), bytes);  // left as it was

  // Experience recalls by length only: another objective or a threshold is a usage error.
  const auto rotation = foldkit({"plan", c.pattern, "--goal", c.g7, "--experience", db, "--objective", "rotation", "-o", out});
  EXPECT_EQ(rotation.exit, 2);
  EXPECT_NE(rotation.err.find("--experience recalls by path length only"), std::string::npos) << rotation.err;
  EXPECT_FALSE(fs::exists(out));

  // A database of another pattern (a Miura 6×6's) for this one.
  const std::string m6 = c.dir + "/m6.pmml", g6 = c.dir + "/g6.cmml", other = c.dir + "/m6.db";
  std::ofstream(m6) << foldkit::io::write_pmml(geo::build_or_throw(geo::generators::miura(6, 6)).to_spec());
  ASSERT_EQ(foldkit({"fold", m6, "--fraction", "0.8", "--no-collision", "-o", g6}).exit, 0);
  fs::remove(other);
  ASSERT_EQ(foldkit({"plan", m6, "--goal", g6, "--experience", other, "-o", c.dir + "/p6.cmml"}).exit, 0);
  const auto foreign = c.plan(c.g7, other, out);
  EXPECT_EQ(foreign.exit, 1);
  EXPECT_NE(foreign.err.find(other + ": written for"), std::string::npos) << foreign.err;
  EXPECT_FALSE(fs::exists(out));
}

// --experience-framework thunder: the same file, recalled through Thunder's roadmap, replayed
// valid; an unknown framework, or one without --experience, is a usage error with nothing written.
TEST(PlanExperienceCli, ThunderUsesTheSameDatabaseFile) {
  const Case c;
  const std::string db = c.dir + "/thunder.db", out = c.dir + "/t7.cmml";
  fs::remove(db);
  ASSERT_EQ(c.plan(c.g8, db, c.dir + "/t8.cmml").exit, 0);  // written by Lightning
  const std::string lightning_bytes = slurp(db);
  const auto thunder = [&](const std::string& to) {
    return foldkit({"plan", c.pattern, "--goal", c.g7, "--experience", db, "--experience-framework", "thunder", "--seed", "2",
                    "--time", "20", "-o", to, "--json"});
  };
  // The same database and seed give the same plan, as with Lightning.
  ASSERT_EQ(thunder(c.dir + "/t7-first.cmml").exit, 0);
  std::ofstream(db, std::ios::binary) << lightning_bytes;
  const auto r = thunder(out);
  ASSERT_EQ(r.exit, 0) << r.err;
  EXPECT_EQ(slurp(out), slurp(c.dir + "/t7-first.cmml"));
  const auto j = nlohmann::json::parse(r.out)["experience"];
  EXPECT_EQ(j["framework"].get<std::string>(), "thunder");
  EXPECT_TRUE(j["recalled"].get<bool>());
  EXPECT_EQ(j["loaded"].get<int>(), 1);
  EXPECT_EQ(j["paths"].get<int>(), 2);
  EXPECT_GE(j["states"].get<int>(), 2);
  EXPECT_GE(j["load_seconds"].get<double>(), 0.0);
  EXPECT_EQ(j["bytes"].get<std::size_t>(), fs::file_size(db));
  EXPECT_EQ(foldkit({"simulate", c.pattern, out}).exit, 0);

  const std::string bytes = slurp(db), never = c.dir + "/never-t.cmml";
  const auto unknown = foldkit({"plan", c.pattern, "--goal", c.g7, "--experience", db, "--experience-framework", "storm", "-o", never});
  EXPECT_EQ(unknown.exit, 2);
  EXPECT_NE(unknown.err.find("unknown experience framework 'storm' (known: lightning, thunder)"), std::string::npos) << unknown.err;
  const auto alone = foldkit({"plan", c.pattern, "--goal", c.g7, "--experience-framework", "thunder", "-o", never});
  EXPECT_EQ(alone.exit, 2);
  EXPECT_NE(alone.err.find("--experience-framework needs --experience DB"), std::string::npos) << alone.err;
  EXPECT_FALSE(fs::exists(never));
  EXPECT_EQ(slurp(db), bytes);
}

// Thunder writes its roadmap into the file: the next process reads it instead of rebuilding it
// (the header says how many paths it covers), gives the same plan for the same bytes and seed,
// refuses a damaged roadmap with the reason and nothing written; Lightning carries the section
// unchanged, and a file from before the section (version 1) still loads.
TEST(PlanExperienceCli, ThunderRoadmapTravelsInTheFile) {
  const Case c;
  const std::string db = c.dir + "/roadmap.db", never = c.dir + "/never-r.cmml";
  fs::remove(db);
  const auto thunder = [&](const std::string& goal, const std::string& to, const char* framework = "thunder") {
    return foldkit({"plan", c.pattern, "--goal", goal, "--experience", db, "--experience-framework", framework, "--seed", "3", "--time",
                    "20", "-o", to, "--json"});
  };
  ASSERT_EQ(thunder(c.g8, c.dir + "/r8.cmml").exit, 0);
  const std::string stored = slurp(db);
  EXPECT_NE(stored.find("\nroadmap-paths 1\n"), std::string::npos) << stored.substr(0, 200);
  std::string outs[2];
  for (int run = 0; run < 2; ++run) {
    std::ofstream(db, std::ios::binary) << stored;
    outs[run] = c.dir + "/r7-" + std::to_string(run) + ".cmml";
    const auto r = thunder(c.g7, outs[run]);
    ASSERT_EQ(r.exit, 0) << r.err;
    EXPECT_TRUE(nlohmann::json::parse(r.out)["experience"]["recalled"].get<bool>());
  }
  EXPECT_EQ(slurp(outs[0]), slurp(outs[1]));
  const std::string two = slurp(db);
  EXPECT_NE(two.find("\nroadmap-paths 2\n"), std::string::npos);

  std::string damaged = two;
  damaged.back() = static_cast<char>(damaged.back() ^ 0x10);  // the roadmap's last record
  std::ofstream(db, std::ios::binary) << damaged;
  fs::remove(never);
  for (const char* framework : {"thunder", "lightning"}) {
    const auto r = thunder(c.g7, never, framework);
    EXPECT_EQ(r.exit, 1) << framework;
    EXPECT_NE(r.err.find(db + ": damaged: the roadmap's records do not match their CRC-32"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(never));
  EXPECT_EQ(slurp(db), damaged);

  std::ofstream(db, std::ios::binary) << two;
  ASSERT_EQ(thunder(c.g8, c.dir + "/l8.cmml", "lightning").exit, 0);
  const std::string carried = slurp(db);
  const std::size_t roadmap_bytes = std::stoull(two.substr(two.find("\nroadmap-bytes ") + 15));
  ASSERT_GT(roadmap_bytes, 0u);
  EXPECT_EQ(carried.substr(carried.size() - roadmap_bytes), two.substr(two.size() - roadmap_bytes));
  EXPECT_NE(carried.find("\nroadmap-paths 2\n"), std::string::npos);  // of its 3 paths

  // A version 1 file (Lightning's without the roadmap lines): Thunder rebuilds its roadmap.
  fs::remove(db);
  ASSERT_EQ(thunder(c.g8, c.dir + "/v8.cmml", "lightning").exit, 0);
  std::istringstream lines(slurp(db));
  std::string v1, line;
  while (std::getline(lines, line) && line.rfind("roadmap-crc ", 0) != 0)
    if (line.rfind("roadmap-", 0) != 0) v1 += (v1.empty() ? std::string("foldkit-experience 1") : line) + "\n";
  v1 += std::string(std::istreambuf_iterator<char>(lines), {});
  std::ofstream(db, std::ios::binary) << v1;
  const auto old = thunder(c.g7, c.dir + "/v7.cmml");
  ASSERT_EQ(old.exit, 0) << old.err;
  EXPECT_EQ(nlohmann::json::parse(old.out)["experience"]["loaded"].get<int>(), 1);
  EXPECT_NE(slurp(db).find("foldkit-experience 2\n"), std::string::npos);
  EXPECT_NE(slurp(db).find("\nroadmap-paths 2\n"), std::string::npos);
}

}  // namespace
