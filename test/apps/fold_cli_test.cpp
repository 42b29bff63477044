// foldkit fold: exit codes, JSON keys, no file unless the target is reached, and the written CMML
// judged by another verb (`foldkit simulate`).
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/io/pmml.hpp"

namespace {

using foldkit::test::foldkit;
using foldkit::test::slurp;
using foldkit::test::temp_dir;
namespace geo = foldkit::geometry;

std::string dir() {
  const std::string d = temp_dir() + "/fold-cli";
  std::filesystem::create_directories(d);
  return d;
}

std::string write_pattern(const std::string& name, const geo::PatternSpec& spec) {
  const std::string path = dir() + "/" + name;
  std::ofstream(path) << foldkit::io::write_pmml(geo::build_or_throw(spec).to_spec());
  return path;
}

TEST(FoldCli, FoldsAMiuraAndTheSimulatorAcceptsTheFile) {
  const std::string pattern = write_pattern("miura.pmml", geo::generators::miura(3, 3));
  const std::string out = dir() + "/miura.cmml";
  std::filesystem::remove(out);
  const auto r = foldkit({"fold", pattern, "--fraction", "0.6", "-o", out, "--json"});
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"stop", "fraction", "steps", "max_closure_error", "time", "replay_ok", "message", "output"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["stop"], "reached");
  EXPECT_EQ(j["status"], "success");
  EXPECT_NEAR(j["fraction"].get<double>(), 0.6, 1e-9);
  EXPECT_LE(j["max_closure_error"].get<double>(), 1e-10);
  EXPECT_TRUE(j["replay_ok"].get<bool>());
  EXPECT_GT(j["steps"].get<int>(), 10);
  ASSERT_TRUE(std::filesystem::exists(out));
  const auto sim = foldkit({"simulate", pattern, out, "--json"});
  EXPECT_EQ(sim.exit, 0) << sim.err;
}

TEST(FoldCli, SameInputGivesTheSameFile) {
  const std::string pattern = write_pattern("waterbomb.pmml", geo::generators::waterbomb(2, 2));
  const std::string a = dir() + "/a.cmml", b = dir() + "/b.cmml";
  for (const auto& out : {a, b}) ASSERT_EQ(foldkit({"fold", pattern, "--fraction", "0.4", "--no-collision", "-o", out}).exit, 0);
  EXPECT_EQ(slurp(a), slurp(b));
}

TEST(FoldCli, SquareTwistExitsFourAndWritesNothing) {
  const std::string pattern = write_pattern("twist.pmml", geo::generators::square_twist());
  const std::string out = dir() + "/twist.cmml";
  std::filesystem::remove(out);
  const auto r = foldkit({"fold", pattern, "-o", out, "--json"});
  EXPECT_EQ(r.exit, 4) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["stop"], "not-rigidly-foldable");
  EXPECT_EQ(j["status"], "not-rigidly-foldable");
  EXPECT_EQ(j["fraction"].get<double>(), 0.0);
  EXPECT_TRUE(j["output"].is_null());
  EXPECT_NE(r.err.find("not-rigidly-foldable"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(FoldCli, CollisionExitsFourAndPartialWritesThePathSoFar) {
  const std::string pattern = write_pattern("strip.pmml", geo::generators::strip(3));
  const std::string out = dir() + "/strip.cmml";
  std::filesystem::remove(out);
  // The strip has no assignment: both creases mountain through --velocity.
  auto r = foldkit({"fold", pattern, "--velocity", "1:1,2:1", "-o", out, "--json"});
  EXPECT_EQ(r.exit, 4) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["stop"], "collision");
  EXPECT_EQ(nlohmann::json::parse(r.out)["status"], "collision");
  EXPECT_FALSE(std::filesystem::exists(out));
  r = foldkit({"fold", pattern, "--velocity", "1:1,2:1", "--partial", "-o", out});
  EXPECT_EQ(r.exit, 4) << r.err;
  ASSERT_TRUE(std::filesystem::exists(out));
  EXPECT_EQ(foldkit({"simulate", pattern, out}).exit, 0);
}

// --chord-tolerance sizes the steps (a tighter one takes more), the JSON reports the largest
// chord error within it, and 0 takes fixed steps of --step.
TEST(FoldCli, ChordToleranceSizesTheSteps) {
  const std::string pattern = write_pattern("miura-chord.pmml", geo::generators::miura(3, 3));
  const std::string out = dir() + "/chord.cmml";
  int last_steps = 0;
  for (const char* tolerance : {"1e-4", "1e-5", "0"}) {
    std::vector<std::string> args = {"fold", pattern, "--fraction", "0.6", "--chord-tolerance", tolerance, "-o", out, "--json"};
    if (std::string(tolerance) == "0") args.insert(args.end(), {"--step", "0.005"});
    const auto r = foldkit(args);
    ASSERT_EQ(r.exit, 0) << tolerance << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const double chord = j["max_chord_error"].get<double>();
    if (std::string(tolerance) != "0") {
      EXPECT_LE(chord, std::stod(tolerance)) << tolerance;
    }
    EXPECT_GT(j["steps"].get<int>(), last_steps) << tolerance;
    last_steps = j["steps"].get<int>();
    EXPECT_TRUE(j["replay_ok"].get<bool>()) << tolerance;
  }
  EXPECT_EQ(foldkit({"fold", pattern, "--chord-tolerance", "1e-12", "-o", out}).exit, 2);
  EXPECT_EQ(foldkit({"fold", pattern, "--chord-tolerance", "-1", "-o", out}).exit, 2);
}

TEST(FoldCli, BadInputAndUsage) {
  const std::string miura = write_pattern("m2.pmml", geo::generators::miura(2, 2));
  const std::string boat = write_pattern("boat.pmml", geo::generators::boat());
  const std::string out = dir() + "/never.cmml";
  EXPECT_EQ(foldkit({"fold", dir() + "/missing.pmml", "-o", out}).exit, 1);
  EXPECT_EQ(foldkit({"fold", boat, "-o", out}).exit, 1);  // no assignment and no --velocity
  EXPECT_EQ(foldkit({"fold", boat, "--velocity", "1:0", "-o", out}).exit, 2);  // a zero velocity is a usage error
  EXPECT_EQ(foldkit({"fold", miura, "--velocity", "99:1", "-o", out}).exit, 2);
  EXPECT_EQ(foldkit({"fold", miura, "--velocity", "1:x", "-o", out}).exit, 2);
  EXPECT_EQ(foldkit({"fold", miura, "--velocity", "1:1,1:1", "-o", out}).exit, 2);
  EXPECT_EQ(foldkit({"fold", miura, "--fraction", "1.5", "-o", out}).exit, 2);
  EXPECT_EQ(foldkit({"fold", miura, "-o", dir() + "/out.txt"}).exit, 2);
  EXPECT_EQ(foldkit({"fold", miura}).exit, 2);
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
