#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "foldkit/io/cmml.hpp"
#include "foldkit/io/number_format.hpp"
#include "foldkit/io/parse_error.hpp"
#include "spec_helpers.hpp"

namespace {

using namespace foldkit;

const char* const kSequence = R"(<CMML>
  <Title>two events</Title>
  <Fold>
    <EventNumber>2</EventNumber>
    <ID>3</ID>
    <FoldAngle>-45</FoldAngle>
    <Velocity>10</Velocity>
  </Fold>
  <Fold>
    <EventNumber>1</EventNumber>
    <ID>1</ID>
    <FoldAngle>90</FoldAngle>
    <Velocity>30</Velocity>
  </Fold>
  <Fold>
    <EventNumber>1</EventNumber>
    <ID>2</ID>
    <FoldAngle>-90</FoldAngle>
    <Velocity>30</Velocity>
  </Fold>
</CMML>
)";

std::string with(const std::string& from, const std::string& to) {
  std::string s = kSequence;
  const auto pos = s.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return s.replace(pos, from.size(), to);
}

void expect_error(const std::string& text, int line, const std::string& fragment) {
  try {
    io::parse_cmml(text, "bad.cmml");
    FAIL() << "accepted: " << fragment;
  } catch (const io::ParseError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(e.message().find(fragment), std::string::npos) << e.what();
  }
}

TEST(Cmml, GroupsFoldsByEventNumber) {
  const geometry::FoldSequence seq = io::parse_cmml(kSequence, "s.cmml");
  EXPECT_EQ(seq.title, "two events");
  ASSERT_EQ(seq.events.size(), 2u);
  EXPECT_EQ(seq.events[0].number, 1);
  ASSERT_EQ(seq.events[0].folds.size(), 2u);
  EXPECT_EQ(seq.events[0].folds[0].joint_id, 1);
  EXPECT_EQ(seq.events[0].folds[1].joint_id, 2);
  EXPECT_DOUBLE_EQ(seq.events[0].folds[0].angle, M_PI / 2);
  EXPECT_DOUBLE_EQ(seq.events[0].folds[1].angle, -M_PI / 2);
  EXPECT_DOUBLE_EQ(seq.events[0].folds[0].speed, M_PI / 6);
  EXPECT_EQ(seq.events[1].number, 2);
  EXPECT_EQ(seq.events[1].folds[0].line, 3);
}

TEST(Cmml, AnglesCarryThroughFromFlat) {
  const geometry::CreasePattern p = geometry::build_or_throw(test::two_by_two());
  const geometry::FoldSequence seq = io::parse_cmml(kSequence, "s.cmml");
  EXPECT_TRUE(geometry::check_sequence(p, seq).empty());
  const auto states = geometry::event_states(p, seq);
  ASSERT_EQ(states.size(), 3u);
  EXPECT_TRUE(states[0].angles.isZero());
  EXPECT_DOUBLE_EQ(states[1].angles[0], M_PI / 2);
  EXPECT_DOUBLE_EQ(states[1].angles[2], 0.0);
  EXPECT_DOUBLE_EQ(states[2].angles[0], M_PI / 2);  // joint 1 kept its angle in event 2
  EXPECT_DOUBLE_EQ(states[2].angles[2], -M_PI / 4);
  EXPECT_DOUBLE_EQ(states[2].angles[3], 0.0);
}

TEST(Cmml, RoundTripIsExact) {
  const geometry::FoldSequence seq = io::parse_cmml(kSequence, "s.cmml");
  const std::string once = io::write_cmml(seq);
  EXPECT_NE(once.find("<FoldAngle>-45</FoldAngle>"), std::string::npos) << once;
  const geometry::FoldSequence back = io::parse_cmml(once, "t.cmml");
  EXPECT_EQ(io::write_cmml(back), once);
  EXPECT_EQ(back.events[1].folds[0].angle, seq.events[1].folds[0].angle);
}

TEST(Cmml, DegreesFromFilesSurviveUnchanged) {
  for (const char* text : {"30", "-179.5", "0.1", "12.345678", "-0.001", "180", "1e-05"}) {
    const double degrees = io::parse_numbers(text).values[0];
    EXPECT_EQ(io::format_degrees(io::degrees_to_radians(degrees)), text);
  }
  // Any value in radians comes back within one unit in the last place.
  for (double radians : {0.1, 1.0 / 3.0, M_PI, -M_PI, 1e-9, 2.5}) {
    const double back = io::degrees_to_radians(io::parse_numbers(io::format_degrees(radians)).values[0]);
    EXPECT_LE(std::abs(back - radians), 2.3e-16 * std::abs(radians)) << radians;
  }
}

TEST(Cmml, CheckAgainstPattern) {
  const geometry::CreasePattern p = geometry::build_or_throw(test::two_by_two());
  const auto unknown = geometry::check_sequence(p, io::parse_cmml(with("<ID>3</ID>", "<ID>33</ID>"), "s.cmml"));
  ASSERT_EQ(unknown.size(), 1u);
  EXPECT_EQ(unknown[0].line, 3);
  EXPECT_NE(unknown[0].message.find("joint 33"), std::string::npos);
  const auto twice = geometry::check_sequence(p, io::parse_cmml(with("<ID>2</ID>", "<ID>1</ID>"), "s.cmml"));
  ASSERT_EQ(twice.size(), 1u);
  EXPECT_NE(twice[0].message.find("folded twice in event 1"), std::string::npos);
}

TEST(CmmlErrors, Values) {
  expect_error(with("<FoldAngle>90</FoldAngle>", "<FoldAngle>180.5</FoldAngle>"), 12, "outside [-180, 180]");
  expect_error(with("<FoldAngle>90</FoldAngle>", "<FoldAngle>nan</FoldAngle>"), 12, "not a finite number");
  expect_error(with("<FoldAngle>90</FoldAngle>", "<FoldAngle>1e999</FoldAngle>"), 12, "out of range");
  expect_error(with("<Velocity>10</Velocity>", "<Velocity>-1</Velocity>"), 7, "must be positive");
  expect_error(with("<Velocity>10</Velocity>", "<Velocity>0</Velocity>"), 7, "must be positive");
  expect_error(with("<EventNumber>2</EventNumber>", "<EventNumber>1.5</EventNumber>"), 4, "non-negative integer");
  expect_error(with("<EventNumber>2</EventNumber>", "<EventNumber>-1</EventNumber>"), 4, "non-negative integer");
  expect_error(with("<ID>3</ID>", "<ID>three</ID>"), 5, "integer joint ID");
}

TEST(CmmlErrors, SubnormalVelocityIsTooSmall) {
  // 5e-324 degrees/s is positive but 0 rad/s once converted.
  expect_error(with("<Velocity>10</Velocity>", "<Velocity>5e-324</Velocity>"), 7, "must be positive");
  expect_error(with("<Velocity>10</Velocity>", "<Velocity>5e-324</Velocity>"), 7, "(too small)");
  expect_error(with("<Velocity>10</Velocity>", "<Velocity>1e-322</Velocity>"), 7, "(too small)");
  // The smallest that survives is accepted.
  const auto seq = io::parse_cmml(with("<Velocity>10</Velocity>", "<Velocity>1e-320</Velocity>"), "s.cmml");
  EXPECT_GT(seq.events[1].folds[0].speed, 0.0);
}

TEST(CmmlErrors, NotUtf8) {
  expect_error(with("two events", "\xe9v\xe9nements"), 2, "not valid UTF-8 (byte 0xE9): foldkit reads UTF-8 only");
  expect_error(with("two events", "&#xDFFF;"), 2, "is not an allowed XML character");
  expect_error("<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?>\n<CMML/>", 1,
               "encoding 'ISO-8859-1' is not supported: convert the file to UTF-8");
}

TEST(Cmml, WrittenAnglesStayWithin180) {
  geometry::FoldSequence seq = io::parse_cmml(kSequence, "s.cmml");
  auto& fold = seq.events[0].folds[0];
  const std::pair<double, const char*> cases[] = {
      {std::nextafter(M_PI, 4.0), "180"}, {-std::nextafter(M_PI, 4.0), "-180"}, {M_PI, "180"},
      {-M_PI, "-180"}, {4.0, "180"}, {-7.0, "-180"}};
  for (const auto& [angle, text] : cases) {
    fold.angle = angle;
    const std::string file = io::write_cmml(seq);
    EXPECT_NE(file.find(std::string("<FoldAngle>") + text + "</FoldAngle>"), std::string::npos) << angle << "\n" << file;
    const auto back = io::parse_cmml(file, "t.cmml");
    EXPECT_EQ(std::abs(back.events[0].folds[0].angle), M_PI);
  }
}

TEST(Cmml, WriterRejectsWhatCannotBeReadBack) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const geometry::FoldSequence good = io::parse_cmml(kSequence, "s.cmml");
  auto expect_throw = [&](double angle, double speed, const std::string& fragment) {
    geometry::FoldSequence seq = good;
    seq.events[1].folds[0].angle = angle;
    seq.events[1].folds[0].speed = speed;
    try {
      io::write_cmml(seq);
      FAIL() << "wrote angle " << angle << " speed " << speed;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("joint 3"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  expect_throw(nan, 1.0, "fold angle: not a finite number");
  expect_throw(inf, 1.0, "fold angle: not a finite number");
  expect_throw(-inf, 1.0, "fold angle: not a finite number");
  expect_throw(0.5, nan, "speed: not a finite number");
  expect_throw(0.5, inf, "speed: not a finite number");
  expect_throw(0.5, 1e308, "not a finite number");  // 5.7e309 degrees/s
  expect_throw(0.5, 0.0, "speed must be positive");
  expect_throw(0.5, -1.0, "speed must be positive");
  // The smallest positive speed is written and reads back positive.
  geometry::FoldSequence seq = good;
  seq.events[1].folds[0].speed = 5e-324;
  const auto back = io::parse_cmml(io::write_cmml(seq), "t.cmml");
  EXPECT_GT(back.events[1].folds[0].speed, 0.0);
}

TEST(Cmml, TitleRoundTripsAndForbiddenCharactersAreReplaced) {
  geometry::FoldSequence seq = io::parse_cmml(kSequence, "s.cmml");
  seq.title = "fold  it\n  twice";
  EXPECT_EQ(io::parse_cmml(io::write_cmml(seq), "t.cmml").title, seq.title);
  seq.title = "bell\x07";
  EXPECT_EQ(io::parse_cmml(io::write_cmml(seq), "t.cmml").title, "bell\xef\xbf\xbd");
}

TEST(CmmlErrors, Structure) {
  expect_error("<PMML/>", 1, "expected <CMML>");
  expect_error(with("<Velocity>10</Velocity>", ""), 3, "no <Velocity>");
  expect_error(with("<ID>3</ID>", "<ID>3</ID><Torque>1</Torque>"), 5, "unknown element <Torque>");
  expect_error(with("<Title>two events</Title>", "<Title>two events</Title><Step/>"), 2, "unknown element <Step>");
  expect_error("<CMML>\n<Fold>\n", 2, "invalid XML");
  expect_error("", 1, "empty");
}

TEST(Cmml, EmptySequenceIsValid) {
  const auto seq = io::parse_cmml("<CMML><Title>nothing</Title></CMML>", "e.cmml");
  EXPECT_TRUE(seq.events.empty());
}

}  // namespace
