// `foldkit simulate --model dynamic`: the verdict, the stall report and the refusals, on a flap
// whose lifting torque is known in closed form (m·g·d).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace {

namespace fs = std::filesystem;
using foldkit::test::foldkit;
using foldkit::test::temp_dir;

// A two-panel strip (unit squares, panel 1 held) and a CMML lifting panel 2 to −60° at 30°/s.
struct FlapCase {
  std::string dir, pmml, cmml;
};

FlapCase flap_case(const std::string& joint = "1") {
  FlapCase c{temp_dir(), "", ""};
  c.pmml = c.dir + "/flap.pmml";
  c.cmml = c.dir + "/lift.cmml";
  EXPECT_EQ(foldkit({"generate", "strip", "--panels", "2", "-o", c.pmml}).exit, 0);
  std::ofstream(c.cmml) << "<CMML>\n  <Title>lift</Title>\n  <Fold><EventNumber>1</EventNumber><ID>" << joint
                        << "</ID><FoldAngle>-60</FoldAngle><Velocity>30</Velocity></Fold>\n</CMML>\n";
  return c;
}

// m·g·d of panel 2 at density 2 kg/m², scale 0.5 m per unit, g = 9.81: m = 0.5 kg, d = 0.25 m.
constexpr double kLift = 0.5 * 9.81 * 0.25;

std::vector<std::string> dynamic_args(const FlapCase& c, double torque) {
  return {"simulate", c.pmml,   c.cmml,       "--model", "dynamic", "--gravity", "0,0,-9.81", "--density", "2",
          "--scale",  "0.5",    "--max-torque", std::to_string(torque), "--json"};
}

TEST(DynamicSimulateCli, EnoughTorqueLiftsTheFlap) {
  const FlapCase c = flap_case();
  const std::string frames = c.dir + "/lift.fold", series = c.dir + "/lift.csv";
  auto args = dynamic_args(c, 1.05 * kLift);
  args.insert(args.end(), {"--frames", frames, "--series", series});
  const auto r = foldkit(args);
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "success");
  EXPECT_EQ(j["model"], "dynamic");
  ASSERT_EQ(j["events"].size(), 1u);
  EXPECT_TRUE(j["events"][0]["reached"].get<bool>());
  EXPECT_NEAR(j["final_angles"][0]["angle"].get<double>(), -60.0, 0.01);
  EXPECT_GE(j["joints"][0]["peak_torque"].get<double>(), 0.99 * kLift);
  EXPECT_LE(j["joints"][0]["peak_torque"].get<double>(), 1.05 * kLift * (1 + 1e-3));
  EXPECT_EQ(j["stalls"].size(), 0u);
  EXPECT_TRUE(j["energy"]["potential"].is_number());
  // Lifted by 60°: the centre of mass rose d·sin 60°.
  EXPECT_NEAR(j["energy"]["potential"].get<double>(), kLift * std::sin(M_PI / 3), 1e-3 * kLift);
  EXPECT_TRUE(fs::exists(frames));
  // The series: a header, then time, event, angle (degrees), torque (N·m) every 0.01 s; at 30°
  // lifted and turning steadily the motor carries m·g·d·cos 30°.
  std::ifstream csv(series);
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  EXPECT_EQ(line, "time,event,angle_1,torque_1");
  int rows = 0, steady = 0;
  while (std::getline(csv, line)) {
    double t = 0, angle = 0, torque = 0;
    int event = 0;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%d,%lf,%lf", &t, &event, &angle, &torque), 4) << line;
    ++rows;
    if (angle < -25 && angle > -35) {
      EXPECT_NEAR(-torque, kLift * std::cos(angle * M_PI / 180), 0.01 * kLift) << line;
      ++steady;
    }
  }
  EXPECT_GT(rows, 100);
  EXPECT_GT(steady, 10);
}

// The series as JSON (--series X.json, what the browser app plots) holds the CSV's numbers, by
// column, and the motor's torque is m·g·d·cos θ while it lifts the flap steadily.
TEST(DynamicSimulateCli, SeriesAsJsonHoldsTheCsvsNumbers) {
  const FlapCase c = flap_case();
  const std::string csv_path = c.dir + "/lift.csv", json_path = c.dir + "/lift.json";
  for (const auto& path : {csv_path, json_path}) {
    auto args = dynamic_args(c, 1.05 * kLift);
    args.insert(args.end(), {"--series", path});
    ASSERT_EQ(foldkit(args).exit, 0) << path;
  }
  std::ifstream in(json_path);
  const auto j = nlohmann::json::parse(in);
  ASSERT_EQ(j["joints"].size(), 1u);
  const auto& joint = j["joints"][0];
  EXPECT_EQ(joint["joint"], 1);
  const std::size_t n = j["time"].size();
  ASSERT_GT(n, 100u);
  ASSERT_EQ(j["event"].size(), n);
  ASSERT_EQ(joint["angle"].size(), n);
  ASSERT_EQ(joint["torque"].size(), n);
  std::ifstream csv(csv_path);
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  std::size_t row = 0;
  int steady = 0;
  for (; std::getline(csv, line); ++row) {
    ASSERT_LT(row, n) << "the CSV has more rows than the JSON has frames";
    double t = 0, angle = 0, torque = 0;
    int event = 0;
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%d,%lf,%lf", &t, &event, &angle, &torque), 4) << line;
    // The CSV has 10 significant digits; the JSON every digit.
    EXPECT_NEAR(j["time"][row].get<double>(), t, 1e-9 * (1 + t));
    EXPECT_EQ(j["event"][row].get<int>(), event);
    EXPECT_NEAR(joint["angle"][row].get<double>(), angle, 1e-8 * (1 + std::abs(angle)));
    EXPECT_NEAR(joint["torque"][row].get<double>(), torque, 1e-8 * (1 + std::abs(torque)));
    const double a = joint["angle"][row].get<double>();
    if (a < -25 && a > -35) {
      EXPECT_NEAR(-joint["torque"][row].get<double>(), kLift * std::cos(a * M_PI / 180), 0.01 * kLift);
      ++steady;
    }
  }
  EXPECT_EQ(row, n);
  EXPECT_GT(steady, 10);
  // Times rise by the 0.01 s between frames.
  for (std::size_t k = 1; k < n; ++k) EXPECT_GT(j["time"][k].get<double>(), j["time"][k - 1].get<double>());
}

TEST(DynamicSimulateCli, TooLittleTorqueStallsExitsThreeNamingTheJoint) {
  const FlapCase c = flap_case();
  const auto r = foldkit(dynamic_args(c, 0.95 * kLift));
  ASSERT_EQ(r.exit, 3) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "no-progress");
  ASSERT_EQ(j["stalls"].size(), 1u);
  const auto& s = j["stalls"][0];
  EXPECT_EQ(s["joint"], 1);
  EXPECT_EQ(s["event"], 1);
  EXPECT_NEAR(s["available_torque"].get<double>(), 0.95 * kLift, 1e-6);
  EXPECT_NEAR(s["needed_torque"].get<double>(), kLift, 0.01 * kLift);
  EXPECT_NEAR(s["target"].get<double>(), -60.0, 1e-9);
  EXPECT_GT(s["time"].get<double>(), 0.0);
  EXPECT_FALSE(j["events"][0]["reached"].get<bool>());
  EXPECT_NE(r.err.find("joint 1 stalled"), std::string::npos) << r.err;
}

// --solver, --iterations and --projection-interval reach the engine: the iterative solver,
// post-stabilised, lifts the flap as the direct one does; they are the dynamic model's only.
TEST(DynamicSimulateCli, IterativeSolverWithPostStabilisationLiftsTheFlap) {
  const FlapCase c = flap_case();
  auto args = dynamic_args(c, 1.05 * kLift);
  args.insert(args.end(), {"--solver", "iterative", "--iterations", "20", "--projection-interval", "0.001"});
  const auto r = foldkit(args);
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "success");
  EXPECT_NEAR(j["final_angles"][0]["angle"].get<double>(), -60.0, 0.01);
  // A strip has no loop: nothing for the corrections to close, before or after them.
  ASSERT_TRUE(j.contains("max_corrected_error"));
  EXPECT_EQ(j["max_corrected_error"].get<double>(), 0.0);
  EXPECT_EQ(j["max_closure_error"].get<double>(), 0.0);
  const auto kinematic = foldkit({"simulate", c.pmml, c.cmml, "--solver", "iterative"});
  EXPECT_EQ(kinematic.exit, 2);
  EXPECT_NE(kinematic.err.find("--solver is an option of --model dynamic"), std::string::npos) << kinematic.err;
}

// PMML's <MaxTorque> (foldkit's extension) is the joint's own limit: 0.95·m·g·d there stalls the
// flap whatever --max-torque says for the other joints; --joint-torque overrides the file.
TEST(DynamicSimulateCli, PmmlMaxTorqueIsTheJointsOwnLimit) {
  const FlapCase c = flap_case();
  std::string text = foldkit::test::slurp(c.pmml);
  const auto at = text.find("</DampConst>");
  ASSERT_NE(at, std::string::npos);
  text.insert(at + std::string("</DampConst>").size(), "\n    <MaxTorque>" + std::to_string(0.95 * kLift) + "</MaxTorque>");
  const std::string pmml = c.dir + "/limited.pmml";
  std::ofstream(pmml) << text;
  auto args = dynamic_args(c, 10 * kLift);
  args[1] = pmml;
  const auto r = foldkit(args);
  ASSERT_EQ(r.exit, 3) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["stalls"].size(), 1u);
  EXPECT_NEAR(j["stalls"][0]["available_torque"].get<double>(), 0.95 * kLift, 1e-5);
  EXPECT_NEAR(j["stalls"][0]["needed_torque"].get<double>(), kLift, 0.01 * kLift);
  args.insert(args.end() - 1, {"--joint-torque", "1:" + std::to_string(1.05 * kLift)});
  EXPECT_EQ(foldkit(args).exit, 0);
  // A limit that is not a positive number is the file's error, at its line (exit 1).
  std::string bad = text;
  bad.replace(bad.find("<MaxTorque>") + 11, bad.find("</MaxTorque>") - bad.find("<MaxTorque>") - 11, "-1");
  std::ofstream(pmml) << bad;
  const auto refused = foldkit(args);
  EXPECT_EQ(refused.exit, 1);
  EXPECT_NE(refused.err.find("limited.pmml:"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("maximum torque must be positive"), std::string::npos) << refused.err;
}

TEST(DynamicSimulateCli, BadInputIsRefusedWithoutOutput) {
  const FlapCase c = flap_case();
  const std::string frames = c.dir + "/never.fold";
  const std::vector<std::vector<std::string>> bad = {
      {"--density", "-1"}, {"--max-torque", "nan"}, {"--max-torque", "-2"}, {"--gravity", "0,0,nan"},
      {"--gravity", "1,2"}, {"--fixed", "99"},      {"--scale", "0"},       {"--drive", "rocket"},
      {"--time-step", "0.5"}, {"--solver", "magic"}, {"--iterations", "0"}, {"--projection-interval", "-1"}};
  for (const auto& extra : bad) {
    std::vector<std::string> args = {"simulate", c.pmml, c.cmml, "--model", "dynamic", "--frames", frames};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = foldkit(args);
    EXPECT_EQ(r.exit, 2) << extra[0] << " " << extra[1] << ": " << r.err;
    EXPECT_FALSE(fs::exists(frames));
  }
  // One model's options given to the other are refused, not ignored: a kinematic replay with a
  // torque limit would say "valid" whatever the torque.
  const auto kinematic = foldkit({"simulate", c.pmml, c.cmml, "--gravity", "0,0,-9.81", "--max-torque", "0.01"});
  EXPECT_EQ(kinematic.exit, 2);
  EXPECT_NE(kinematic.err.find("--gravity is an option of --model dynamic"), std::string::npos) << kinematic.err;
  EXPECT_EQ(foldkit({"simulate", c.pmml, c.cmml, "--model", "dynamic", "--no-collision"}).exit, 2);
  // --series is the dynamic model's, and CSV or JSON.
  EXPECT_EQ(foldkit({"simulate", c.pmml, c.cmml, "--series", c.dir + "/s.csv"}).exit, 2);
  EXPECT_EQ(foldkit({"simulate", c.pmml, c.cmml, "--series", c.dir + "/s.json"}).exit, 2);
  const auto txt = foldkit({"simulate", c.pmml, c.cmml, "--model", "dynamic", "--series", c.dir + "/s.txt"});
  EXPECT_EQ(txt.exit, 2);
  EXPECT_NE(txt.err.find("a .csv or .json file name"), std::string::npos) << txt.err;
  EXPECT_FALSE(fs::exists(c.dir + "/s.txt"));
  // A fold of a joint the pattern lacks: invalid input at the CMML's line.
  const FlapCase unknown = flap_case("7");
  const auto r = foldkit({"simulate", unknown.pmml, unknown.cmml, "--model", "dynamic", "--frames", frames});
  EXPECT_EQ(r.exit, 1) << r.err;
  EXPECT_NE(r.err.find("lift.cmml:3"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(frames));
}

}  // namespace
