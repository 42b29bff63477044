// foldkit serve's simulate with the dynamic model, as the browser app's physics switch asks it:
// the physical options reach the CLI by their CLI names, a stall is an answer (200, exit 3), and
// the per-joint series the page plots is the CLI's own file, read back through GET /api/file.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "serve_test_server.hpp"

#include <httplib.h>  // last: its <resolv.h> macros would break headers included after it

namespace {

using foldkit::test::comparable;
using foldkit::test::foldkit;
using foldkit::test::Server;
using foldkit::test::slurp;
using nlohmann::json;

// A two-panel strip (unit squares, panel 1 held) and a CMML lifting panel 2 to −60° at 30°/s:
// under g = 9.81 m/s² at 1 kg/m² the motor needs m·g·d = 1 · 9.81 · 0.5 N·m to lift it.
constexpr double kLift = 9.81 * 0.5;

void flap(const Server& s) {
  ASSERT_EQ(foldkit({"generate", "strip", "--panels", "2", "-o", s.path("flap.pmml")}).exit, 0);
  std::ofstream(s.path("lift.cmml")) << "<CMML><Title>lift</Title><Fold><EventNumber>1</EventNumber><ID>1</ID>"
                                        "<FoldAngle>-60</FoldAngle><Velocity>30</Velocity></Fold></CMML>\n";
}

// The report less what depends on the wall clock.
json steady_part(json j, const std::string& root) {
  j = comparable(std::move(j), root);
  j.erase("real_time_factor");
  return j;
}

TEST(ServePhysics, ADynamicSimulateAnswersAsTheCliAndWritesItsSeries) {
  Server s("physics");
  ASSERT_GT(s.port(), 0) << s.log();
  flap(s);
  for (const double torque : {0.95 * kLift, 1.05 * kLift}) {
    SCOPED_TRACE(torque);
    const json request = {{"pattern", "flap.pmml"}, {"sequence", "lift.cmml"}, {"model", "dynamic"},
                          {"gravity", "0,0,-9.81"},  {"max-torque", torque},   {"series", "lift.json"},
                          {"frames", "lift.fold"}};
    const auto r = s.post("simulate", request);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    const json api = json::parse(r->body);
    const std::string served = slurp(s.path("lift.json"));
    const auto cli = foldkit({"simulate", s.path("flap.pmml"), s.path("lift.cmml"), "--model", "dynamic", "--gravity",
                              "0,0,-9.81", "--max-torque", api["result"]["max_torque"].dump(), "--series",
                              s.path("lift.json"), "--json"});
    EXPECT_EQ(api["exit"].get<int>(), cli.exit) << cli.err;
    EXPECT_EQ(steady_part(api["result"], s.root()), steady_part(json::parse(cli.out), s.root()));
    EXPECT_EQ(served, slurp(s.path("lift.json")));  // the same run, the same series
    const bool stalls = torque < kLift;
    EXPECT_EQ(api["exit"].get<int>(), stalls ? 3 : 0);
    ASSERT_EQ(api["result"]["stalls"].size(), stalls ? 1u : 0u);

    // The page reads the series as any file of the root: JSON, one entry per frame.
    const auto file = s.client().Get("/api/file?path=lift.json");
    ASSERT_TRUE(file);
    ASSERT_EQ(file->status, 200);
    EXPECT_EQ(file->get_header_value("Content-Type"), "application/json");
    const json series = json::parse(file->body);
    ASSERT_EQ(series["joints"].size(), 1u);
    const auto& torques = series["joints"][0]["torque"];
    ASSERT_EQ(torques.size(), series["time"].size());
    double peak = 0;
    for (const auto& t : torques) peak = std::max(peak, std::abs(t.get<double>()));
    // The report's peak is of every step, the series' of every 0.01 s.
    const double reported = api["result"]["joints"][0]["peak_torque"].get<double>();
    EXPECT_LE(peak, reported * (1 + 1e-12));
    EXPECT_GE(peak, 0.99 * reported);
    // A stall: the series ends at its time, the motor at its limit.
    if (stalls) {
      EXPECT_NEAR(series["time"].back().get<double>(), api["result"]["stalls"][0]["time"].get<double>(), 1e-9);
      EXPECT_NEAR(std::abs(torques.back().get<double>()), torque, 1e-6 * kLift);
    }
  }
}

TEST(ServePhysics, PhysicalOptionsAreCheckedAsTheCliChecksThem) {
  Server s("physics-bad");
  ASSERT_GT(s.port(), 0) << s.log();
  flap(s);
  const json base = {{"pattern", "flap.pmml"}, {"sequence", "lift.cmml"}, {"model", "dynamic"}};
  const std::vector<std::pair<json, std::string>> bad = {
      {{{"max-torque", -1}}, "max-torque"},
      {{{"max-torque", "1"}}, "expected a finite number"},
      {{{"gravity", "0,0"}}, "--gravity needs three finite numbers"},
      {{{"series", "lift.txt"}}, "a .csv or .json file name"},
      {{{"series", "../lift.json"}}, ""},
  };
  for (const auto& [extra, message] : bad) {
    SCOPED_TRACE(extra.dump());
    json request = base;
    request.update(extra);
    const auto r = s.post("simulate", request);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 400) << r->body;
    EXPECT_NE(json::parse(r->body)["error"].get<std::string>().find(message), std::string::npos) << r->body;
  }
  // The kinematic model refuses the physical options rather than ignoring them.
  const auto kinematic = s.post("simulate", {{"pattern", "flap.pmml"}, {"sequence", "lift.cmml"}, {"gravity", "0,0,-9.81"}});
  ASSERT_TRUE(kinematic);
  EXPECT_EQ(kinematic->status, 400) << kinematic->body;
  EXPECT_FALSE(std::filesystem::exists(s.path("lift.txt")));
}

}  // namespace
