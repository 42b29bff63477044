// One word, one meaning in the CLI's JSON (issue 37, docs/CLI.md): every verb that runs an
// algorithm or checks files says how it ended in `status` (+ `message`), elapsed wall-clock time
// is `seconds`, and the keys and options renamed by issue 37 are still written or read, agreeing
// with their replacements, for one release.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/io/pmml.hpp"

namespace {

using foldkit::test::CliResult;
using foldkit::test::foldkit;
using foldkit::test::slurp;
using foldkit::test::write_temp;
namespace geo = foldkit::geometry;

std::string pattern_file(const std::string& name, const geo::PatternSpec& spec) {
  return write_temp(name, foldkit::io::write_pmml(geo::build_or_throw(spec).to_spec()));
}

// The JSON of a run that printed one; `status` and `message` are there, `status` one of the
// documented names, and it is `success` exactly when the exit code is 0.
nlohmann::json checked_json(const CliResult& r) {
  EXPECT_FALSE(r.out.empty()) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j.contains("status") && j["status"].is_string()) << r.out;
  EXPECT_TRUE(j.contains("message") && j["message"].is_string()) << r.out;
  const std::vector<std::string> names = {"success",       "invalid-input",        "collision",   "closure-violated", "singular",
                                          "not-rigidly-foldable", "no-solution", "no-progress", "limit-reached"};
  EXPECT_NE(std::find(names.begin(), names.end(), j.value("status", std::string())), names.end()) << j["status"];
  EXPECT_EQ(j["status"] == "success", r.exit == 0) << r.out;
  return j;
}

TEST(JsonStatus, EveryVerbSaysHowItEndedInStatusAndTheOldKeysAgree) {
  const std::string miura = pattern_file("js-miura.pmml", geo::generators::miura(3, 3));
  const std::string fold = write_temp("js-fold.cmml", "");
  auto j = checked_json(foldkit({"fold", miura, "--fraction", "0.5", "-o", fold, "--json"}));
  EXPECT_EQ(j["reached"], true);
  EXPECT_EQ(j["stop"], "reached");
  EXPECT_EQ(j["replay_status"], "success");
  EXPECT_EQ(j["replay_ok"], true);
  EXPECT_TRUE(j["seconds"].is_number() && j["seconds"] == j["time"]);

  j = checked_json(foldkit({"plan", miura, "--goal", fold, "-o", write_temp("js-plan.cmml", ""), "--json"}));
  EXPECT_EQ(j["solved"], true);
  EXPECT_TRUE(j["seconds"].is_number() && j["seconds"] == j["time"]);

  j = checked_json(foldkit({"simulate", miura, fold, "--json"}));
  EXPECT_EQ(j["ok"], true);

  j = checked_json(foldkit({"validate", miura, "--json"}));
  EXPECT_EQ(j["ok"], true);
  ASSERT_EQ(j["files"].size(), 1u);
  EXPECT_EQ(j["files"][0]["status"], "success");
  EXPECT_EQ(j["files"][0]["ok"], true);
  j = checked_json(foldkit({"validate", write_temp("js-broken.pmml", "<PMML>"), "--json"}));
  EXPECT_EQ(j["status"], "invalid-input");
  EXPECT_EQ(j["ok"], false);
  EXPECT_EQ(j["files"][0]["status"], "invalid-input");

  j = checked_json(foldkit({"carpenter", write_temp("js-chain.txt", "0 0\n1 0\n1 1\n0 1\n0 2\n"), "--json"}));
  EXPECT_EQ(j["straight"], true);
  EXPECT_TRUE(j["seconds"].is_number() && j["seconds"] == j["time"]);

  j = checked_json(foldkit({"hamiltonian", write_temp("js-shape.txt", "###\n#.#\n"), "--json"}));
  EXPECT_EQ(j["found"], true);
  EXPECT_EQ(j["verdict"], "found");
  j = checked_json(foldkit({"hamiltonian", write_temp("js-parity.txt", "###\n###\n###\n"), "--cycle", "--json"}));
  EXPECT_EQ(j["status"], "no-solution");
  EXPECT_EQ(j["found"], false);
}

// `project --speed` writes the CMML's <Velocity> in degrees per second; `--velocity`, its name
// before issue 37, still does the same.
TEST(JsonStatus, ProjectSpeedAndItsDeprecatedNameWriteTheSameFile) {
  const std::string strip = pattern_file("js-vertex.pmml", geo::generators::single_vertex({1.4, 1.6, 1.5, 1.783185307179586}));
  const std::string rough =
      write_temp("js-rough.cmml",
                 "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<CMML>\n  <Title>rough</Title>\n  <Fold>\n    <EventNumber>1</EventNumber>\n"
                 "    <ID>1</ID>\n    <FoldAngle>40</FoldAngle>\n    <Velocity>10</Velocity>\n  </Fold>\n</CMML>\n");
  const std::string a = write_temp("js-speed.cmml", ""), b = write_temp("js-velocity.cmml", "");
  const auto ra = foldkit({"project", strip, "--state", rough, "--speed", "45", "-o", a, "--json"});
  const auto rb = foldkit({"project", strip, "--state", rough, "--velocity", "45", "-o", b, "--json"});
  ASSERT_EQ(ra.exit, 0) << ra.err;
  ASSERT_EQ(rb.exit, 0) << rb.err;
  EXPECT_EQ(checked_json(ra)["converged"], true);
  EXPECT_EQ(slurp(a), slurp(b));
  EXPECT_NE(slurp(a).find("<Velocity>45</Velocity>"), std::string::npos) << slurp(a);
}

}  // namespace
