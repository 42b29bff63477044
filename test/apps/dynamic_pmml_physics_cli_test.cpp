// `foldkit simulate --model dynamic` with the sheet's physics in its PMML (foldkit's extensions
// <Density>, <Gravity>, <FixedActor>): the file's values are the run's, the CLI's options override
// them, the kinematic models ignore them, and bad values are the file's errors at their lines.
// Checked against the closed form m·g·d of the panel the motor lifts.
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

// Two panels of unequal size on the hinge x = 1: actor 1 the unit square [0,1]², actor 2 the
// rectangle [1,3]×[0,1]. At scale 0.5 m per unit and ρ kg/m², lifting actor 1 (actor 2 held) takes
// m·g·d = (0.25ρ)·g·0.25, lifting actor 2 (actor 1 held) (0.5ρ)·g·0.5: four times as much.
std::string unequal_panels(const std::string& physics) {
  return "<PMML>\n  <Title>unequal panels</Title>\n" + physics +
         "  <Actor><ID>1</ID><Triangle>0 0 1 0 1 1</Triangle><Triangle>0 0 1 1 0 1</Triangle></Actor>\n"
         "  <Actor><ID>2</ID><Triangle>1 0 3 0 3 1</Triangle><Triangle>1 0 3 1 1 1</Triangle></Actor>\n"
         "  <Joint><ID>1</ID><Coords>1 0 1 1</Coords><ActorIDs>1 2</ActorIDs><SpringConst>0</SpringConst>"
         "<DampConst>0</DampConst></Joint>\n</PMML>\n";
}

// The file's physics: ρ = 2 kg/m², g = 9.81 m/s² down, actor 2 held (lines 3, 4, 5).
const char* const kFilePhysics = "  <Density>2</Density>\n  <Gravity>0 0 -9.81</Gravity>\n  <FixedActor>2</FixedActor>\n";
// m·g·d of actor 1 at ρ = 2, g = 9.81, scale 0.5: m = 0.5 kg, d = 0.25 m.
constexpr double kLift = 0.5 * 9.81 * 0.25;

struct Files {
  std::string dir, pmml, cmml;
};

// The pattern with `physics` and a CMML turning joint 1 to −60° (the free panel rises) at 30°/s.
Files files(const std::string& physics) {
  Files f{temp_dir(), "", ""};
  f.pmml = f.dir + "/panels.pmml";
  f.cmml = f.dir + "/lift.cmml";
  std::ofstream(f.pmml) << unequal_panels(physics);
  std::ofstream(f.cmml) << "<CMML>\n  <Title>lift</Title>\n  <Fold><EventNumber>1</EventNumber><ID>1</ID>"
                           "<FoldAngle>-60</FoldAngle><Velocity>30</Velocity></Fold>\n</CMML>\n";
  return f;
}

// A dynamic run with torque limit `torque` (N·m) and `extra` options; its JSON report.
nlohmann::json run(const Files& f, double torque, const std::vector<std::string>& extra, int expected_exit) {
  std::vector<std::string> args = {"simulate", f.pmml, f.cmml, "--model", "dynamic", "--scale", "0.5",
                                   "--max-torque", std::to_string(torque), "--json"};
  args.insert(args.end(), extra.begin(), extra.end());
  const auto r = foldkit(args);
  EXPECT_EQ(r.exit, expected_exit) << r.err;
  return r.exit == 0 || r.exit == 3 ? nlohmann::json::parse(r.out) : nlohmann::json();
}

// The torque a stalled run found the joint needs, N·m.
double needed(const nlohmann::json& j) {
  EXPECT_EQ(j["status"], "no-progress") << j.dump();
  return j["stalls"].empty() ? 0.0 : j["stalls"][0]["needed_torque"].get<double>();
}

TEST(DynamicPmmlPhysicsCli, TheFilesDensityGravityAndFixedActorAreTheRunsSettings) {
  const Files f = files(kFilePhysics);
  // Actor 2 held, actor 1 lifted against ρ = 2 and g = 9.81: m·g·d = kLift (not 4·kLift, not 0).
  const auto stalled = run(f, 0.95 * kLift, {}, 3);
  EXPECT_NEAR(needed(stalled), kLift, 0.01 * kLift);
  EXPECT_EQ(stalled["density"], 2.0);
  EXPECT_EQ(stalled["gravity"], nlohmann::json({0.0, 0.0, -9.81}));
  EXPECT_EQ(stalled["fixed"], 2);
  const auto lifted = run(f, 1.05 * kLift, {}, 0);
  EXPECT_EQ(lifted["status"], "success");
  EXPECT_NEAR(lifted["final_angles"][0]["angle"].get<double>(), -60.0, 0.01);
  // Lifted by 60°: actor 1's centre of mass rose d·sin 60°.
  EXPECT_NEAR(lifted["energy"]["potential"].get<double>(), kLift * std::sin(M_PI / 3), 1e-3 * kLift);
}

TEST(DynamicPmmlPhysicsCli, TheCliOptionsOverrideTheFile) {
  const Files f = files(kFilePhysics);
  const auto lighter = run(f, 0.45 * kLift, {"--density", "1"}, 3);  // half the mass
  EXPECT_NEAR(needed(lighter), 0.5 * kLift, 0.01 * kLift);
  EXPECT_EQ(lighter["density"], 1.0);
  const auto stronger = run(f, 1.05 * kLift, {"--gravity", "0,0,-19.62"}, 3);  // twice the gravity
  EXPECT_NEAR(needed(stronger), 2.0 * kLift, 0.02 * kLift);
  EXPECT_EQ(stronger["gravity"], nlohmann::json({0.0, 0.0, -19.62}));
  const auto other_side = run(f, 1.05 * kLift, {"--fixed", "1"}, 3);  // actor 2 lifted instead
  EXPECT_NEAR(needed(other_side), 4.0 * kLift, 0.04 * kLift);
  EXPECT_EQ(other_side["fixed"], 1);
  // No actor held: the sheet falls freely under the file's gravity; nothing to lift against.
  const auto free = run(f, 0.95 * kLift, {"--fixed", "none"}, 0);
  EXPECT_EQ(free["fixed"], "none");
}

// Without the extensions the built-in defaults hold: ρ = 1, no gravity, the first actor held.
TEST(DynamicPmmlPhysicsCli, WithoutThemTheDefaultsHold) {
  const Files f = files("");
  const auto j = run(f, 1e-3, {}, 0);  // weightless: any torque lifts
  EXPECT_EQ(j["density"], 1.0);
  EXPECT_EQ(j["gravity"], nlohmann::json({0.0, 0.0, 0.0}));
  EXPECT_EQ(j["fixed"], 1);
  // The file's gravity alone, actor 1 held by default: actor 2 at ρ = 1 needs (0.5·g·0.5)·0.5 = 2·kLift.
  const Files g = files("  <Gravity>0 0 -9.81</Gravity>\n");
  EXPECT_NEAR(needed(run(g, 1.05 * kLift, {}, 3)), 2.0 * kLift, 0.02 * kLift);
}

TEST(DynamicPmmlPhysicsCli, TheKinematicModelsAndConvertTakeTheFileAsItIs) {
  const Files f = files(kFilePhysics);
  EXPECT_EQ(foldkit({"simulate", f.pmml, f.cmml}).exit, 0);
  EXPECT_EQ(foldkit({"simulate", f.pmml, f.cmml, "--model", "sync"}).exit, 0);
  const std::string copy = f.dir + "/copy.pmml";
  ASSERT_EQ(foldkit({"convert", f.pmml, copy}).exit, 0);
  const std::string text = foldkit::test::slurp(copy);
  for (const char* element : {"<Density>2</Density>", "<Gravity>0 0 -9.81</Gravity>", "<FixedActor>2</FixedActor>"})
    EXPECT_NE(text.find(element), std::string::npos) << element << " in\n" << text;
}

TEST(DynamicPmmlPhysicsCli, BadValuesAreTheFilesErrorsAtTheirLinesWithoutOutput) {
  const struct {
    std::string physics, message;
  } bad[] = {{"  <Density>-1</Density>\n", "panels.pmml:3: density must be positive and finite"},
             {"  <Density>nan</Density>\n", "panels.pmml:3: <Density>"},
             {"  <Gravity>0 0 -9.81</Gravity>\n  <FixedActor>9</FixedActor>\n", "panels.pmml:4: fixed actor 9 does not exist"},
             {"  <Gravity>0,0,-9.81</Gravity>\n", "panels.pmml:3: <Gravity>"},
             {"  <Gravity>0 -9.81</Gravity>\n", "panels.pmml:3: <Gravity> needs 3 numbers"}};
  for (const auto& b : bad) {
    const Files f = files(b.physics);
    const std::string frames = f.dir + "/never.fold";
    const auto r = foldkit({"simulate", f.pmml, f.cmml, "--model", "dynamic", "--frames", frames});
    EXPECT_EQ(r.exit, 1) << b.physics << r.err;
    EXPECT_NE(r.err.find(b.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(frames));
  }
}

}  // namespace
