#include <regex>

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include "foldkit/io/svg.hpp"
#include "spec_helpers.hpp"

namespace {

using namespace foldkit;

int count(const std::string& text, const std::string& needle) {
  int n = 0;
  for (auto pos = text.find(needle); pos != std::string::npos; pos = text.find(needle, pos + 1)) ++n;
  return n;
}

TEST(Svg, DrawsMountainValleyAndBoundaryDistinctly) {
  geometry::PatternSpec s = test::two_by_two();
  s.joints[0].assignment = geometry::Assignment::Mountain;
  s.joints[1].assignment = geometry::Assignment::Valley;
  const geometry::CreasePattern p = geometry::build_or_throw(s);
  io::SvgOptions o;
  o.joint_ids = true;
  const std::string svg = io::write_svg(p, o);
  tinyxml2::XMLDocument doc;
  ASSERT_EQ(doc.Parse(svg.c_str()), tinyxml2::XML_SUCCESS) << svg;
  EXPECT_EQ(count(svg, "stroke=\"#ff0000\""), 1);
  EXPECT_EQ(count(svg, "stroke=\"#0000ff\""), 1);
  EXPECT_EQ(count(svg, "data-joint="), 4);
  EXPECT_EQ(count(svg, "<text "), 4);
  EXPECT_EQ(count(svg, "<polygon "), 8);
  // Boundary group holds the eight outer edges.
  const auto* boundary = doc.RootElement()->FirstChildElement("g")->NextSiblingElement("g");
  ASSERT_STREQ(boundary->Attribute("id"), "boundary");
  int lines = 0;
  for (auto* l = boundary->FirstChildElement("line"); l; l = l->NextSiblingElement("line")) ++lines;
  EXPECT_EQ(lines, 8);
}

TEST(Svg, StateSignOverridesAssignment) {
  geometry::PatternSpec s = test::two_by_two();
  s.joints[0].assignment = geometry::Assignment::Mountain;
  const geometry::CreasePattern p = geometry::build_or_throw(s);
  geometry::FoldState state = geometry::FoldState::flat(p);
  state.angles[0] = -1.0;  // valley
  state.angles[1] = 0.5;   // mountain
  io::SvgOptions o;
  o.state = &state;
  const std::string svg = io::write_svg(p, o);
  EXPECT_NE(svg.find("data-joint=\"1\" stroke=\"#0000ff\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("data-joint=\"2\" stroke=\"#ff0000\""), std::string::npos) << svg;
}

TEST(Svg, YAxisPointsUp) {
  const geometry::CreasePattern p = geometry::build_or_throw(test::two_by_two());
  const std::string svg = io::write_svg(p);
  // Joint 3 runs from (1,1) up to (1,2): in SVG its second end has the smaller y.
  std::smatch m;
  ASSERT_TRUE(std::regex_search(svg, m, std::regex("data-joint=\"3\"[^>]*y1=\"([0-9.]+)\"[^>]*y2=\"([0-9.]+)\"")));
  EXPECT_GT(std::stod(m[1]), std::stod(m[2]));
}

}  // namespace

namespace {

TEST(Svg, ScalesAnyPatternToItsCanvas) {
  for (double f : {1e-90, 1.0, 1e90}) {
    foldkit::geometry::PatternSpec s = foldkit::test::two_by_two();
    for (auto& a : s.actors)
      for (auto& t : a.triangles)
        for (auto& c : t.corners) c *= f;
    for (auto& j : s.joints)
      for (auto& c : j.coords) c *= f;
    const std::string svg = foldkit::io::write_svg(foldkit::geometry::build_or_throw(s));
    EXPECT_NE(svg.find("width=\"840\" height=\"840\" viewBox=\"0 0 840 840\""), std::string::npos) << f;
  }
}

}  // namespace
