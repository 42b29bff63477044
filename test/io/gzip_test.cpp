// gzip-compressed CMML and FOLD (docs/FORMATS.md, "Compressed files"): written compressed when the
// name ends in .gz, read compressed when the file starts with 1f 8b whatever its name, the same
// sequence as the plain file (lines included), the plain file's bytes once decompressed — by zlib
// itself (gzip_oracle.hpp), not by the code under test — and damaged data refused at FILE:LINE.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "fold_sequence_equal.hpp"

#include "foldkit/geometry/generators.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/fold_format.hpp"
#include "foldkit/io/formats.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/io/pmml.hpp"
#include "gzip_oracle.hpp"
#include "test_paths.hpp"

namespace {

namespace fs = std::filesystem;
using namespace foldkit;

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void put(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

int lines_in(const std::string& text) { return 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

// `events` events folding `joints` joints each, as projected folding writes every crease at every step.
geometry::FoldSequence sequence(int events, int joints) {
  geometry::FoldSequence s;
  s.title = "gzip";
  for (int e = 0; e < events; ++e) {
    geometry::FoldEvent event{e, {}};
    for (int j = 1; j <= joints; ++j) event.folds.push_back({j, 0.013 * (e + 1) * (j % 2 ? 1 : -1), 0.5 + 0.001 * j});
    s.events.push_back(event);
  }
  return s;
}

using foldkit::test::expect_same;

// The ParseError reading `path` as CMML throws (fails the test when it throws none).
io::ParseError cmml_error(const std::string& path) {
  try {
    io::read_cmml(path);
  } catch (const io::ParseError& e) {
    return e;
  }
  ADD_FAILURE() << path << " was read";
  return io::ParseError(path, 0, "read");
}

TEST(GzipFormats, TheOneTableKnowsCompressedNames) {
  for (const auto& [name, kind] : std::vector<std::pair<std::string, io::FileKind>>{
           {"x.cmml.gz", io::FileKind::Cmml}, {"X.FOLD.GZ", io::FileKind::Fold}, {"dir.gz/p.pmml.Gz", io::FileKind::Pmml}, {"x.fold", io::FileKind::Fold}}) {
    const io::FileFormat* f = io::format_of(name);
    ASSERT_NE(f, nullptr) << name;
    EXPECT_EQ(f->kind, kind) << name;
  }
  for (const char* name : {"x.gz", "x.cmml.gz.bak", "x.cmmlgz", ".gz", "x.gz.gz"}) EXPECT_EQ(io::format_of(name), nullptr) << name;
}

// Small (read whole) and large (from 4 MB: read a slice at a time) sequences alike.
TEST(GzipCmml, CompressedRoundTripEqualsPlain) {
  const std::string dir = test::temp_dir();
  for (const auto& [events, joints] : std::vector<std::pair<int, int>>{{1, 1}, {12, 40}, {200, 300}}) {
    SCOPED_TRACE(std::to_string(events) + " × " + std::to_string(joints));
    const geometry::FoldSequence s = sequence(events, joints);
    io::write_cmml_file(dir + "/s.cmml", s);
    io::write_cmml_file(dir + "/s.cmml.gz", s);
    const std::string plain = bytes_of(dir + "/s.cmml"), packed = bytes_of(dir + "/s.cmml.gz");
    EXPECT_EQ(plain, io::write_cmml(s));  // the paper's format, byte for byte
    ASSERT_GE(packed.size(), 2u);
    EXPECT_EQ(packed.substr(0, 2), "\x1f\x8b");
    EXPECT_EQ(test::gunzip(packed), plain);
    if (plain.size() > (std::size_t(4) << 20)) {
      EXPECT_LT(packed.size() * 8, plain.size());
    }
    const geometry::FoldSequence a = io::read_cmml(dir + "/s.cmml"), b = io::read_cmml(dir + "/s.cmml.gz");
    expect_same(b, a);
    expect_same(a, io::parse_cmml(plain, dir + "/s.cmml"));
    // The sliced reader on compressed input: the same sequence as slicing the plain text.
    const auto sliced = io::detail::parse_cmml_sliced(plain, "s.cmml", 4096);
    ASSERT_TRUE(sliced.has_value()) << "the sliced reader declined foldkit's own output";
    expect_same(b, *sliced);
  }
  // The same sequence always gives the same compressed bytes (no time stamp in the header).
  io::write_cmml_file(dir + "/again.cmml.gz", sequence(12, 40));
  io::write_cmml_file(dir + "/s.cmml.gz", sequence(12, 40));
  EXPECT_EQ(bytes_of(dir + "/again.cmml.gz"), bytes_of(dir + "/s.cmml.gz"));
}

TEST(GzipCmml, MagicBytesDecideNotTheName) {
  const std::string dir = test::temp_dir();
  const std::string text = io::write_cmml(sequence(3, 5));
  put(dir + "/looks-plain.cmml", test::gzip(text));  // compressed under a plain name
  put(dir + "/looks-packed.cmml.gz", text);          // plain under a compressed name
  put(dir + "/other.pmml", test::gzip(text));
  const geometry::FoldSequence reference = io::parse_cmml(text, "x");
  expect_same(io::read_cmml(dir + "/looks-plain.cmml"), reference);
  expect_same(io::read_cmml(dir + "/looks-packed.cmml.gz"), reference);
  expect_same(io::read_cmml(dir + "/other.pmml"), reference);
  // gzip's concatenated members are one text, as gzip -d reads them.
  put(dir + "/two.cmml", test::gzip(text.substr(0, 100)) + test::gzip(text.substr(100)));
  expect_same(io::read_cmml(dir + "/two.cmml"), reference);
  EXPECT_EQ(io::read_file(dir + "/two.cmml"), text);
  // A single 0x1f is no magic: a plain file that starts with it is read (and refused) as text.
  put(dir + "/one-byte.cmml", "\x1f");
  EXPECT_EQ(io::read_file(dir + "/one-byte.cmml"), "\x1f");
}

TEST(GzipFold, PatternsAndFramesRoundTripCompressed) {
  const std::string dir = test::temp_dir();
  const geometry::CreasePattern p = geometry::build_or_throw(geometry::generators::miura(3, 3));
  io::FoldExport extra;
  extra.state = geometry::FoldState::flat(p);
  const std::string text = io::write_fold(p, extra);
  io::write_file_atomic(dir + "/m.fold.gz", text);
  EXPECT_EQ(test::gunzip(bytes_of(dir + "/m.fold.gz")), text);
  const io::FoldImport plain = io::parse_fold(text, "m.fold");
  for (const char* name : {"/m.fold.gz", "/m.fold"}) {
    if (std::string(name) == "/m.fold") put(dir + name, test::gzip(text));  // compressed, plain name
    const io::PatternFile read = io::read_pattern_file(dir + name);
    EXPECT_EQ(io::write_pmml(read.pattern.to_spec()), io::write_pmml(plain.pattern.to_spec())) << name;
    ASSERT_TRUE(read.state.has_value()) << name;
  }
  // Through the table: X.pmml.gz is a compressed PMML.
  io::write_file_atomic(dir + "/m.pmml.gz", io::pattern_text(dir + "/m.pmml.gz", p));
  EXPECT_EQ(test::gunzip(bytes_of(dir + "/m.pmml.gz")), io::write_pmml(p.to_spec()));
  EXPECT_EQ(io::read_pattern_file(dir + "/m.pmml.gz").pattern.joints().size(), p.joints().size());
}

// Cut in half, the file stops at the line its text reached; bytes flipped in the middle are
// corrupt data (or, at the latest, a failed CRC at the end). Either way: FILE:LINE, no sequence.
TEST(GzipCmml, TruncatedAndCorruptFilesAreErrorsAtTheirLine) {
  const std::string dir = test::temp_dir();
  for (const auto& [events, joints] : std::vector<std::pair<int, int>>{{12, 40}, {200, 300}}) {
    const std::string packed = test::gzip(io::write_cmml(sequence(events, joints)));
    const std::string cut = packed.substr(0, packed.size() / 2);
    put(dir + "/cut.cmml.gz", cut);
    const io::ParseError e = cmml_error(dir + "/cut.cmml.gz");
    EXPECT_EQ(e.file(), dir + "/cut.cmml.gz");
    EXPECT_EQ(e.line(), lines_in(test::gunzip_prefix(cut))) << e.what();
    EXPECT_NE(e.message().find("truncated gzip data"), std::string::npos) << e.what();
    EXPECT_THROW(io::read_file(dir + "/cut.cmml.gz"), io::ParseError);

    std::string bad = packed;
    for (std::size_t i = bad.size() / 2; i < bad.size() / 2 + 16; ++i) bad[i] = static_cast<char>(bad[i] ^ 0x5a);
    put(dir + "/bad.cmml.gz", bad);
    const io::ParseError c = cmml_error(dir + "/bad.cmml.gz");
    EXPECT_EQ(c.file(), dir + "/bad.cmml.gz");
    EXPECT_GT(c.line(), 1) << c.what();
    EXPECT_NE(c.message().find("corrupt gzip data"), std::string::npos) << c.what();
  }
  // Nothing but the magic bytes: no text at all, so no line.
  put(dir + "/magic.cmml", "\x1f\x8b");
  const io::ParseError m = cmml_error(dir + "/magic.cmml");
  EXPECT_EQ(std::string(m.what()), dir + "/magic.cmml: truncated gzip data: the file ends before its compressed stream does");
  // Bytes after the last member that are not another member.
  put(dir + "/tail.cmml", test::gzip(io::write_cmml(sequence(2, 2))) + "junk");
  EXPECT_NE(cmml_error(dir + "/tail.cmml").message().find("corrupt gzip data"), std::string::npos);
}

// Random damage never crashes, hangs or reads as a sequence: every cut and every flipped byte is
// caught, by inflate or by the CRC-32 and length of the trailer.
TEST(GzipCmml, RandomDamageIsAlwaysAParseError) {
  const std::string dir = test::temp_dir();
  const std::string packed = test::gzip(io::write_cmml(sequence(6, 9)));
  std::mt19937 rng(35);
  for (int trial = 0; trial < 400; ++trial) {
    std::string t = packed;
    if (trial % 2 == 0) {
      t.resize(rng() % t.size());
    } else {
      const std::size_t at = 10 + rng() % (t.size() - 10);  // past the header, whose flags gzip ignores in part
      t[at] = static_cast<char>(t[at] ^ (1 + rng() % 255));
    }
    put(dir + "/r.cmml", t);
    SCOPED_TRACE("trial " + std::to_string(trial));
    EXPECT_THROW(io::read_cmml(dir + "/r.cmml"), io::ParseError);
  }
}

TEST(GzipWrite, FailuresLeaveNothing) {
  const std::string dir = test::temp_dir();
  geometry::FoldSequence s = sequence(3, 3);
  s.events[1].folds[1].angle = std::nan("");
  EXPECT_THROW(io::write_cmml_file(dir + "/nan.cmml.gz", s), std::invalid_argument);
  EXPECT_THROW(io::write_cmml_file(dir + "/nan.cmml", s), std::invalid_argument);
  EXPECT_THROW(io::write_cmml_file(dir + "/missing/x.cmml.gz", sequence(1, 1)), io::WriteError);
  EXPECT_TRUE(fs::is_empty(dir));  // no output and no temporary file
  // An old file stays as it was when writing over it fails.
  io::write_cmml_file(dir + "/keep.cmml.gz", sequence(1, 1));
  const std::string before = bytes_of(dir + "/keep.cmml.gz");
  EXPECT_THROW(io::write_cmml_file(dir + "/keep.cmml.gz", s), std::invalid_argument);
  EXPECT_EQ(bytes_of(dir + "/keep.cmml.gz"), before);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

}  // namespace
