#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "test_paths.hpp"

namespace {

namespace fs = std::filesystem;
using foldkit::test::cli_path;
using foldkit::test::data_path;
using foldkit::test::temp_dir;

using foldkit::test::CliResult;
using foldkit::test::foldkit;
using foldkit::test::slurp;

TEST(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(foldkit({}).exit, 2);
  EXPECT_EQ(foldkit({"fly"}).exit, 2);
  EXPECT_EQ(foldkit({"info"}).exit, 2);
  EXPECT_EQ(foldkit({"generate", "miura", "--rows", "0", "-o", "x.pmml"}).exit, 2);
  EXPECT_EQ(foldkit({"generate", "single-vertex", "--sectors", "90,90,90", "-o", "x.pmml"}).exit, 2);
  EXPECT_EQ(foldkit({"convert", "a.pmml", "b.txt"}).exit, 1);  // a.pmml does not exist
  const CliResult help = foldkit({"--help"});
  EXPECT_EQ(help.exit, 0);
  EXPECT_NE(help.out.find("validate"), std::string::npos);
  EXPECT_EQ(foldkit({"generate", "--help"}).exit, 0);
}

TEST(Cli, GenerateInfoJson) {
  const std::string dir = temp_dir();
  const CliResult gen = foldkit({"generate", "miura", "--rows", "3", "--cols", "4", "-o", dir + "/m.pmml", "--json"});
  ASSERT_EQ(gen.exit, 0) << gen.err;
  EXPECT_EQ(nlohmann::json::parse(gen.out)["actors"], 12);
  const CliResult info = foldkit({"info", dir + "/m.pmml", "--json"});
  ASSERT_EQ(info.exit, 0) << info.err;
  const auto j = nlohmann::json::parse(info.out);  // exactly one JSON object on stdout
  EXPECT_EQ(j["actors"], 12);
  EXPECT_EQ(j["joints"], 3 * 3 + 4 * 2);
  EXPECT_EQ(j["vertices"], 4 * 5);
  EXPECT_EQ(j["interior_vertices"], 2 * 3);
  EXPECT_EQ(j["boundary_vertices"], 14);
  EXPECT_EQ(j["interior_vertex_degrees"]["4"], 6);
}

// The cube sheet with the CMML that folds it into a line of cubes: the simulator replays it valid.
TEST(Cli, CubeSheetComesWithItsChainFolding) {
  const std::string dir = temp_dir();
  const CliResult g = foldkit({"generate", "cube-sheet", "--cubes", "3", "-o", dir + "/sheet.pmml", "--chain-cmml",
                               dir + "/chain.cmml", "--json"});
  ASSERT_EQ(g.exit, 0) << g.err;
  const auto j = nlohmann::json::parse(g.out);
  EXPECT_EQ(j["chain_events"], 9);
  EXPECT_EQ(j["chain_cmml"], dir + "/chain.cmml");
  const CliResult s = foldkit({"simulate", dir + "/sheet.pmml", dir + "/chain.cmml", "--json"});
  ASSERT_EQ(s.exit, 0) << s.err;
  // A folding that cannot be written takes the sheet with it: no half of the pair is left.
  const CliResult bad = foldkit({"generate", "cube-sheet", "--cubes", "2", "-o", dir + "/lone.pmml", "--chain-cmml",
                                 dir + "/no-such-folder/chain.cmml"});
  EXPECT_NE(bad.exit, 0);
  EXPECT_FALSE(std::filesystem::exists(dir + "/lone.pmml"));
  // The option belongs to the cube sheet only.
  EXPECT_EQ(foldkit({"generate", "strip", "-o", dir + "/strip.pmml", "--chain-cmml", dir + "/x.cmml"}).exit, 2);
}

TEST(Cli, EveryGeneratorValidates) {
  const std::string dir = temp_dir();
  const std::vector<std::vector<std::string>> kinds = {
      {"single-vertex", "--degree", "8"},
      {"single-vertex", "--degree", "12", "--seed", "3"},
      {"single-vertex", "--sectors", "100,80,80,100"},
      {"strip", "--panels", "5"},
      {"grid", "--rows", "3", "--cols", "2"},
      {"circular", "--rings", "2", "--spokes", "6"},
      {"miura", "--rows", "4", "--cols", "4", "--angle", "70"},
      {"waterbomb", "--units", "3", "--rows", "2"},
      {"boat"},
      {"cube-sheet", "--cubes", "3"},
      {"square-twist", "--twist", "30"}};
  for (const auto& k : kinds) {
    std::vector<std::string> args = {"generate"};
    args.insert(args.end(), k.begin(), k.end());
    const std::string out = dir + "/" + k[0] + ".pmml";
    args.insert(args.end(), {"-o", out});
    const CliResult g = foldkit(args);
    ASSERT_EQ(g.exit, 0) << k[0] << ": " << g.err;
    const CliResult v = foldkit({"validate", out});
    EXPECT_EQ(v.exit, 0) << k[0] << ": " << v.err;
    const CliResult f = foldkit({"convert", out, dir + "/" + k[0] + ".fold"});
    EXPECT_EQ(f.exit, 0) << k[0] << ": " << f.err;
    const CliResult back = foldkit({"convert", dir + "/" + k[0] + ".fold", dir + "/" + k[0] + "-back.pmml"});
    EXPECT_EQ(back.exit, 0) << k[0] << ": " << back.err;
    const auto a = nlohmann::json::parse(foldkit({"info", out, "--json"}).out);
    const auto b = nlohmann::json::parse(foldkit({"info", dir + "/" + k[0] + "-back.pmml", "--json"}).out);
    for (const char* key : {"actors", "joints", "vertices", "interior_vertices", "boundary_vertices"})
      EXPECT_EQ(a[key], b[key]) << k[0] << " " << key;
  }
}

TEST(Cli, SameSeedSameFile) {
  const std::string dir = temp_dir();
  for (const char* name : {"a.pmml", "b.pmml"})
    ASSERT_EQ(foldkit({"generate", "single-vertex", "--degree", "9", "--seed", "42", "-o", dir + "/" + name}).exit, 0);
  EXPECT_EQ(slurp(dir + "/a.pmml"), slurp(dir + "/b.pmml"));
  ASSERT_EQ(foldkit({"generate", "single-vertex", "--degree", "9", "--seed", "43", "-o", dir + "/c.pmml"}).exit, 0);
  EXPECT_NE(slurp(dir + "/a.pmml"), slurp(dir + "/c.pmml"));
}

TEST(Cli, BadInputCorpus) {
  // Every file under test/data/bad: exit 1, "FILE:LINE: message", and no output written.
  const std::string dir = temp_dir();
  int files = 0;
  for (const auto& entry : fs::directory_iterator(data_path("bad"))) {
    const std::string path = entry.path().string();
    if (entry.path().extension() == ".loadcase") continue;  // load cases: stiffness_cli_test.cpp
    ++files;
    const CliResult v = foldkit({"validate", path});
    EXPECT_EQ(v.exit, 1) << path << "\n" << v.err;
    EXPECT_TRUE(std::regex_search(v.err, std::regex("^" + std::regex_replace(path, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)") + ":[0-9]+: ")))
        << v.err;
    if (entry.path().extension() == ".cmml") continue;
    const std::string out = dir + "/out.fold";
    const CliResult c = foldkit({"convert", path, out});
    EXPECT_EQ(c.exit, 1) << path << "\n" << c.err;
    EXPECT_FALSE(fs::exists(out)) << path;
  }
  EXPECT_GE(files, 10);
}

TEST(Cli, DeepNestingAndHugeInputsDoNotCrash) {
  const std::string dir = temp_dir();
  std::ofstream(dir + "/deep.pmml") << "<PMML>" + [] { std::string s; for (int i = 0; i < 20000; ++i) s += "<a>"; return s; }();
  std::ofstream(dir + "/deep.fold") << std::string(20000, '[');
  std::ofstream(dir + "/deep-obj.fold") << [] { std::string s; for (int i = 0; i < 20000; ++i) s += "{\"a\":"; return s; }();
  for (const char* name : {"deep.pmml", "deep.fold", "deep-obj.fold"}) {
    const CliResult v = foldkit({"validate", dir + "/" + name});
    EXPECT_EQ(v.exit, 1) << name << ": " << v.err;
    EXPECT_NE(v.err.find(dir + "/" + name + ":"), std::string::npos) << v.err;
  }
}

TEST(Cli, ValidateCmmlAgainstPattern) {
  const std::string dir = temp_dir();
  ASSERT_EQ(foldkit({"generate", "strip", "--panels", "3", "-o", dir + "/s.pmml"}).exit, 0);
  std::ofstream(dir + "/ok.cmml") << "<CMML><Title>t</Title>\n<Fold><EventNumber>1</EventNumber><ID>1</ID>"
                                     "<FoldAngle>90</FoldAngle><Velocity>10</Velocity></Fold></CMML>\n";
  std::ofstream(dir + "/unknown.cmml") << "<CMML><Title>t</Title>\n<Fold><EventNumber>1</EventNumber><ID>77</ID>"
                                          "<FoldAngle>90</FoldAngle><Velocity>10</Velocity></Fold></CMML>\n";
  EXPECT_EQ(foldkit({"validate", dir + "/ok.cmml", "--pattern", dir + "/s.pmml"}).exit, 0);
  const CliResult bad = foldkit({"validate", dir + "/unknown.cmml", "--pattern", dir + "/s.pmml", "--json"});
  EXPECT_EQ(bad.exit, 1);
  EXPECT_NE(bad.err.find(dir + "/unknown.cmml:2: fold names joint 77"), std::string::npos) << bad.err;
  const auto j = nlohmann::json::parse(bad.out);
  EXPECT_FALSE(j["ok"].get<bool>());
  EXPECT_EQ(j["files"][0]["errors"][0]["line"], 2);
  // CMML → FOLD carries one frame per event; → SVG draws the end state.
  EXPECT_EQ(foldkit({"convert", dir + "/ok.cmml", dir + "/ok.fold", "--pattern", dir + "/s.pmml"}).exit, 0);
  const auto fold = nlohmann::json::parse(slurp(dir + "/ok.fold"));
  ASSERT_EQ(fold["file_frames"].size(), 1u);
  EXPECT_EQ(foldkit({"convert", dir + "/ok.cmml", dir + "/ok.svg"}).exit, 2);  // needs --pattern
}

TEST(Cli, FailedWriteLeavesNothing) {
  const std::string dir = temp_dir();
  ASSERT_EQ(foldkit({"generate", "boat", "-o", dir + "/b.pmml"}).exit, 0);
  const CliResult r = foldkit({"convert", dir + "/b.pmml", dir + "/missing/sub/b.fold"});
  EXPECT_EQ(r.exit, 1);
  EXPECT_FALSE(fs::exists(dir + "/missing"));
  for (const auto& e : fs::directory_iterator(dir)) EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos);
}

TEST(Cli, DemoWritesItsFolder) {
  const std::string dir = temp_dir() + "/demo";
  const CliResult d = foldkit({"demo", "-o", dir});
  ASSERT_EQ(d.exit, 0) << d.err;
  const auto report = nlohmann::json::parse(d.out);
  EXPECT_EQ(report["patterns"]["boat"]["actors"], 8);
  EXPECT_EQ(report["kinematics"]["degree8-vertex"]["dof_flat"], 6);
  EXPECT_EQ(report["kinematics"]["degree8-vertex"]["dof_folded"], 5);
  EXPECT_EQ(report["kinematics"]["boat"]["dof_folded"], 1);
  EXPECT_EQ(report["kinematics"]["miura-4x4"]["dof_folded"], 1);
  EXPECT_LT(report["kinematics"]["miura-4x4"]["closure_error"].get<double>(), 1e-10);
  for (const char* f : {"boat.pmml", "boat.svg", "boat.fold", "boat-folded.cmml", "miura-4x4.pmml", "miura-4x4-folded.fold",
                        "strip-5-zigzag.cmml", "report.json"})
    EXPECT_TRUE(fs::exists(dir + "/" + f)) << f;
  EXPECT_EQ(foldkit({"validate", dir + "/strip-5-zigzag.cmml", "--pattern", dir + "/strip-5.pmml"}).exit, 0);
  // The simulation stage: every CMML the demo wrote replays as valid, with closure held.
  for (const char* name : {"degree8-vertex-folded", "boat-folded", "miura-4x4-folded", "strip-5-zigzag", "cube-1-folded"}) {
    const auto& sim = report["simulation"][name];
    ASSERT_TRUE(sim.is_object()) << name;
    EXPECT_TRUE(sim["ok"].get<bool>()) << name;
    EXPECT_LT(sim["max_closure_error"].get<double>(), 1e-3) << name;
    EXPECT_EQ(sim["collisions"], 0) << name;
    EXPECT_TRUE(fs::exists(dir + "/" + name + "-snapshots/event-1.svg")) << name;
    EXPECT_EQ(foldkit({"simulate", dir + "/" + (std::string(name).substr(0, std::string(name).rfind('-'))) + ".pmml",
                       dir + "/" + name + ".cmml"})
                  .exit,
              0)
        << name;
  }
  // The stiffness stage: a closed cube (5 hinges, 7 edges meeting) converges to a small sag, and
  // the files it wrote give the same answer through the command line.
  EXPECT_TRUE(report["stiffness"]["converged"].get<bool>());
  EXPECT_EQ(report["stiffness"]["connections"]["hinged"], 5);
  EXPECT_EQ(report["stiffness"]["connections"]["edge"], 7);
  const CliResult s = foldkit({"stiffness", dir + "/cube-1.pmml", dir + "/cube-1-top-load.loadcase", "--state",
                               dir + "/cube-1-folded.cmml", "--json"});
  ASSERT_EQ(s.exit, 0) << s.err;
  EXPECT_DOUBLE_EQ(nlohmann::json::parse(s.out)["max_displacement"].get<double>(),
                   report["stiffness"]["max_displacement"].get<double>());
}

}  // namespace

namespace {

TEST(CliKinematics, DofAndProject) {
  const std::string dir = temp_dir();
  ASSERT_EQ(foldkit({"generate", "single-vertex", "--degree", "8", "-o", dir + "/v8.pmml"}).exit, 0);
  const CliResult flat = foldkit({"dof", dir + "/v8.pmml", "--json"});
  ASSERT_EQ(flat.exit, 0) << flat.err;
  const auto f = nlohmann::json::parse(flat.out);
  EXPECT_EQ(f["dof"], 6);  // paper Fig. 2a
  EXPECT_EQ(f["rank"], 2);
  EXPECT_EQ(f["creases"], 8);
  EXPECT_GT(f["tolerance"].get<double>(), 0.0);
  // An unclosed start: every crease at ±30°, alternating.
  std::ofstream start(dir + "/start.cmml");
  start << "<CMML><Title>start</Title>\n";
  for (int j = 1; j <= 8; ++j)
    start << "<Fold><EventNumber>1</EventNumber><ID>" << j << "</ID><FoldAngle>" << (j % 2 ? 30 : -25)
          << "</FoldAngle><Velocity>10</Velocity></Fold>\n";
  start << "</CMML>\n";
  start.close();
  const CliResult open = foldkit({"dof", dir + "/v8.pmml", "--state", dir + "/start.cmml", "--json"});
  EXPECT_GT(nlohmann::json::parse(open.out)["closure_error"].get<double>(), 1e-3);
  const CliResult proj = foldkit({"project", dir + "/v8.pmml", "--state", dir + "/start.cmml", "-o", dir + "/closed.cmml", "--json"});
  ASSERT_EQ(proj.exit, 0) << proj.err;
  const auto p = nlohmann::json::parse(proj.out);
  EXPECT_TRUE(p["converged"].get<bool>());
  EXPECT_LT(p["closure_error"].get<double>(), 1e-10);
  const CliResult folded = foldkit({"dof", dir + "/v8.pmml", "--state", dir + "/closed.cmml", "--json"});
  const auto d = nlohmann::json::parse(folded.out);
  EXPECT_EQ(d["dof"], 5);  // paper Fig. 2b
  EXPECT_LT(d["closure_error"].get<double>(), 1e-9);
}

TEST(CliKinematics, ProjectFailureWritesNothing) {
  const std::string dir = temp_dir();
  ASSERT_EQ(foldkit({"generate", "single-vertex", "--degree", "4", "-o", dir + "/v4.pmml"}).exit, 0);
  std::ofstream(dir + "/far.cmml") << "<CMML><Title>far</Title>\n"
                                      "<Fold><EventNumber>1</EventNumber><ID>1</ID><FoldAngle>170</FoldAngle><Velocity>10</Velocity></Fold>\n"
                                      "<Fold><EventNumber>1</EventNumber><ID>2</ID><FoldAngle>170</FoldAngle><Velocity>10</Velocity></Fold>\n"
                                      "<Fold><EventNumber>1</EventNumber><ID>3</ID><FoldAngle>170</FoldAngle><Velocity>10</Velocity></Fold>\n"
                                      "<Fold><EventNumber>1</EventNumber><ID>4</ID><FoldAngle>170</FoldAngle><Velocity>10</Velocity></Fold>\n"
                                      "</CMML>\n";
  const CliResult r = foldkit({"project", dir + "/v4.pmml", "--state", dir + "/far.cmml", "-o", dir + "/out.cmml",
                               "--max-iterations", "2", "--json"});
  EXPECT_EQ(r.exit, 4) << r.err;
  EXPECT_FALSE(nlohmann::json::parse(r.out)["converged"].get<bool>());
  EXPECT_FALSE(fs::exists(dir + "/out.cmml"));
  std::ofstream(dir + "/unknown.cmml") << "<CMML><Title>t</Title>\n<Fold><EventNumber>1</EventNumber><ID>9</ID>"
                                          "<FoldAngle>10</FoldAngle><Velocity>10</Velocity></Fold></CMML>\n";
  const CliResult bad = foldkit({"dof", dir + "/v4.pmml", "--state", dir + "/unknown.cmml"});
  EXPECT_EQ(bad.exit, 1);
  EXPECT_NE(bad.err.find("unknown.cmml:2: "), std::string::npos) << bad.err;
}

}  // namespace

namespace {

TEST(CliReview, ValidateWithAnInvalidPatternStillReports) {
  const std::string dir = temp_dir();
  ASSERT_EQ(foldkit({"generate", "strip", "--panels", "2", "-o", dir + "/s.pmml"}).exit, 0);
  // Drop the joint: the pattern now needs --auto-joints.
  std::string text = slurp(dir + "/s.pmml");
  text.erase(text.find("  <Joint>"), text.find("</Joint>") + 9 - text.find("  <Joint>"));
  std::ofstream(dir + "/a.pmml") << text;
  std::ofstream(dir + "/s.cmml") << "<CMML><Title>t</Title>\n<Fold><EventNumber>1</EventNumber><ID>1</ID>"
                                    "<FoldAngle>90</FoldAngle><Velocity>10</Velocity></Fold></CMML>\n";
  const CliResult strict = foldkit({"validate", dir + "/s.cmml", "--pattern", dir + "/a.pmml", "--json"});
  EXPECT_EQ(strict.exit, 1);
  const auto j = nlohmann::json::parse(strict.out);
  EXPECT_FALSE(j["ok"].get<bool>());
  EXPECT_EQ(j["files"].size(), 2u);
  const CliResult lenient = foldkit({"validate", dir + "/s.cmml", "--pattern", dir + "/a.pmml", "--auto-joints", "--json"});
  EXPECT_EQ(lenient.exit, 0) << lenient.err;
}

TEST(CliReview, JsonSurvivesNonUtf8FileNames) {
  const std::string dir = temp_dir();
  const std::string name = dir + "/n\xe9.pmml";
  ASSERT_EQ(foldkit({"generate", "boat", "-o", name}).exit, 0);
  const CliResult v = foldkit({"validate", name, "--json"});
  EXPECT_EQ(v.exit, 0) << v.err;
  EXPECT_TRUE(nlohmann::json::parse(v.out)["ok"].get<bool>());
}

}  // namespace
