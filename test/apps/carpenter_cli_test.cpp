// foldkit carpenter: exit codes, JSON fields, the frame and CMML files, and bad chains.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "foldkit/io/cmml.hpp"
#include "test_paths.hpp"

namespace {

using foldkit::test::CliResult;
using foldkit::test::foldkit;
using foldkit::test::slurp;
using foldkit::test::temp_dir;
using foldkit::test::write_temp;


const char* kSpiral = "# a square spiral\n0 0\n3 0\n3 3\n0 3\n0 1\n2 1\n2 2\n1 2\n";

TEST(CarpenterCli, OpenChainStraightensWithJsonAndFiles) {
  const std::string chain = write_temp("spiral.txt", kSpiral);
  const std::string cmml = write_temp("spiral.cmml", ""), csv = write_temp("spiral.csv", "");
  const CliResult r = foldkit({"carpenter", chain, "--json", "-o", cmml, "--frames-csv", csv});
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["straight"].get<bool>());
  EXPECT_FALSE(j.contains("convex"));
  EXPECT_GT(j["steps"].get<int>(), 0);
  EXPECT_GE(j["time"].get<double>(), 0.0);
  EXPECT_LE(j["max_length_error"].get<double>(), 1e-9);
  EXPECT_GE(j["min_distance_growth"].get<double>(), -1e-12);
  const std::size_t frames = j["frames"].get<std::size_t>();

  // CSV: a header, then 8 vertices per frame; the last frame is straight: the last vertex at
  // distance 3+3+3+2+2+1+1 = 15 from the first.
  std::istringstream in(slurp(csv));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "frame,vertex,x,y");
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  ASSERT_EQ(rows.size(), frames * 8);
  const auto& first = rows[rows.size() - 8];
  const auto& last = rows.back();
  EXPECT_NEAR(std::hypot(last[2] - first[2], last[3] - first[3]), 15.0, 1e-9);

  // CMML: one event per frame, joints 1..6, the last event all straight.
  const auto seq = foldkit::io::parse_cmml(slurp(cmml), cmml);
  ASSERT_EQ(seq.events.size(), frames);
  ASSERT_EQ(seq.events.back().folds.size(), 6u);
  for (const auto& f : seq.events.back().folds) EXPECT_NEAR(f.angle, 0.0, 1e-9);
  EXPECT_NEAR(seq.events.front().folds.front().angle, M_PI / 2, 1e-12);  // the input's left turn
}

TEST(CarpenterCli, OutputExtensionIgnoresCase) {
  const std::string chain = write_temp("spiral-upper.txt", kSpiral);
  const std::string json = temp_dir() + "/SPIRAL.JSON";
  const CliResult r = foldkit({"carpenter", chain, "-o", json});
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto frames = nlohmann::json::parse(slurp(json));
  EXPECT_FALSE(frames["closed"].get<bool>());
  EXPECT_GT(frames["frames"].size(), 1u);
}

// X.cmml.gz as every other verb writes it: gzip's magic bytes, and the same events as the plain
// file of the same run (read back through the gzip reader of io::read_cmml).
TEST(CarpenterCli, CompressedCmmlOutputReadsAsThePlainOne) {
  const std::string chain = write_temp("spiral-gz.txt", kSpiral);
  const std::string plain = temp_dir() + "/spiral-gz.cmml", packed = temp_dir() + "/spiral-gz.cmml.gz";
  ASSERT_EQ(foldkit({"carpenter", chain, "-o", plain}).exit, 0);
  const CliResult r = foldkit({"carpenter", chain, "-o", packed});
  ASSERT_EQ(r.exit, 0) << r.err;
  const std::string bytes = slurp(packed);
  ASSERT_GE(bytes.size(), 2u);
  EXPECT_EQ(static_cast<unsigned char>(bytes[0]), 0x1f);
  EXPECT_EQ(static_cast<unsigned char>(bytes[1]), 0x8b);
  const auto a = foldkit::io::parse_cmml(slurp(plain), plain), b = foldkit::io::read_cmml(packed);
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t e = 0; e < a.events.size(); ++e) {
    ASSERT_EQ(a.events[e].folds.size(), b.events[e].folds.size());
    for (std::size_t f = 0; f < a.events[e].folds.size(); ++f) EXPECT_EQ(a.events[e].folds[f].angle, b.events[e].folds[f].angle);
  }
  EXPECT_EQ(foldkit({"carpenter", chain, "-o", temp_dir() + "/spiral.txt.gz"}).exit, 2);
}

TEST(CarpenterCli, FoldWritesTheFramesBackwards) {
  const std::string chain = write_temp("spiral2.txt", kSpiral);
  const std::string json = write_temp("fold.json", "");
  const CliResult r = foldkit({"carpenter", chain, "--fold", "-o", json});
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto j = nlohmann::json::parse(slurp(json));
  const auto& frames = j["frames"];
  ASSERT_GE(frames.size(), 2u);
  EXPECT_EQ(frames.back()[4][0].get<double>(), 0.0);  // the input's vertex 4 is (0, 1)
  EXPECT_EQ(frames.back()[4][1].get<double>(), 1.0);
}

TEST(CarpenterCli, ClosedPolygonConvexifies) {
  const std::string chain = write_temp("u.txt", "0 0\n4 0\n4 4\n3 4\n3 1\n1 1\n1 4\n0 4\n");
  const CliResult r = foldkit({"carpenter", chain, "--closed", "--json"});
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["convex"].get<bool>());
  EXPECT_TRUE(j["closed"].get<bool>());
  EXPECT_LE(j["max_length_error"].get<double>(), 1e-9);
}

TEST(CarpenterCli, BadInputExitsOneWithLocation) {
  CliResult r = foldkit({"carpenter", write_temp("bad.txt", "0 0\n1 0\n# ok\n1 x\n")});
  EXPECT_EQ(r.exit, 1);
  EXPECT_NE(r.err.find("bad.txt:4:"), std::string::npos) << r.err;
  r = foldkit({"carpenter", write_temp("three.txt", "0 0\n1 2 3\n")});
  EXPECT_EQ(r.exit, 1);
  EXPECT_NE(r.err.find("three.txt:2: expected two numbers"), std::string::npos) << r.err;
  r = foldkit({"carpenter", write_temp("cross.txt", "0 0\n2 0\n2 1\n1 -1\n")});
  EXPECT_EQ(r.exit, 1);
  EXPECT_NE(r.err.find("not simple"), std::string::npos) << r.err;
  r = foldkit({"carpenter", write_temp("zero.txt", "0 0\n1 0\n1 0\n")});
  EXPECT_EQ(r.exit, 1);
  EXPECT_NE(r.err.find("zero-length bar"), std::string::npos) << r.err;
  r = foldkit({"carpenter", write_temp("missing-dir/none.txt", "")});
  EXPECT_EQ(r.exit, 1);
}

TEST(CarpenterCli, UsageErrorsAndStepLimit) {
  const std::string chain = write_temp("spiral3.txt", kSpiral);
  EXPECT_EQ(foldkit({"carpenter"}).exit, 2);
  EXPECT_EQ(foldkit({"carpenter", chain, "-o", write_temp("out.xyz", "")}).exit, 2);
  EXPECT_EQ(foldkit({"carpenter", chain, "--state", "x.cmml"}).exit, 2);
  const CliResult r = foldkit({"carpenter", chain, "--max-steps", "1", "--json"});
  EXPECT_EQ(r.exit, 4);
  EXPECT_FALSE(nlohmann::json::parse(r.out)["straight"].get<bool>());
  EXPECT_NE(r.err.find("not straight"), std::string::npos);
}

// --method picks how each step's motion is found (docs/CARPENTER.md, "Methods"): both straighten
// the spiral expansively, the JSON names the method, and an unknown one is a usage error.
TEST(CarpenterCli, MethodOptionSelectsTheGlobalLpOrTheCarriedField) {
  const std::string chain = write_temp("spiral4.txt", kSpiral);
  for (const char* method : {"lp", "carried"}) {
    SCOPED_TRACE(method);
    const CliResult r = foldkit({"carpenter", chain, "--method", method, "--json"});
    ASSERT_EQ(r.exit, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["method"].get<std::string>(), method);
    // The carried field's counts, as Python's result has them (0 under the global LP).
    EXPECT_LE(j["window_lp_solves"].get<std::size_t>(), j["lp_solves"].get<std::size_t>());
    EXPECT_EQ(j["carried_steps"].get<std::size_t>() > 0, std::string(method) == "carried") << j.dump();
    EXPECT_TRUE(j["straight"].get<bool>());
    EXPECT_GE(j["min_distance_growth"].get<double>(), -1e-12);
    EXPECT_LE(j["max_length_error"].get<double>(), 1e-9);
  }
  EXPECT_EQ(nlohmann::json::parse(foldkit({"carpenter", chain, "--json"}).out)["method"].get<std::string>(), "carried");
  EXPECT_EQ(foldkit({"carpenter", chain, "--method", "simplex"}).exit, 2);
}

// --method pseudo (Streinu's pseudo-triangulation mechanism) beside the LP methods: the issue's
// 90-point spiral straightens expansively, and the JSON counts the mechanism's events. (The small
// spiral above is monotone after two steps, before any event.)
TEST(CarpenterCli, MethodPseudoStraightensWithFlipsCounted) {
  const std::string chain = foldkit::test::data_path("carpenter_spiral90.txt");
  const CliResult r = foldkit({"carpenter", chain, "--method", "pseudo", "--json"});
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["method"].get<std::string>(), "pseudo");
  EXPECT_TRUE(j["straight"].get<bool>());
  // The spiral takes flips and joints merged at events (2 and 30 when measured).
  EXPECT_GE(j["flips"].get<std::size_t>(), 1u) << j.dump();
  EXPECT_GE(j["straightenings"].get<std::size_t>(), 1u) << j.dump();
  EXPECT_LE(j["pseudo_lp_steps"].get<std::size_t>(), j["steps"].get<std::size_t>());
  EXPECT_GE(j["min_distance_growth"].get<double>(), -1e-12);
  EXPECT_LE(j["max_length_error"].get<double>(), 1e-9);
}

// Every metric of CarpenterPlanarResult is in the JSON under its C++ name, for every method
// (docs/CARPENTER.md, Metrics; Python's CarpenterResult has the same names and, for the same run,
// the same values: test_carpenter_metrics_have_one_name_in_python_and_json).
TEST(CarpenterCli, JsonHasEveryMetricOfTheResult) {
  const std::string chain = foldkit::test::data_path("carpenter_spiral90.txt");
  for (const char* method : {"carried", "lp", "pseudo"}) {
    SCOPED_TRACE(method);
    const CliResult r = foldkit({"carpenter", chain, "--method", method, "--json"});
    ASSERT_EQ(r.exit, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    for (const char* key : {"status", "closed", "steps", "frames", "lp_solves", "window_lp_solves", "carried_steps", "held_steps",
                            "max_struts", "flips", "straightenings", "pseudo_lp_steps", "certificate_seconds", "seconds",
                            "max_length_error", "min_distance_growth"})
      EXPECT_TRUE(j.contains(key)) << key << " missing from " << j.dump();
    // The spiral needs LPs (its held steps, above), each with rows; the certificate is the
    // pseudo-triangulation's own check, a part of the run's time.
    EXPECT_GT(j["max_struts"].get<std::size_t>(), 0u) << j.dump();
    EXPECT_LE(j["certificate_seconds"].get<double>(), j["seconds"].get<double>());
    EXPECT_EQ(j["certificate_seconds"].get<double>() > 0.0, std::string(method) == "pseudo") << j.dump();
  }
}

// Issue 36: a simple 90-point spiral (test/data/carpenter_spiral90.txt) was refused by both methods
// ("the expansive-motion LP failed at step 0 (infeasible)"); now it straightens, some steps with
// the spiral's slow centre held rigid (`held_steps`).
TEST(CarpenterCli, NinetyPointSpiralStraightensByBothMethods) {
  const std::string chain = foldkit::test::data_path("carpenter_spiral90.txt");
  for (const char* method : {"lp", "carried"}) {
    SCOPED_TRACE(method);
    const CliResult r = foldkit({"carpenter", chain, "--method", method, "--json", "-o", write_temp("spiral90.json", "")});
    ASSERT_EQ(r.exit, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_TRUE(j["straight"].get<bool>());
    EXPECT_GT(j["held_steps"].get<std::size_t>(), 0u);
    EXPECT_LE(j["held_steps"].get<std::size_t>(), j["steps"].get<std::size_t>());
    EXPECT_GE(j["min_distance_growth"].get<double>(), -1e-12);
    EXPECT_LE(j["max_length_error"].get<double>(), 1e-9);
  }
}

// --frame-stride N keeps every N-th step's frame of the same run (the input and the end always):
// the frames of the unstrided run at steps 0, N, 2N, …, and its last, bit for bit, and the JSON
// counts them. The run itself (its steps) does not change.
TEST(CarpenterCli, FrameStrideKeepsEveryNthFrameOfTheSameRun) {
  const std::string chain = foldkit::test::data_path("carpenter_spiral90.txt");
  const std::string every = temp_dir() + "/stride-1.json", some = temp_dir() + "/stride-3.json";
  const CliResult all = foldkit({"carpenter", chain, "-o", every, "--json"});
  ASSERT_EQ(all.exit, 0) << all.err;
  const CliResult strided = foldkit({"carpenter", chain, "-o", some, "--frame-stride", "3", "--json"});
  ASSERT_EQ(strided.exit, 0) << strided.err;
  const auto j1 = nlohmann::json::parse(all.out), j3 = nlohmann::json::parse(strided.out);
  EXPECT_EQ(j1["steps"], j3["steps"]);
  const auto f1 = nlohmann::json::parse(slurp(every))["frames"], f3 = nlohmann::json::parse(slurp(some))["frames"];
  ASSERT_GT(f1.size(), 7u) << "too few steps to tell a stride from none";
  std::vector<std::size_t> kept;
  for (std::size_t k = 0; k < f1.size(); k += 3) kept.push_back(k);
  if (kept.back() != f1.size() - 1) kept.push_back(f1.size() - 1);
  ASSERT_EQ(f3.size(), kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) EXPECT_EQ(f3[i], f1[kept[i]]) << "frame " << i << " = step " << kept[i];
  EXPECT_EQ(j3["frames"].get<std::size_t>(), kept.size());
  EXPECT_TRUE(j3["straight"].get<bool>());
  EXPECT_EQ(foldkit({"carpenter", chain, "--frame-stride", "0"}).exit, 2);
  EXPECT_EQ(foldkit({"carpenter", chain, "--frame-stride", "x"}).exit, 2);
}

TEST(CarpenterCli, SingleVertexPmmlIsFlattenedOnTheSphere) {
  // A degree-4 vertex folded to a closed state (projected by foldkit project), then flattened.
  const std::string pattern = write_temp("v4.pmml", "");
  ASSERT_EQ(foldkit({"generate", "single-vertex", "--degree", "4", "-o", pattern}).exit, 0);
  std::string rough = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<CMML>\n  <Title>rough</Title>\n";
  const int angles[4] = {40, -40, 40, 40};
  for (int j = 0; j < 4; ++j)
    rough += "  <Fold><EventNumber>0</EventNumber><ID>" + std::to_string(j + 1) + "</ID><FoldAngle>" +
             std::to_string(angles[j]) + "</FoldAngle><Velocity>10</Velocity></Fold>\n";
  rough += "</CMML>\n";
  const std::string closed = write_temp("v4-closed.cmml", "");
  ASSERT_EQ(foldkit({"project", pattern, "--state", write_temp("v4-rough.cmml", rough), "-o", closed}).exit, 0);
  const std::string folding = write_temp("v4-folding.cmml", "");
  const CliResult r = foldkit({"carpenter", pattern, "--state", closed, "--json", "-o", folding});
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["flat"].get<bool>());
  EXPECT_TRUE(j["spherical"].get<bool>());
  EXPECT_GE(j["min_distance_growth"].get<double>(), -1e-12);
  EXPECT_FALSE(foldkit::io::parse_cmml(slurp(folding), folding).events.empty());
  EXPECT_EQ(foldkit({"carpenter", pattern}).exit, 2);  // no folded state given
  // --max-steps holds for the sphere too: one step does not reach flat (exit 4, no plan).
  const CliResult short_run = foldkit({"carpenter", pattern, "--state", closed, "--max-steps", "1", "--json"});
  EXPECT_EQ(short_run.exit, 4) << short_run.err;
  EXPECT_EQ(foldkit({"carpenter", pattern, "--state", closed, "--frame-stride", "2"}).exit, 2);  // planar only
  EXPECT_FALSE(nlohmann::json::parse(short_run.out)["flat"].get<bool>());
}

}  // namespace
