#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include "foldkit/io/parse_error.hpp"
#include "foldkit/io/pmml.hpp"
#include "spec_helpers.hpp"

namespace {

using namespace foldkit;
using geometry::Vec2;

const char* const kTwoPanels = R"(<?xml version="1.0"?>
<PMML>
  <Title>two panels</Title>
  <Actor>
    <ID>1</ID>
    <Triangle>0 0 1 0 1 1</Triangle>
    <Triangle>0 0 1 1 0 1</Triangle>
  </Actor>
  <Actor>
    <ID>2</ID>
    <Triangle>1 0 2 0 2 1</Triangle>
    <Triangle>1 0 2 1 1 1</Triangle>
  </Actor>
  <Joint>
    <ID>10</ID>
    <Coords>1 0 1 1</Coords>
    <ActorIDs>1 2</ActorIDs>
    <SpringConst>2.5</SpringConst>
    <DampConst>0.25</DampConst>
  </Joint>
</PMML>
)";

// Parses `text` expecting a ParseError at `line` whose message contains `fragment`.
void expect_error(const std::string& text, int line, const std::string& fragment) {
  try {
    io::parse_pmml(text, "bad.pmml");
    FAIL() << "accepted: " << fragment;
  } catch (const io::ParseError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(e.message().find(fragment), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("bad.pmml:", 0), 0u) << e.what();
  }
}

// kTwoPanels with `from` replaced by `to` (first occurrence).
std::string with(const std::string& from, const std::string& to) {
  std::string s = kTwoPanels;
  const auto pos = s.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return s.replace(pos, from.size(), to);
}

TEST(Pmml, ReadsTable1) {
  const geometry::PatternSpec s = io::parse_pmml(kTwoPanels, "two.pmml");
  EXPECT_EQ(s.title, "two panels");
  ASSERT_EQ(s.actors.size(), 2u);
  EXPECT_EQ(s.actors[1].id, 2);
  EXPECT_EQ(s.actors[1].line, 9);
  ASSERT_EQ(s.actors[0].triangles.size(), 2u);
  EXPECT_EQ(s.actors[0].triangles[1].corners[1], Vec2(1, 1));
  EXPECT_EQ(s.actors[0].triangles[1].line, 7);
  ASSERT_EQ(s.joints.size(), 1u);
  EXPECT_EQ(s.joints[0].id, 10);
  EXPECT_EQ(s.joints[0].coords[1], Vec2(1, 1));
  EXPECT_EQ(s.joints[0].actor_ids[1], 2);
  EXPECT_EQ(s.joints[0].spring, 2.5);
  EXPECT_EQ(s.joints[0].damping, 0.25);
  EXPECT_EQ(s.joints[0].assignment, geometry::Assignment::Unassigned);
  const geometry::CreasePattern p = geometry::build_or_throw(s);
  EXPECT_EQ(p.joints().size(), 1u);
}

TEST(Pmml, RoundTripIsExact) {
  geometry::PatternSpec s = test::two_by_two();
  s.actors[0].triangles[0].corners[1] = Vec2(0.1 + 0.2, 1.0 / 3.0);  // digits that need 17 places
  s.actors[0].triangles[0].corners[0] = Vec2(0, 0);
  s.joints[1].assignment = geometry::Assignment::Valley;
  s.joints[2].spring = 1e-300;
  s.title = "a <title> & \"quotes\"";
  const std::string once = io::write_pmml(s);
  const geometry::PatternSpec back = io::parse_pmml(once, "x.pmml");
  EXPECT_EQ(back.title, s.title);
  EXPECT_EQ(back.actors[0].triangles[0].corners[1], s.actors[0].triangles[0].corners[1]);
  EXPECT_EQ(back.joints[1].assignment, geometry::Assignment::Valley);
  EXPECT_EQ(back.joints[2].spring, 1e-300);
  EXPECT_EQ(io::write_pmml(back), once);
}

TEST(Pmml, MaxTorqueExtensionReadsWritesAndIsOptional) {
  const auto s = io::parse_pmml(with("<DampConst>0.25</DampConst>", "<DampConst>0.25</DampConst><MaxTorque>2.5</MaxTorque>"), "x");
  ASSERT_TRUE(s.joints[0].max_torque.has_value());
  EXPECT_EQ(*s.joints[0].max_torque, 2.5);
  const std::string text = io::write_pmml(s);
  EXPECT_NE(text.find("<MaxTorque>2.5</MaxTorque>"), std::string::npos) << text;
  EXPECT_EQ(io::parse_pmml(text, "y").joints[0].max_torque, 2.5);
  // Without it, nothing is written: plain PMML stays the paper's Table 1.
  geometry::PatternSpec plain = test::two_by_two();
  EXPECT_EQ(io::write_pmml(plain).find("MaxTorque"), std::string::npos);
  plain.joints[0].max_torque = std::numeric_limits<double>::infinity();
  EXPECT_THROW(io::write_pmml(plain), std::invalid_argument);
  expect_error(with("<DampConst>0.25</DampConst>", "<DampConst>0.25</DampConst><MaxTorque>strong</MaxTorque>"), 19, "MaxTorque");
}

TEST(Pmml, AcceptsAssignmentExtension) {
  const auto s = io::parse_pmml(with("<DampConst>0.25</DampConst>", "<DampConst>0.25</DampConst><Assignment>M</Assignment>"), "x");
  EXPECT_EQ(s.joints[0].assignment, geometry::Assignment::Mountain);
}

TEST(PmmlErrors, Syntax) {
  expect_error("", 1, "empty");
  expect_error("<PMML>\n<Actor>\n</PMML>", 2, "invalid XML");
  expect_error(std::string("<PMML>\n\0</PMML>", 16), 2, "NUL");
  expect_error(std::string(20000, '<'), 1, "invalid XML");
}

TEST(PmmlErrors, DeepNestingIsRejected) {
  std::string deep = "<PMML>";
  for (int i = 0; i < 20000; ++i) deep += "<a>";
  EXPECT_THROW(io::parse_pmml(deep, "deep.pmml"), io::ParseError);
}

TEST(PmmlErrors, Structure) {
  expect_error("<CMML/>", 1, "expected <PMML>");
  expect_error("<PMML><Title>x</Title></PMML>", 1, "no <Actor>");
  expect_error(with("<Title>two panels</Title>", "<Title>a</Title>\n<Title>b</Title>"), 4, "more than one <Title>");
  expect_error(with("<ID>1</ID>", "<ID>1</ID><Colour>red</Colour>"), 5, "unknown element <Colour> in <Actor>");
  expect_error(with("<SpringConst>", "<Material>x</Material><SpringConst>"), 18, "unknown element <Material>");
  expect_error(with("<Title>", "<Sheet/><Title>"), 3, "unknown element <Sheet> in <PMML>");
  expect_error(with("<Actor>", "<Actor id=\"3\">"), 4, "unexpected attribute 'id'");
  expect_error(with("<ID>1</ID>", "<ID>1</ID>stray"), 5, "unexpected text");
  expect_error(with("<ActorIDs>1 2</ActorIDs>", ""), 14, "no <ActorIDs>");
  expect_error(with("<ID>1</ID>", ""), 4, "no <ID>");
  expect_error(with("<DampConst>0.25</DampConst>", "<DampConst>0.25</DampConst><DampConst>1</DampConst>"), 19,
               "more than one <DampConst>");
  expect_error(with("<Triangle>0 0 1 0 1 1</Triangle>\n    <Triangle>0 0 1 1 0 1</Triangle>", ""), 4, "has no <Triangle>");
}

TEST(PmmlErrors, Values) {
  expect_error(with("<ID>1</ID>", "<ID>1.5</ID>"), 5, "must be an integer");
  expect_error(with("<ID>1</ID>", "<ID>one</ID>"), 5, "must be an integer");
  expect_error(with("<ID>1</ID>", "<ID>99999999999</ID>"), 5, "must be an integer");
  expect_error(with("<ActorIDs>1 2</ActorIDs>", "<ActorIDs>1 2.0</ActorIDs>"), 17, "two integer actor IDs");
  expect_error(with("<ActorIDs>1 2</ActorIDs>", "<ActorIDs>1</ActorIDs>"), 17, "two actor IDs");
  expect_error(with("0 0 1 0 1 1", "0 0 1 0 1"), 6, "needs 6 numbers, found 5");
  expect_error(with("0 0 1 0 1 1", "0 0 1 0 1 nan"), 6, "'nan' is not a finite number");
  expect_error(with("0 0 1 0 1 1", "0 0 1 0 1 inf"), 6, "is not a finite number");
  expect_error(with("0 0 1 0 1 1", "0 0 1 0 1 1e999"), 6, "out of range");
  expect_error(with("<Coords>1 0 1 1</Coords>", "<Coords>1 0 1 x</Coords>"), 16, "'x' is not a number");
  expect_error(with("<SpringConst>2.5</SpringConst>", "<SpringConst></SpringConst>"), 18, "must hold one number, found 0");
}

TEST(PmmlErrors, RejectsBytesThatAreNotUtf8) {
  const std::string msg = "not valid UTF-8 (byte 0xE9): foldkit reads UTF-8 only";
  expect_error(with("<ID>1</ID>", "<ID>\xe9</ID>"), 5, msg);
  expect_error(with("two panels", "caf\xe9"), 3, msg);                         // ISO-8859-1 "café"
  expect_error(with("two panels", "\xc0\xaf"), 3, "(byte 0xC0)");              // overlong '/'
  expect_error(with("two panels", "\xe0\x80\xaf"), 3, "(byte 0xE0)");          // overlong, 3 bytes
  expect_error(with("two panels", "\xed\xa0\x80"), 3, "(byte 0xED)");          // surrogate U+D800
  expect_error(with("two panels", "\xf4\x90\x80\x80"), 3, "(byte 0xF4)");      // U+110000
  expect_error(with("two panels", "\xf8\x88\x80\x80\x80"), 3, "(byte 0xF8)");  // 5-byte form
  expect_error(with("two panels", "\x80"), 3, "(byte 0x80)");                  // stray continuation
  expect_error(with("<DampConst>0.25</DampConst>", "<DampConst>0.25</DampConst><!-- \xe9 -->"), 19, "(byte 0xE9)");
  expect_error(std::string(kTwoPanels) + "\xe2\x82", 22, "(byte 0xE2)");  // truncated at the end
  expect_error(with("two panels", "a\x1b"), 3, "character U+001B is not allowed in XML");
  expect_error(with("two panels", "\xef\xbf\xbe"), 3, "U+FFFE is not allowed");
  // Real UTF-8 (2, 3 and 4 bytes) and a byte-order mark are fine.
  const auto s = io::parse_pmml("\xef\xbb\xbf" + with("two panels", "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x93\x84"), "u.pmml");
  EXPECT_EQ(s.title, "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x93\x84");
}

TEST(PmmlErrors, RejectsCharacterReferencesToForbiddenCodePoints) {
  expect_error(with("two panels", "&#xD800;"), 3, "character reference '&#xD800;' is not an allowed XML character");
  expect_error(with("two panels", "a &#57343; b"), 3, "'&#57343;'");  // U+DFFF
  expect_error(with("two panels", "&#x110000;"), 3, "'&#x110000;'");
  expect_error(with("two panels", "&#x200000;"), 3, "'&#x200000;'");
  expect_error(with("two panels", "&#0;"), 3, "'&#0;'");
  expect_error(with("two panels", "&#x1B;"), 3, "'&#x1B;'");
  expect_error(with("two panels", "&#xFFFF;"), 3, "'&#xFFFF;'");
  expect_error(with("<ID>1</ID>", "<ID>1&#xD800;</ID>"), 5, "'&#xD800;'");
  // Allowed references decode; in comments and CDATA "&#0;" is plain text.
  const auto s = io::parse_pmml(with("two panels", "caf&#xE9; &#x1F4C4;&#9;x<!-- &#0; -->"), "r.pmml");
  EXPECT_EQ(s.title, "caf\xc3\xa9 \xf0\x9f\x93\x84\tx");
  EXPECT_EQ(io::parse_pmml(with("two panels", "<![CDATA[&#0;]]>"), "r.pmml").title, "&#0;");
}

TEST(PmmlErrors, RejectsDeclaredEncodingsOtherThanUtf8) {
  const std::string latin1 = std::string("<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?>\n") + (kTwoPanels + 22);
  expect_error(latin1, 1, "encoding 'ISO-8859-1' is not supported: convert the file to UTF-8");
  // Reported before the first Latin-1 byte.
  std::string latin1_cafe = latin1;
  latin1_cafe.replace(latin1_cafe.find("two panels"), 10, "caf\xe9");
  expect_error(latin1_cafe, 1, "encoding 'ISO-8859-1' is not supported");
  // A declaration after leading whitespace is read from tinyxml2's declaration node.
  expect_error("\n" + latin1, 2, "encoding 'ISO-8859-1' is not supported");
  expect_error(std::string("<?xml version='1.0' encoding = 'windows-1252'?>\n") + (kTwoPanels + 22), 1, "'windows-1252'");
  for (const char* ok : {"UTF-8", "utf-8"}) {
    const std::string text = std::string("<?xml version=\"1.0\" encoding=\"") + ok + "\"?>\n" + (kTwoPanels + 22);
    EXPECT_EQ(io::parse_pmml(text, "ok.pmml").title, "two panels");
  }
}

TEST(Pmml, LeafTextJoinsTextCdataAndSkipsComments) {
  EXPECT_EQ(io::parse_pmml(with("<ID>1</ID>", "<ID>1<!-- c -->2</ID>"), "x").actors[0].id, 12);
  EXPECT_EQ(io::parse_pmml(with("<ID>1</ID>", "<ID>5<![CDATA[6]]></ID>"), "x").actors[0].id, 56);
  EXPECT_EQ(io::parse_pmml(with("<SpringConst>2.5</SpringConst>", "<SpringConst><!-- k -->2<![CDATA[.]]>5</SpringConst>"), "x")
                .joints[0].spring, 2.5);
  EXPECT_EQ(io::parse_pmml(with("two panels", "two <!-- x -->panels<![CDATA[ & <more>]]>"), "x").title,
            "two panels & <more>");
  expect_error(with("<ID>1</ID>", "<ID>1 <!-- c --> 2</ID>"), 5, "must be an integer");
}

TEST(Pmml, TitleKeepsInnerWhitespace) {
  EXPECT_EQ(io::parse_pmml(with("two panels", "  two   panels\n\tend  "), "x").title, "two   panels\n\tend");
  geometry::PatternSpec s = test::two_by_two();
  for (const std::string title : {"a   x", "line one\nline two", "a \t b\r\nc", "x  y  \n  z"}) {
    s.title = title;
    EXPECT_EQ(io::parse_pmml(io::write_pmml(s), "t.pmml").title, title);
  }
  // Whitespace elsewhere is tolerated as before.
  const auto a = io::parse_pmml(with("<DampConst>0.25</DampConst>", "<DampConst>\n 0.25 \n</DampConst><Assignment> V\n</Assignment>"), "x");
  EXPECT_EQ(a.joints[0].assignment, geometry::Assignment::Valley);
  EXPECT_EQ(a.joints[0].damping, 0.25);
}

TEST(Pmml, WriterReplacesCharactersXmlForbids) {
  geometry::PatternSpec s = test::two_by_two();
  const std::string fffd = "\xef\xbf\xbd";
  const std::pair<std::string, std::string> cases[] = {
      {"esc\x1b[0m", "esc" + fffd + "[0m"},
      {std::string("a\x01" "b\x1f" "c\x7f"), "a" + fffd + "b" + fffd + "c\x7f"},
      {"x\xef\xbf\xbey\xef\xbf\xbf", "x" + fffd + "y" + fffd},   // U+FFFE, U+FFFF
      {"caf\xe9 \xed\xa0\x80!", "caf" + fffd + " " + fffd + fffd + fffd + "!"},  // not UTF-8
      {"tab\tok \xc3\xa9", "tab\tok \xc3\xa9"},
  };
  for (const auto& [title, expected] : cases) {
    s.title = title;
    const std::string file = io::write_pmml(s);
    tinyxml2::XMLDocument doc;
    ASSERT_EQ(doc.Parse(file.c_str(), file.size()), tinyxml2::XML_SUCCESS) << file;
    EXPECT_EQ(io::parse_pmml(file, "w.pmml").title, expected);
  }
}

TEST(Pmml, WriterRejectsNonFiniteNumbers) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto expect_throw = [](const geometry::PatternSpec& s, const std::string& fragment) {
    try {
      io::write_pmml(s);
      FAIL() << "wrote " << fragment;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("not a finite number"), std::string::npos) << e.what();
    }
  };
  geometry::PatternSpec s = test::two_by_two();
  s.actors[1].triangles[0].corners[2] = Vec2(inf, 0);
  expect_throw(s, "actor " + std::to_string(s.actors[1].id) + " triangle coordinate");
  s = test::two_by_two();
  s.actors[0].triangles[0].corners[0] = Vec2(0, nan);
  expect_throw(s, "triangle coordinate");
  s = test::two_by_two();
  s.joints[0].coords[1] = Vec2(-inf, 1);
  expect_throw(s, "joint " + std::to_string(s.joints[0].id) + " coordinate");
  s = test::two_by_two();
  s.joints[1].spring = nan;
  expect_throw(s, "spring constant");
  s = test::two_by_two();
  s.joints[2].damping = inf;
  expect_throw(s, "damping constant");
}

TEST(Pmml, ReadPmmlReportsGeometryWithLine) {
  // read_pmml builds the pattern; a joint on a boundary edge is reported at the joint's line.
  const std::string text = with("<Coords>1 0 1 1</Coords>", "<Coords>0 0 1 0</Coords>");
  const auto spec = io::parse_pmml(text, "j.pmml");
  const auto built = geometry::build_pattern(spec);
  ASSERT_FALSE(built.pattern);
  EXPECT_EQ(built.diagnostics[0].line, 14);
}

}  // namespace
