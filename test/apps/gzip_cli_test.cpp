// gzip-compressed files through the command line: `fold -o X.cmml.gz` writes the plain file's
// bytes compressed (`gzip -dc` the oracle), every verb reads compressed CMML and FOLD whatever the
// name, and a cut or damaged file is exit 1 naming the file and its line, with nothing written.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "cli_runner.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/io/pmml.hpp"

namespace {

using foldkit::test::foldkit;
using foldkit::test::shell_quote;
using foldkit::test::slurp;
using foldkit::test::temp_dir;
namespace fs = std::filesystem;
namespace geo = foldkit::geometry;

const std::string& dir() {
  static const std::string d = [] {
    const std::string path = temp_dir() + "/gzip-cli";
    fs::create_directories(path);
    return path;
  }();
  return d;
}

const std::string& pattern() {
  static const std::string path = [] {
    const std::string p = dir() + "/miura.pmml";
    std::ofstream(p) << foldkit::io::write_pmml(geo::build_or_throw(geo::generators::miura(4, 4)).to_spec());
    return p;
  }();
  return path;
}

// `gzip -dc FILE`: the decompressed bytes, by gzip itself.
std::string gunzip(const std::string& path) {
  const std::string out = dir() + "/gunzipped";
  EXPECT_EQ(std::system(("gzip -dc " + shell_quote(path) + " > " + shell_quote(out)).c_str()), 0) << path;
  return slurp(out);
}

void put(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// No file of the folder but `keep`: neither an output nor a temporary file was left behind.
void expect_only(const std::vector<std::string>& keep) {
  for (const auto& e : fs::directory_iterator(dir())) {
    const std::string name = e.path().filename().string();
    EXPECT_NE(std::find(keep.begin(), keep.end(), name), keep.end()) << "left behind: " << name;
  }
}

// Folded once, plain and compressed: the fixture of the tests below.
const std::string& folded() {
  static const std::string packed = [] {
    for (const char* out : {"/fold.cmml", "/fold.cmml.gz"}) {
      const auto r = foldkit({"fold", pattern(), "--fraction", "0.7", "--no-collision", "-o", dir() + out});
      EXPECT_EQ(r.exit, 0) << r.err;
    }
    return dir() + "/fold.cmml.gz";
  }();
  return packed;
}

TEST(GzipCli, FoldWritesThePlainBytesCompressed) {
  const std::string packed = slurp(folded()), plain = slurp(dir() + "/fold.cmml");
  ASSERT_GT(plain.size(), 1000u);
  EXPECT_EQ(packed.substr(0, 2), "\x1f\x8b");
  EXPECT_LT(packed.size() * 5, plain.size());
  EXPECT_EQ(gunzip(folded()), plain);
  // The simulator and the validator read it as they read the plain file.
  const auto a = foldkit({"simulate", pattern(), dir() + "/fold.cmml", "--json"});
  const auto b = foldkit({"simulate", pattern(), folded(), "--json"});
  ASSERT_EQ(b.exit, 0) << b.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_EQ(foldkit({"validate", folded(), "--pattern", pattern()}).exit, 0);
  // -o names the format: a bare .gz is no CMML.
  EXPECT_EQ(foldkit({"fold", pattern(), "--fraction", "0.7", "--no-collision", "-o", dir() + "/x.gz"}).exit, 2);
}

TEST(GzipCli, ConvertReadsAndWritesCompressed) {
  folded();
  const std::string fold_gz = dir() + "/frames.fold.gz", fold = dir() + "/frames.fold";
  ASSERT_EQ(foldkit({"convert", folded(), fold_gz, "--pattern", pattern()}).exit, 0);
  ASSERT_EQ(foldkit({"convert", dir() + "/fold.cmml", fold, "--pattern", pattern()}).exit, 0);
  EXPECT_EQ(gunzip(fold_gz), slurp(fold));
  // Back from the compressed FOLD to PMML and to compressed PMML.
  const std::string pmml = dir() + "/back.pmml", pmml_gz = dir() + "/back.pmml.gz";
  ASSERT_EQ(foldkit({"convert", fold_gz, pmml}).exit, 0);
  ASSERT_EQ(foldkit({"convert", fold_gz, pmml_gz}).exit, 0);
  EXPECT_EQ(gunzip(pmml_gz), slurp(pmml));
  const auto info = foldkit({"info", pmml_gz, "--json"});
  EXPECT_EQ(info.exit, 0) << info.err;
  // CMML to compressed CMML: the same bytes as the fold wrote.
  ASSERT_EQ(foldkit({"convert", dir() + "/fold.cmml", dir() + "/copy.cmml.gz", "--pattern", pattern()}).exit, 0);
  EXPECT_EQ(gunzip(dir() + "/copy.cmml.gz"), slurp(dir() + "/fold.cmml"));
}

TEST(GzipCli, MagicBytesDecideWhateverTheName) {
  const std::string hidden = dir() + "/hidden.cmml";
  fs::copy_file(folded(), hidden, fs::copy_options::overwrite_existing);
  const auto r = foldkit({"simulate", pattern(), hidden, "--json"});
  EXPECT_EQ(r.exit, 0) << r.err;
  EXPECT_EQ(r.out, foldkit({"simulate", pattern(), dir() + "/fold.cmml", "--json"}).out);
}

TEST(GzipCli, CutAndDamagedFilesAreExitOneNamingTheFileAndWriteNothing) {
  const std::string packed = slurp(folded());
  std::string damaged = packed;
  for (std::size_t i = damaged.size() / 2; i < damaged.size() / 2 + 8; ++i) damaged[i] = static_cast<char>(damaged[i] ^ 0x5a);
  for (const auto& [name, bytes, what] : std::vector<std::tuple<std::string, std::string, std::string>>{
           {"cut.cmml.gz", packed.substr(0, packed.size() / 2), "truncated gzip data"},
           {"damaged.cmml.gz", damaged, "corrupt gzip data"}}) {
    SCOPED_TRACE(name);
    const std::string path = dir() + "/" + name;
    put(path, bytes);
    const auto sim = foldkit({"simulate", pattern(), path});
    EXPECT_EQ(sim.exit, 1) << sim.err;
    EXPECT_NE(sim.err.find(path + ":"), std::string::npos) << sim.err;
    EXPECT_NE(sim.err.find(what), std::string::npos) << sim.err;
    const auto conv = foldkit({"convert", path, dir() + "/out.fold.gz", "--pattern", pattern()});
    EXPECT_EQ(conv.exit, 1) << conv.err;
    EXPECT_NE(conv.err.find(path + ":"), std::string::npos) << conv.err;
    // A damaged compressed pattern: exit 1 too, naming the file.
    put(dir() + "/p.pmml.gz", bytes.substr(0, 30));
    const auto to = foldkit({"convert", dir() + "/p.pmml.gz", dir() + "/out.fold"});
    EXPECT_EQ(to.exit, 1) << to.err;
    EXPECT_NE(to.err.find(dir() + "/p.pmml.gz:"), std::string::npos) << to.err;
    fs::remove(dir() + "/p.pmml.gz");
    fs::remove(path);
  }
  // No out.fold(.gz), no temporary .foldkit-XXXXXX.
  expect_only({"miura.pmml", "fold.cmml", "fold.cmml.gz", "gunzipped", "frames.fold.gz", "frames.fold", "back.pmml", "back.pmml.gz",
               "copy.cmml.gz", "hidden.cmml"});
}

}  // namespace
