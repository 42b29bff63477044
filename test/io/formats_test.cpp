// The one table of file formats (io/formats.hpp, issue 37): picking by extension, the messages
// that list what is accepted, and every format that reads and writes patterns round-tripping the
// shared fixtures. The oracle for what was read is the format's own reader called directly and
// the pattern's invariants (counts, area), not the table.
#include <gtest/gtest.h>

#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <set>

#include "foldkit/geometry/generators.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/fold_format.hpp"
#include "foldkit/io/formats.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/io/pmml.hpp"
#include "test_paths.hpp"

namespace foldkit::io {
namespace {

using geometry::CreasePattern;

double area(const CreasePattern& p) {
  double a = 0.0;
  for (const auto& actor : p.actors())
    for (const auto& t : actor.triangles) {
      const geometry::Vec2 u = p.vertices()[t.v[1]] - p.vertices()[t.v[0]], w = p.vertices()[t.v[2]] - p.vertices()[t.v[0]];
      a += 0.5 * (u.x() * w.y() - u.y() * w.x());
    }
  return a;
}

// Joint angles keyed by the joint's end coordinates (rounded to 1e-9), which survive writing and
// reading again although joint IDs and order do not.
std::map<std::array<long long, 4>, double> by_segment(const CreasePattern& p, const geometry::FoldState& s) {
  std::map<std::array<long long, 4>, double> out;
  const auto key = [](double v) { return std::llround(v * 1e9); };
  for (std::size_t j = 0; j < p.joints().size(); ++j) {
    geometry::Vec2 a = p.vertices()[p.joints()[j].v[0]], b = p.vertices()[p.joints()[j].v[1]];
    if (std::make_pair(b.x(), b.y()) < std::make_pair(a.x(), a.y())) std::swap(a, b);
    out[{key(a.x()), key(a.y()), key(b.x()), key(b.y())}] = s.angles[static_cast<Eigen::Index>(j)];
  }
  return out;
}

void expect_same_sheet(const CreasePattern& a, const CreasePattern& b) {
  EXPECT_EQ(a.actors().size(), b.actors().size());
  EXPECT_EQ(a.joints().size(), b.joints().size());
  EXPECT_EQ(a.interior_vertices().size(), b.interior_vertices().size());
  EXPECT_NEAR(area(a), area(b), 1e-9 * std::max(1.0, std::abs(area(a))));
}

TEST(Formats, OneEntryPerExtensionPickedIgnoringCase) {
  std::set<std::string> seen;
  for (const FileFormat& f : file_formats()) {
    ASSERT_EQ(f.extension.front(), '.');
    for (char c : f.extension) EXPECT_FALSE(std::isupper(static_cast<unsigned char>(c))) << f.extension;
    EXPECT_TRUE(seen.insert(f.extension).second) << f.extension << " twice";
    EXPECT_FALSE(f.name.empty());
    EXPECT_FALSE(f.media_type.empty());
    EXPECT_TRUE(f.read_pattern || f.write_pattern || f.sequence) << f.name << " does nothing";
    ASSERT_NE(format_of("a/b" + f.extension), nullptr);
    EXPECT_EQ(format_of("a/b" + f.extension)->kind, f.kind);
    std::string upper = f.extension;
    for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    ASSERT_NE(format_of("B" + upper), nullptr) << upper;
    EXPECT_EQ(format_of("B" + upper)->kind, f.kind);
  }
  EXPECT_EQ(format_of("pattern.txt"), nullptr);
  EXPECT_EQ(format_of("pmml"), nullptr);      // a name without the dot is not the extension
  EXPECT_EQ(format_of("x.pmml.bak"), nullptr);
}

TEST(Formats, MessagesListWhatIsAccepted) {
  EXPECT_EQ(extensions(reads_patterns), ".pmml, .fold, .svg, .cp or .opx");
  EXPECT_EQ(extensions(writes_patterns), ".pmml, .cmml, .fold or .svg");
  EXPECT_EQ(extensions(readable), ".pmml, .cmml, .fold, .svg, .cp or .opx");
  EXPECT_EQ(extensions([](const FileFormat&) { return false; }), "");
  try {
    read_pattern_file("sheet.txt");
    FAIL() << "a .txt was read as a pattern";
  } catch (const UnknownFormat& e) {
    EXPECT_STREQ(e.what(), "sheet.txt: a crease pattern must be a .pmml, .fold, .svg, .cp or .opx file");
  }
  // A CMML holds a sequence, not a pattern.
  EXPECT_THROW(read_pattern_file("fold.cmml"), UnknownFormat);
  const CreasePattern p = geometry::build_or_throw(geometry::generators::miura(2, 2));
  try {
    pattern_text("out.obj", p);
    FAIL() << "an .obj was written";
  } catch (const UnknownFormat& e) {
    EXPECT_STREQ(e.what(), "out.obj: unknown output type (use .pmml, .cmml, .fold or .svg)");
  }
  // CMML needs the state it folds to; the message names the file.
  try {
    pattern_text("out.cmml", p);
    FAIL() << "a CMML without a state was written";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("out.cmml: a .cmml output needs fold angles", 0), 0u) << e.what();
  }
}

// Every fixture FOLD read through the table is what read_fold reads; written back through the
// table as each pattern format and read again, it is the same sheet, and a FOLD keeps its angles.
TEST(Formats, FixturesRoundTripThroughEveryPatternFormat) {
  if (!foldkit::test::fixtures_available()) GTEST_SKIP() << "no ../shared/fixtures";
  const std::string dir = foldkit::test::temp_dir();
  int files = 0;
  for (const char* name : {"edemaine_fold__simple.fold", "edemaine_fold__squaretwist.fold", "FoldForge__miura.fold",
                           "osbo_rigid-origami__birdBase.fold", "osbo_rigid-origami__waterbombBase.fold"}) {
    SCOPED_TRACE(name);
    const std::string path = foldkit::test::fixture_path(std::string("fold/") + name);
    const PatternFile read = read_pattern_file(path);
    const FoldImport direct = read_fold(path);
    expect_same_sheet(read.pattern, direct.pattern);
    ASSERT_EQ(read.state.has_value(), direct.state.has_value());
    if (read.state) {
      EXPECT_EQ((read.state->angles - direct.state->angles).cwiseAbs().maxCoeff(), 0.0);
    }
    PatternOutput out;
    out.state = read.state ? &*read.state : nullptr;
    for (const FileFormat& f : file_formats()) {
      if (!f.read_pattern || !f.write_pattern || f.kind == FileKind::Svg) continue;  // SVG: drawn_lines_test
      const std::string copy = dir + "/copy" + std::to_string(files) + f.extension;
      write_file_atomic(copy, pattern_text(copy, read.pattern, out));
      const PatternFile again = read_pattern_file(copy);
      expect_same_sheet(read.pattern, again.pattern);
      if (f.kind == FileKind::Pmml) expect_same_sheet(read_pmml(copy), again.pattern);
      if (f.kind == FileKind::Fold && read.state) {
        ASSERT_TRUE(again.state.has_value());
        const auto before = by_segment(read.pattern, *read.state), after = by_segment(again.pattern, *again.state);
        ASSERT_EQ(before.size(), after.size());
        for (const auto& [segment, angle] : before) {
          ASSERT_EQ(after.count(segment), 1u);
          EXPECT_NEAR(after.at(segment), angle, 1e-9);
        }
      }
    }
    ++files;
  }
  EXPECT_EQ(files, 5);
}

TEST(Formats, AFileItsFormatRefusesIsAParseError) {
  const std::string dir = foldkit::test::temp_dir();
  write_file_atomic(dir + "/bad.pmml", "<PMML><Vertex>");
  write_file_atomic(dir + "/bad.fold", "{\"vertices_coords\": [[0, 0]], ");
  EXPECT_THROW(read_pattern_file(dir + "/bad.pmml"), ParseError);
  EXPECT_THROW(read_pattern_file(dir + "/bad.fold"), ParseError);
}

}  // namespace
}  // namespace foldkit::io
