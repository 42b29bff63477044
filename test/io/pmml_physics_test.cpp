// foldkit's PMML extensions for the dynamic model under <PMML>: <Density>, <Gravity>,
// <FixedActor>. Read, checked at their lines, carried by the built pattern, written back only
// when set; a plain PMML (the paper's Table 1) writes exactly as it did before them. The written
// text is read back with tinyxml2 directly, not with foldkit's reader.
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include "foldkit/io/parse_error.hpp"
#include "foldkit/io/pmml.hpp"
#include "test_paths.hpp"

namespace {

using namespace foldkit;

// Two unit panels; line 3 is the line the extensions are inserted at (after the title).
const char* const kPlain = R"(<?xml version="1.0" encoding="UTF-8"?>
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

// kPlain with `lines` (each one line of text) inserted after the title, from line 4 on.
std::string with_physics(const std::vector<std::string>& lines) {
  std::string text = kPlain;
  std::string block;
  for (const auto& l : lines) block += "  " + l + "\n";
  const std::string title = "</Title>\n";
  return text.insert(text.find(title) + title.size(), block);
}

// The names and texts of <PMML>'s children in `text`, as tinyxml2 reads them.
std::vector<std::pair<std::string, std::string>> root_children(const std::string& text) {
  tinyxml2::XMLDocument doc;
  EXPECT_EQ(doc.Parse(text.c_str()), tinyxml2::XML_SUCCESS) << text;
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto* e = doc.RootElement()->FirstChildElement(); e; e = e->NextSiblingElement())
    out.emplace_back(e->Name(), e->GetText() ? e->GetText() : "");
  return out;
}

// read_pmml() of `text` (written to a file) fails with FILE:LINE: … containing `fragment`.
void expect_file_error(const std::string& text, int line, const std::string& fragment) {
  const std::string path = test::temp_dir() + "/bad.pmml";
  std::ofstream(path) << text;
  try {
    io::read_pmml(path);
    FAIL() << "accepted: " << fragment;
  } catch (const io::ParseError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(e.message().find(fragment), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind(path + ":" + std::to_string(line) + ":", 0), 0u) << e.what();
  }
}

TEST(PmmlPhysics, ReadIntoTheSpecAndThePatternAtTheirLines) {
  const auto spec = io::parse_pmml(
      with_physics({"<Density>0.08</Density>", "<Gravity>0 -1.5 -9.81</Gravity>", "<FixedActor>2</FixedActor>"}), "x.pmml");
  ASSERT_TRUE(spec.physics.density && spec.physics.gravity && spec.physics.fixed_actor);
  EXPECT_EQ(*spec.physics.density, 0.08);
  EXPECT_EQ(*spec.physics.gravity, geometry::Vec3(0, -1.5, -9.81));
  EXPECT_EQ(*spec.physics.fixed_actor, 2);
  EXPECT_EQ(spec.physics.density_line, 4);
  EXPECT_EQ(spec.physics.gravity_line, 5);
  EXPECT_EQ(spec.physics.fixed_actor_line, 6);
  const geometry::CreasePattern p = geometry::build_or_throw(spec);
  EXPECT_EQ(p.physics().density, 0.08);
  EXPECT_EQ(p.physics().gravity, geometry::Vec3(0, -1.5, -9.81));
  EXPECT_EQ(p.physics().fixed_actor, 2);
  // Anywhere among <PMML>'s children, each on its own.
  std::string late = kPlain;
  late.insert(late.find("</PMML>"), "  <FixedActor>1</FixedActor>\n");
  const auto only_fixed = io::parse_pmml(late, "late.pmml").physics;
  EXPECT_EQ(only_fixed.fixed_actor, 1);
  EXPECT_FALSE(only_fixed.density || only_fixed.gravity);
}

TEST(PmmlPhysics, WrittenBackAfterTheTitleAndRoundTripExactly) {
  const std::string text =
      with_physics({"<FixedActor>2</FixedActor>", "<Gravity>0.1 0 -9.81</Gravity>", "<Density>0.3333333333333333</Density>"});
  const geometry::CreasePattern p = geometry::build_or_throw(io::parse_pmml(text, "x.pmml"));
  const std::string once = io::write_pmml(p);
  const auto children = root_children(once);
  ASSERT_GE(children.size(), 4u);
  EXPECT_EQ(children[0].first, "Title");
  EXPECT_EQ(children[1], (std::pair<std::string, std::string>{"Density", "0.3333333333333333"}));
  EXPECT_EQ(children[2], (std::pair<std::string, std::string>{"Gravity", "0.1 0 -9.81"}));
  EXPECT_EQ(children[3], (std::pair<std::string, std::string>{"FixedActor", "2"}));
  EXPECT_EQ(children[4].first, "Actor");
  const auto back = io::parse_pmml(once, "y.pmml");
  EXPECT_EQ(back.physics.density, 1.0 / 3.0);
  EXPECT_EQ(back.physics.gravity, geometry::Vec3(0.1, 0, -9.81));
  EXPECT_EQ(back.physics.fixed_actor, 2);
  EXPECT_EQ(io::write_pmml(back), once);
}

// Without the extensions nothing new is written: the paper's Table 1, byte for byte as before.
TEST(PmmlPhysics, PlainPmmlWritesAsBefore) {
  const auto spec = io::parse_pmml(kPlain, "plain.pmml");
  EXPECT_FALSE(spec.physics.density || spec.physics.gravity || spec.physics.fixed_actor);
  EXPECT_EQ(io::write_pmml(spec), std::string(kPlain));
  EXPECT_EQ(io::write_pmml(geometry::build_or_throw(spec)), std::string(kPlain));
}

TEST(PmmlPhysics, MalformedValuesAreErrorsAtTheirLines) {
  expect_file_error(with_physics({"<Density>nan</Density>"}), 4, "'nan'");
  expect_file_error(with_physics({"<Density>heavy</Density>"}), 4, "'heavy' is not a number");
  expect_file_error(with_physics({"<Density>1 2</Density>"}), 4, "<Density> must hold one number, found 2");
  expect_file_error(with_physics({"<Gravity>0 0</Gravity>"}), 4, "<Gravity> needs 3 numbers, found 2");
  expect_file_error(with_physics({"<Gravity>0 0 -9.81 1</Gravity>"}), 4, "<Gravity> needs 3 numbers, found 4");
  expect_file_error(with_physics({"<Gravity>0,0,-9.81</Gravity>"}), 4, "'0,0,-9.81' is not a number");
  expect_file_error(with_physics({"<Gravity>0 inf 0</Gravity>"}), 4, "'inf'");
  expect_file_error(with_physics({"<FixedActor>first</FixedActor>"}), 4, "<FixedActor> must be an actor ID");
  expect_file_error(with_physics({"<FixedActor>1.5</FixedActor>"}), 4, "<FixedActor> must be an actor ID");
  expect_file_error(with_physics({"<Density>1</Density>", "<Gravity>0 0 -1</Gravity>", "<Density>2</Density>"}), 6,
                    "more than one <Density>");
  expect_file_error(with_physics({"<FixedActor>1</FixedActor>", "<FixedActor>2</FixedActor>"}), 5, "more than one <FixedActor>");
  expect_file_error(with_physics({"<Gravity a=\"1\">0 0 -1</Gravity>"}), 4, "attribute");
}

TEST(PmmlPhysics, OutOfRangeValuesAreErrorsAtTheirLinesWhenBuilt) {
  expect_file_error(with_physics({"<Density>-1</Density>"}), 4, "density must be positive and finite");
  expect_file_error(with_physics({"<Gravity>0 0 -9.81</Gravity>", "<Density>0</Density>"}), 5,
                    "density must be positive and finite");
  expect_file_error(with_physics({"<FixedActor>7</FixedActor>"}), 4, "fixed actor 7 does not exist");
  // Every problem of the file is listed, each at its line (what `foldkit validate` prints).
  const auto built = geometry::build_pattern(
      io::parse_pmml(with_physics({"<Density>-2</Density>", "<FixedActor>3</FixedActor>"}), "x.pmml"));
  ASSERT_FALSE(built.pattern);
  ASSERT_EQ(built.diagnostics.size(), 2u);
  EXPECT_EQ(built.diagnostics[0].line, 4);
  EXPECT_EQ(built.diagnostics[1].line, 5);
  // A spec built in code is checked as a file is (line 0).
  geometry::PatternSpec spec = io::parse_pmml(kPlain, "plain.pmml");
  spec.physics.gravity = geometry::Vec3(0, std::numeric_limits<double>::quiet_NaN(), 0);
  const auto nan_gravity = geometry::build_pattern(spec);
  ASSERT_FALSE(nan_gravity.pattern);
  EXPECT_NE(nan_gravity.diagnostics[0].message.find("gravity is not finite"), std::string::npos);
}

TEST(PmmlPhysics, WriterRefusesNonFiniteValues) {
  geometry::PatternSpec spec = io::parse_pmml(kPlain, "plain.pmml");
  spec.physics.density = std::numeric_limits<double>::infinity();
  EXPECT_THROW(io::write_pmml(spec), std::invalid_argument);
  spec.physics.density.reset();
  spec.physics.gravity = geometry::Vec3(0, 0, std::numeric_limits<double>::quiet_NaN());
  EXPECT_THROW(io::write_pmml(spec), std::invalid_argument);
}

}  // namespace
