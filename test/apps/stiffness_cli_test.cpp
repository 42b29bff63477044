// foldkit stiffness: JSON fields, the closed form through the command line, bad load cases.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "test_paths.hpp"

namespace {

namespace fs = std::filesystem;
using foldkit::test::CliResult;
using foldkit::test::data_path;
using foldkit::test::foldkit;
using foldkit::test::temp_dir;

std::string strip_pmml(const std::string& dir) {
  const std::string path = dir + "/strip.pmml";
  EXPECT_EQ(foldkit({"generate", "strip", "--panels", "4", "-o", path}).exit, 0);
  return path;
}

TEST(StiffnessCli, StripTipLoadMatchesClosedForm) {
  const std::string dir = temp_dir();
  const std::string pmml = strip_pmml(dir);
  for (const char* mode : {"--linear", ""}) {
    std::vector<std::string> args = {"stiffness", pmml, data_path("good/strip-tip.loadcase"), "--json"};
    if (*mode) args.push_back(mode);
    const CliResult r = foldkit(args);
    ASSERT_EQ(r.exit, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_TRUE(j["converged"].get<bool>());
    EXPECT_EQ(j["title"], "strip tip load");
    EXPECT_EQ(j["connections"]["hinged"], 3);
    EXPECT_EQ(j["modules"].size(), 4u);
    EXPECT_TRUE(j["modules"][0]["fixed"].get<bool>());
    // Tip (x = 4) from the last panel's centroid (x = 3.5) and rotation: P·Σdᵢ²/k + 3P/k_t.
    const auto& m = j["modules"][3];
    const double tip = m["displacement"][2].get<double>() - 0.5 * m["rotation"][1].get<double>();
    const double expected = 1e-4 * (9 + 4 + 1) / 3.0 + 3 * 1e-4 / 1e9;
    EXPECT_NEAR(-tip, expected, 1e-4 * expected) << mode;
    EXPECT_GE(j["max_displacement"].get<double>(), 0.0);
    EXPECT_GE(j["residual_norm"].get<double>(), 0.0);
    EXPECT_GT(j["condition_estimate"].get<double>(), 1.0);
    EXPECT_GE(j["iterations"].get<int>(), 1);
  }
}

TEST(StiffnessCli, FoldedCubeFromCmml) {
  const std::string dir = temp_dir();
  ASSERT_EQ(foldkit({"generate", "cube-sheet", "--cubes", "1", "--tile", "0.01", "-o", dir + "/cube.pmml"}).exit, 0);
  const CliResult r = foldkit({"stiffness", dir + "/cube.pmml", data_path("good/cube-top-load.loadcase"), "--state",
                               data_path("good/cube-fold.cmml"), "--json"});
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["connections"]["hinged"], 5);
  EXPECT_EQ(j["connections"]["edge"], 7);
  EXPECT_EQ(j["connections"]["face"], 0);
  EXPECT_GT(j["max_displacement"].get<double>(), 0.0);
  EXPECT_LT(j["max_displacement"].get<double>(), 0.01);
  // Flat, the cube's tiles are a tree of hinges: same file, other connection counts.
  const CliResult flat = foldkit({"stiffness", dir + "/cube.pmml", data_path("good/cube-top-load.loadcase"), "--json"});
  ASSERT_EQ(flat.exit, 0) << flat.err;
  EXPECT_EQ(nlohmann::json::parse(flat.out)["connections"]["edge"], 0);
}

TEST(StiffnessCli, BadLoadCasesExitOneWithFileAndLine) {
  const std::string dir = temp_dir();
  const std::string pmml = strip_pmml(dir);
  int files = 0;
  for (const auto& entry : fs::directory_iterator(data_path("bad"))) {
    if (entry.path().extension() != ".loadcase") continue;
    ++files;
    const std::string path = entry.path().string();
    const CliResult r = foldkit({"stiffness", pmml, path, "--json"});
    EXPECT_EQ(r.exit, 1) << path << "\n" << r.err;
    const std::string escaped = std::regex_replace(path, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)");
    EXPECT_TRUE(std::regex_search(r.err, std::regex("^" + escaped + ":[0-9]+: "))) << r.err;
    EXPECT_TRUE(r.out.empty()) << path;
  }
  EXPECT_GE(files, 10);
}

TEST(StiffnessCli, UsageAndMissingFiles) {
  EXPECT_EQ(foldkit({"stiffness"}).exit, 2);
  EXPECT_EQ(foldkit({"stiffness", "--help"}).exit, 0);
  const std::string dir = temp_dir();
  const std::string pmml = strip_pmml(dir);
  EXPECT_EQ(foldkit({"stiffness", pmml, dir + "/missing.loadcase"}).exit, 1);
}

TEST(StiffnessCli, NotConvergedExitsFour) {
  // One Newton iteration cannot reach a large rotation.
  const std::string dir = temp_dir();
  const std::string pmml = strip_pmml(dir);
  std::ofstream(dir + "/big.loadcase") << "<LoadCase><Fixed>1</Fixed><Load><ActorID>4</ActorID><Force>0 0 -5</Force>"
                                          "<Point>4 0.5 0</Point></Load></LoadCase>";
  const CliResult r = foldkit({"stiffness", pmml, dir + "/big.loadcase", "--max-iterations", "1", "--json"});
  EXPECT_EQ(r.exit, 4) << r.err;
  EXPECT_FALSE(nlohmann::json::parse(r.out)["converged"].get<bool>());
  const CliResult ok = foldkit({"stiffness", pmml, dir + "/big.loadcase", "--json"});
  EXPECT_EQ(ok.exit, 0) << ok.err;
}

}  // namespace
