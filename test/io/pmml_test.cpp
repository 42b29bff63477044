#include <gtest/gtest.h>

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

TEST(Pmml, ReadPmmlReportsGeometryWithLine) {
  // read_pmml builds the pattern; a joint on a boundary edge is reported at the joint's line.
  const std::string text = with("<Coords>1 0 1 1</Coords>", "<Coords>0 0 1 0</Coords>");
  const auto spec = io::parse_pmml(text, "j.pmml");
  const auto built = geometry::build_pattern(spec);
  ASSERT_FALSE(built.pattern);
  EXPECT_EQ(built.diagnostics[0].line, 14);
}

}  // namespace
