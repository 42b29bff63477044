// `foldkit simulate --model dynamic` with contacts (--ground, --contacts, --thickness, --friction),
// --start and --joint-torque: a flap folded down onto the ground stops where its far edge touches
// it (a closed form), exit 3 naming the contact; the refusals.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using foldkit::test::foldkit;
using foldkit::test::temp_dir;

// A two-panel strip (unit squares, panel 1 held, scale 0.5 m) and a CMML turning joint 1 to
// `degrees` at 30°/s (positive: panel 2 down, below the held panel).
struct Strip {
  std::string dir, pmml, cmml;
};

std::string write_cmml(const std::string& path, double degrees, int joint = 1) {
  std::ofstream(path) << "<CMML>\n  <Title>turn</Title>\n  <Fold><EventNumber>1</EventNumber><ID>" << joint
                      << "</ID><FoldAngle>" << degrees << "</FoldAngle><Velocity>30</Velocity></Fold>\n</CMML>\n";
  return path;
}

Strip strip(double degrees) {
  Strip s{temp_dir(), "", ""};
  s.pmml = s.dir + "/strip.pmml";
  EXPECT_EQ(foldkit({"generate", "strip", "--panels", "2", "-o", s.pmml}).exit, 0);
  s.cmml = write_cmml(s.dir + "/turn.cmml", degrees);
  return s;
}

TEST(DynamicContactCli, FlapFoldedIntoTheGroundIsBlockedWhereItsEdgeTouches) {
  const Strip s = strip(60);
  const double L = 0.5, h = 0.25, t = 0.002;
  const auto r = foldkit({"simulate", s.pmml, s.cmml, "--model", "dynamic", "--scale", "0.5", "--ground", "-0.25",
                          "--thickness", "0.002", "--json"});
  ASSERT_EQ(r.exit, 3) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "collision");
  ASSERT_EQ(j["stalls"].size(), 1u);
  EXPECT_EQ(j["stalls"][0]["joint"], 1);
  EXPECT_EQ(j["stalls"][0]["blocked_by"], nlohmann::json::array({2}));
  EXPECT_NE(r.err.find("joint 1 blocked"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("actor 2 and the ground"), std::string::npos) << r.err;
  // The far edge's lower corner on the ground: L sin φ + (t/2) cos φ = h.
  double phi = std::asin(h / L);
  for (int i = 0; i < 50; ++i)
    phi -= (L * std::sin(phi) + t / 2 * std::cos(phi) - h) / (L * std::cos(phi) - t / 2 * std::sin(phi));
  // Pressed by its motor (1 N·m) the flap sinks by the contact's penetration: within t/10 over L.
  EXPECT_NEAR(j["final_angles"][0]["angle"].get<double>(), phi * 180 / M_PI, 0.1 * t / L * 180 / M_PI);
  ASSERT_EQ(j["contacts"].size(), 1u);
  EXPECT_TRUE(j["contacts"][0]["ground"].get<bool>());
  EXPECT_EQ(j["contacts"][0]["actors"], nlohmann::json::array({2}));
  EXPECT_LE(j["max_penetration"].get<double>(), 0.1 * t);
  EXPECT_DOUBLE_EQ(j["thickness"].get<double>(), t);
  // The run's settings, defaults included.
  EXPECT_DOUBLE_EQ(j["ground"].get<double>(), -h);
  EXPECT_EQ(j["facet_contacts"], false);
  EXPECT_DOUBLE_EQ(j["friction"].get<double>(), 0.5);
  EXPECT_EQ(j["fixed"], 1);
  EXPECT_EQ(j["solver"], "direct");
  EXPECT_EQ(j["iterations"], 100);
  EXPECT_DOUBLE_EQ(j["projection_interval"].get<double>(), 0.0);
  // Without the ground the motor reaches its angle, and no contact is reported.
  const auto free = foldkit({"simulate", s.pmml, s.cmml, "--model", "dynamic", "--scale", "0.5", "--json"});
  ASSERT_EQ(free.exit, 0) << free.err;
  const auto jf = nlohmann::json::parse(free.out);
  EXPECT_TRUE(jf["contacts"].empty());
  EXPECT_TRUE(jf["thickness"].is_null());
  EXPECT_TRUE(jf["ground"].is_null());
  EXPECT_TRUE(jf["friction"].is_null());  // nothing to touch: no friction
}

TEST(DynamicContactCli, StartStateAndJointTorque) {
  const Strip s = strip(-60);
  const std::string start = write_cmml(s.dir + "/start.cmml", -30);
  // From −30° at rest the motor turns 30° at 30°/s: about 1 s, not the 2 s from flat.
  const auto r = foldkit({"simulate", s.pmml, s.cmml, "--model", "dynamic", "--start", start, "--json"});
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["final_angles"][0]["angle"].get<double>(), -60.0, 0.01);
  EXPECT_LT(j["duration"].get<double>(), 1.3);
  EXPECT_GT(j["duration"].get<double>(), 0.9);
  // Under gravity (m g d = 0.5·9.81·0.25 N·m at density 2, scale 0.5) --max-torque 0.1 stalls:
  // the flap falls and swings below the base, and where it came closest (flat) it needed m g d;
  // --joint-torque 1:2 gives joint 1 its own limit and it lifts.
  const double mgd = 0.5 * 9.81 * 0.25;
  const std::vector<std::string> heavy = {"simulate", s.pmml, s.cmml, "--model", "dynamic", "--gravity", "0,0,-9.81",
                                          "--density", "2", "--scale", "0.5", "--max-torque", "0.1"};
  auto weak = heavy;
  weak.push_back("--json");
  const auto stalled = foldkit(weak);
  ASSERT_EQ(stalled.exit, 3) << stalled.err;
  const auto js = nlohmann::json::parse(stalled.out);
  EXPECT_EQ(js["status"], "no-progress");
  ASSERT_EQ(js["stalls"].size(), 1u);
  EXPECT_EQ(js["stalls"][0]["joint"], 1);
  EXPECT_TRUE(js["stalls"][0]["blocked_by"].empty());
  EXPECT_NEAR(js["stalls"][0]["needed_torque"].get<double>(), mgd, 0.01 * mgd);
  EXPECT_NE(stalled.err.find("joint 1 stalled"), std::string::npos) << stalled.err;
  // Resting on the ground the flap is lifted off it, which pushes it up: still a stall needing m g
  // d (the ground's help left out), not a collision.
  auto grounded = weak;
  grounded.insert(grounded.end(), {"--ground", "-0.001", "--thickness", "0.002"});
  const auto on_ground = foldkit(grounded);
  ASSERT_EQ(on_ground.exit, 3) << on_ground.err;
  const auto jg = nlohmann::json::parse(on_ground.out);
  EXPECT_EQ(jg["status"], "no-progress");
  ASSERT_EQ(jg["stalls"].size(), 1u);
  EXPECT_TRUE(jg["stalls"][0]["blocked_by"].empty());
  EXPECT_NEAR(jg["stalls"][0]["needed_torque"].get<double>(), mgd, 0.01 * mgd);
  auto strong = heavy;
  strong.insert(strong.end(), {"--joint-torque", "1:2"});
  const auto lifted = foldkit(strong);
  EXPECT_EQ(lifted.exit, 0) << lifted.err;
}

// --fixed none: no actor held; without gravity the free strip still folds to its angle.
TEST(DynamicContactCli, FreeSheetFoldsWithNoActorHeld) {
  const Strip s = strip(60);
  const auto r = foldkit({"simulate", s.pmml, s.cmml, "--model", "dynamic", "--fixed", "none", "--json"});
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["final_angles"][0]["angle"].get<double>(), 60.0, 0.01);
  EXPECT_NEAR(j["energy"]["potential"].get<double>(), 0.0, 1e-12);  // no gravity
  EXPECT_EQ(j["fixed"], "none");
}

TEST(DynamicContactCli, BadContactOptionsAreRefusedWithoutOutput) {
  const Strip s = strip(60);
  const std::string frames = s.dir + "/never.fold";
  const std::vector<std::vector<std::string>> usage = {
      {"--friction", "-1"}, {"--friction", "nan"}, {"--thickness", "0"}, {"--thickness", "-1"}, {"--ground", "nan"},
      {"--fixed", "abc"},   {"--joint-torque", "9:1"}, {"--joint-torque", "1:-1"}, {"--joint-torque", "1"}};
  for (const auto& extra : usage) {
    std::vector<std::string> args = {"simulate", s.pmml, s.cmml, "--model", "dynamic", "--frames", frames};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = foldkit(args);
    EXPECT_EQ(r.exit, 2) << extra[0] << " " << extra[1] << ": " << r.err;
    EXPECT_FALSE(fs::exists(frames));
  }
  // Friction and thickness with nothing to touch would be ignored: refused.
  EXPECT_EQ(foldkit({"simulate", s.pmml, s.cmml, "--model", "dynamic", "--friction", "0.3"}).exit, 2);
  EXPECT_EQ(foldkit({"simulate", s.pmml, s.cmml, "--model", "dynamic", "--thickness", "0.01"}).exit, 2);
  // The dynamic model's contacts are refused for the kinematic ones.
  EXPECT_EQ(foldkit({"simulate", s.pmml, s.cmml, "--contacts"}).exit, 2);
  EXPECT_EQ(foldkit({"simulate", s.pmml, s.cmml, "--ground", "0"}).exit, 2);
  // A --start CMML folding a joint the pattern lacks: invalid input at its line.
  const std::string bad = write_cmml(s.dir + "/bad-start.cmml", 30, 7);
  const auto r = foldkit({"simulate", s.pmml, s.cmml, "--model", "dynamic", "--start", bad, "--frames", frames});
  EXPECT_EQ(r.exit, 1) << r.err;
  EXPECT_NE(r.err.find("bad-start.cmml:3"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(frames));
}

}  // namespace
