// foldkit hamiltonian: exit codes, JSON fields, the path file and bad shapes.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli_runner.hpp"
#include "test_paths.hpp"

namespace {

using foldkit::test::CliResult;
using foldkit::test::foldkit;
using foldkit::test::slurp;
using foldkit::test::temp_dir;
using foldkit::test::write_temp;


std::size_t line_count(const std::string& text) {
  std::size_t n = 0;
  for (const char c : text) n += c == '\n';
  return n;
}

TEST(HamiltonianCli, RectangleExactPathToFile) {
  const std::string shape = write_temp("rect.txt", "####\n####\n####\n");
  const std::string out = write_temp("rect.path", "");
  const CliResult r = foldkit({"hamiltonian", shape, "--json", "-o", out});
  ASSERT_EQ(r.exit, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["found"].get<bool>());
  EXPECT_EQ(j["method"], "exact");
  EXPECT_EQ(j["cells"], 12);
  EXPECT_EQ(j["length"], 12);
  const std::string path = slurp(out);
  EXPECT_EQ(line_count(path), 12u);
  int x = -1, y = -1;
  std::istringstream(path) >> x >> y;
  EXPECT_GE(x, 0);
  EXPECT_GE(y, 0);
}

TEST(HamiltonianCli, PlusHasNoPathButItsRefinementHasACycle) {
  const std::string shape = write_temp("plus.grid", ".#.\n###\n.#.\n");
  const CliResult none = foldkit({"hamiltonian", shape, "--json"});
  EXPECT_EQ(none.exit, 4);
  const auto j = nlohmann::json::parse(none.out);
  EXPECT_FALSE(j["found"].get<bool>());
  EXPECT_EQ(j["verdict"], "none");
  EXPECT_EQ(j["status"], "no-solution");
  EXPECT_EQ(j["message"], j["reason"]);
  EXPECT_NE(j["reason"].get<std::string>().find("degree 1"), std::string::npos);
  EXPECT_NE(none.err.find("degree 1"), std::string::npos);
  const CliResult refined = foldkit({"hamiltonian", shape, "--refine"});
  ASSERT_EQ(refined.exit, 0) << refined.err;
  EXPECT_EQ(line_count(refined.out), 20u);
}

TEST(HamiltonianCli, PbmAndVoxels) {
  const CliResult pbm = foldkit({"hamiltonian", write_temp("l.pbm", "P1\n2 3\n1 0\n1 0\n1 1\n"), "--json"});
  ASSERT_EQ(pbm.exit, 0) << pbm.err;
  EXPECT_EQ(nlohmann::json::parse(pbm.out)["length"], 4);
  // Extensions ignore case, as for the other verbs: an upper-case .PBM is read as PBM.
  const CliResult upper = foldkit({"hamiltonian", write_temp("L.PBM", "P1\n2 3\n1 0\n1 0\n1 1\n"), "--json"});
  ASSERT_EQ(upper.exit, 0) << upper.err;
  EXPECT_EQ(nlohmann::json::parse(upper.out)["length"], 4);
  const std::string out = write_temp("v.path", "");
  const CliResult vox = foldkit({"hamiltonian", write_temp("v.vox", "##\n#.\n\n#.\n..\n"), "--refine", "-o", out, "--json"});
  ASSERT_EQ(vox.exit, 0) << vox.err;
  EXPECT_EQ(nlohmann::json::parse(vox.out)["length"], 32);
  const std::string path = slurp(out);
  EXPECT_EQ(line_count(path), 32u);
  int x = -1, y = -1, z = -1;
  std::istringstream(path) >> x >> y >> z;
  EXPECT_GE(z, 0);
}

TEST(HamiltonianCli, StartOnTheMinorityColourIsAParityVerdict) {
  const std::string shape = write_temp("square.txt", "###\n###\n###\n");
  const CliResult corner = foldkit({"hamiltonian", shape, "--start", "2,2"});
  ASSERT_EQ(corner.exit, 0) << corner.err;
  EXPECT_EQ(corner.out.substr(0, 4), "2 2\n");
  const CliResult edge = foldkit({"hamiltonian", shape, "--start", "1,0", "--json"});
  EXPECT_EQ(edge.exit, 4);
  EXPECT_NE(nlohmann::json::parse(edge.out)["reason"].get<std::string>().find("majority colour"), std::string::npos);
  EXPECT_EQ(foldkit({"hamiltonian", shape, "--start", "1"}).exit, 2);
  EXPECT_EQ(foldkit({"hamiltonian", shape, "--start", "1,1", "--refine"}).exit, 2);
}

TEST(HamiltonianCli, BadInputs) {
  const CliResult ragged = foldkit({"hamiltonian", write_temp("ragged.txt", "##\n###\n")});
  EXPECT_EQ(ragged.exit, 1);
  EXPECT_NE(ragged.err.find("ragged.txt:2:"), std::string::npos) << ragged.err;
  const CliResult pbm = foldkit({"hamiltonian", write_temp("bad.pbm", "P1\n2 2\n1 1\n1 7\n")});
  EXPECT_EQ(pbm.exit, 1);
  EXPECT_NE(pbm.err.find("bad.pbm:4:"), std::string::npos) << pbm.err;
  const CliResult apart = foldkit({"hamiltonian", write_temp("apart.txt", "#.#\n"), "--refine"});
  EXPECT_EQ(apart.exit, 4);
  EXPECT_NE(apart.err.find("not connected"), std::string::npos) << apart.err;
  EXPECT_EQ(foldkit({"hamiltonian", write_temp("shape.png", "#\n")}).exit, 2);
  EXPECT_EQ(foldkit({"hamiltonian"}).exit, 2);
  EXPECT_EQ(foldkit({"hamiltonian", write_temp("missing-dir/none.txt", "")}).exit, 1);
}

}  // namespace
