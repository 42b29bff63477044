#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using foldkit::test::foldkit;
using foldkit::test::slurp;
using foldkit::test::temp_dir;

// A three-panel strip and a one-event CMML folding its two creases to the given angles.
struct StripCase {
  std::string dir, pmml, cmml;
};

StripCase strip_case(const std::string& a1, const std::string& a2, const std::string& velocity = "45") {
  StripCase c{temp_dir(), "", ""};
  c.pmml = c.dir + "/strip.pmml";
  c.cmml = c.dir + "/seq.cmml";
  EXPECT_EQ(foldkit({"generate", "strip", "--panels", "3", "-o", c.pmml}).exit, 0);
  std::ofstream(c.cmml) << "<CMML>\n  <Title>t</Title>\n"
                        << "  <Fold><EventNumber>1</EventNumber><ID>1</ID><FoldAngle>" << a1 << "</FoldAngle><Velocity>"
                        << velocity << "</Velocity></Fold>\n"
                        << "  <Fold><EventNumber>1</EventNumber><ID>2</ID><FoldAngle>" << a2
                        << "</FoldAngle><Velocity>45</Velocity></Fold>\n</CMML>\n";
  return c;
}

TEST(SimulateCli, ValidZigZagExitsZeroWithReport) {
  const StripCase c = strip_case("170", "-170");
  const auto r = foldkit({"simulate", c.pmml, c.cmml, "--json"});
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);  // exactly one object
  EXPECT_TRUE(j["ok"].get<bool>());
  EXPECT_EQ(j["status"], "success");
  EXPECT_EQ(j["collisions"].size(), 0u);
  EXPECT_EQ(j["max_closure_error"].get<double>(), 0.0);
  ASSERT_EQ(j["events"].size(), 1u);
  EXPECT_NEAR(j["events"][0]["end"].get<double>(), 170.0 / 45.0, 1e-12);
  EXPECT_NEAR(j["duration"].get<double>(), 170.0 / 45.0, 1e-12);
  EXPECT_EQ(j["model"], "motor");
  EXPECT_NEAR(j["final_angles"][1]["angle"].get<double>(), -170.0, 1e-9);
  EXPECT_NE(r.err.find("valid"), std::string::npos);
}

TEST(SimulateCli, RollingCollisionExitsThreeAndNamesTheActors) {
  const StripCase c = strip_case("170", "170");
  const std::string frames = c.dir + "/trajectory.fold", svg = c.dir + "/snaps";
  const auto r = foldkit({"simulate", c.pmml, c.cmml, "--json", "--frames", frames, "--svg", svg});
  ASSERT_EQ(r.exit, 3) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_FALSE(j["ok"].get<bool>());
  EXPECT_EQ(j["status"], "collision");
  EXPECT_EQ(j["message"], j["problems"][0]);
  ASSERT_EQ(j["collisions"].size(), 1u);
  const auto& hit = j["collisions"][0];
  EXPECT_EQ(hit["actors"], nlohmann::json({1, 3}));
  EXPECT_EQ(hit["event"], 1);
  EXPECT_GT(hit["time"].get<double>(), 0.0);
  EXPECT_EQ(hit["point"].size(), 3u);
  // Outputs people look at: the trajectory as FOLD frames, and snapshots with the collision.
  const auto fold = nlohmann::json::parse(slurp(frames));
  EXPECT_GT(fold["file_frames"].size(), 100u);
  EXPECT_TRUE(fs::exists(svg + "/event-1.svg"));
  const std::string shot = slurp(svg + "/collision-1.svg");
  EXPECT_NE(shot.find("actors 1 and 3"), std::string::npos);
  EXPECT_NE(shot.find("<polygon"), std::string::npos);
  // Without collision checks only closure is judged, and a strip has none to break.
  EXPECT_EQ(foldkit({"simulate", c.pmml, c.cmml, "--no-collision"}).exit, 0);
}

// Same input, same bytes: the report, the trajectory and the snapshots.
TEST(SimulateCli, DeterministicOutputs) {
  const StripCase c = strip_case("170", "170");
  std::vector<std::string> outs;
  for (const char* run : {"a", "b"}) {
    const std::string frames = c.dir + "/" + run + ".fold", svg = c.dir + "/" + run + "-svg";
    const auto r = foldkit({"simulate", c.pmml, c.cmml, "--json", "--model", "spring", "--frames", frames, "--svg", svg});
    ASSERT_EQ(r.exit, 3) << r.err;
    outs.push_back(r.out + slurp(frames) + slurp(svg + "/collision-1.svg") + slurp(svg + "/event-1.svg"));
  }
  EXPECT_GT(outs[0].size(), 1000u);
  EXPECT_EQ(outs[0], outs[1]);
}

TEST(SimulateCli, ModelsAndOptions) {
  const StripCase c = strip_case("90", "-90");
  for (const char* model : {"motor", "spring", "sync"}) {
    const auto r = foldkit({"simulate", c.pmml, c.cmml, "--json", "--model", model, "--time-step", "0.05"});
    ASSERT_EQ(r.exit, 0) << model << ": " << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["model"], model);
  }
  EXPECT_EQ(foldkit({"simulate", c.pmml, c.cmml, "--model", "hydraulic"}).exit, 2);
  EXPECT_EQ(foldkit({"simulate", c.pmml, c.cmml, "--time-step", "0"}).exit, 2);
  EXPECT_EQ(foldkit({"simulate", c.pmml, c.cmml, "--frames", c.dir + "/x.txt"}).exit, 2);
  EXPECT_EQ(foldkit({"simulate", c.pmml}).exit, 2);
}

TEST(SimulateCli, BadSequencesExitOneWithFileAndLine) {
  StripCase c = strip_case("90", "90");
  std::ofstream(c.cmml) << "<CMML>\n  <Title>t</Title>\n"
                        << "  <Fold><EventNumber>1</EventNumber><ID>9</ID><FoldAngle>10</FoldAngle><Velocity>1</Velocity></Fold>\n"
                        << "</CMML>\n";
  auto r = foldkit({"simulate", c.pmml, c.cmml});
  EXPECT_EQ(r.exit, 1);
  EXPECT_NE(r.err.find(c.cmml + ":3:"), std::string::npos) << r.err;
  // A velocity so small that the event would take more steps than the simulator allows.
  c = strip_case("90", "0", "1e-12");
  r = foldkit({"simulate", c.pmml, c.cmml, "--frames", c.dir + "/never.fold"});
  EXPECT_EQ(r.exit, 1);
  EXPECT_NE(r.err.find(c.cmml + ":3:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("steps"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(c.dir + "/never.fold"));  // nothing half-written
}

}  // namespace
