// The load-case reader: defaults, both stiffness forms, errors at their lines.
#include <gtest/gtest.h>

#include "foldkit/analysis/load_case.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/io/parse_error.hpp"

namespace {

using namespace foldkit;

TEST(LoadCase, DefaultsAndBothStiffnessForms) {
  const auto lc = analysis::parse_load_case(
      "<LoadCase>\n<Title> t </Title>\n<Connection><Kind>face</Kind><Stiffness>1 2 3 4 5 6</Stiffness></Connection>\n"
      "<Connection><Kind>edge</Kind><Stiffness>2 1 0 0 0 0 1 2 0 0 0 0 0 0 1 0 0 0 0 0 0 1 0 0 0 0 0 0 1 0 0 0 0 0 0 1</Stiffness></Connection>\n"
      "<Fixed>3 4</Fixed><Fixed>5</Fixed>\n<Load><ActorID>2</ActorID><Force>0 0 -1</Force></Load>\n"
      "<Load><ActorID>1</ActorID><Force>1 0 0</Force><Point>1 2 3</Point></Load></LoadCase>",
      "x.loadcase");
  EXPECT_EQ(lc.title, "t");
  EXPECT_EQ(lc.stiffness[0], analysis::default_stiffness(analysis::ConnectionKind::Hinged));
  EXPECT_EQ(lc.stiffness[1](5, 5), 6.0);
  EXPECT_EQ(lc.stiffness[2](0, 1), 1.0);
  EXPECT_EQ(lc.fixed, (std::vector<int>{3, 4, 5}));
  ASSERT_EQ(lc.loads.size(), 2u);
  EXPECT_FALSE(lc.loads[0].point.has_value());
  EXPECT_EQ(*lc.loads[1].point, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(lc.loads[1].line, 7);
}

TEST(LoadCase, ErrorsCarryFileAndLine) {
  const std::vector<std::pair<std::string, int>> bad = {
      {"<LoadCase>\n<Fixed>1</Fixed>\n<Oops/></LoadCase>", 3},
      {"<LoadCase>\n<Fixed>1</Fixed>\n<Connection><Kind>face</Kind><Stiffness>-1 1 1 1 1 1</Stiffness></Connection></LoadCase>", 3},
      {"<LoadCase>\n<Fixed>1</Fixed>\n<Connection><Kind>face</Kind><Stiffness>1 1 1 1 1 1</Stiffness></Connection>\n"
       "<Connection><Kind>face</Kind><Stiffness>1 1 1 1 1 1</Stiffness></Connection></LoadCase>", 4},
      {"<LoadCase>\n<Fixed>1 1</Fixed></LoadCase>", 2},
      {"<PMML/>", 1},
      {"<LoadCase>\n<Fixed>1</Fixed>\n<Load><Force>0 0 1</Force></Load></LoadCase>", 3},
  };
  for (const auto& [text, line] : bad) {
    try {
      analysis::parse_load_case(text, "bad.loadcase");
      ADD_FAILURE() << text;
    } catch (const io::ParseError& e) {
      EXPECT_EQ(e.line(), line) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("bad.loadcase:" + std::to_string(line) + ": ", 0), 0u) << e.what();
    }
  }
}

TEST(LoadCase, ProblemResolvesActorIds) {
  const auto pattern = geometry::build_or_throw(geometry::generators::strip(3));
  const auto s = analysis::build_structure(pattern, geometry::FoldState::flat(pattern));
  const auto lc = analysis::parse_load_case("<LoadCase><Fixed>1</Fixed>\n<Load><ActorID>9</ActorID><Force>0 0 1</Force></Load></LoadCase>", "l");
  EXPECT_THROW(analysis::make_problem(s, lc, "l"), io::ParseError);
  const auto ok = analysis::make_problem(
      s, analysis::parse_load_case("<LoadCase><Fixed>1</Fixed><Load><ActorID>3</ActorID><Force>0 0 1</Force></Load></LoadCase>", "l"), "l");
  EXPECT_TRUE(ok.fixed[0]);
  EXPECT_EQ(ok.loads[0].module, 2);
  EXPECT_EQ(ok.loads[0].point, s.modules[2].centroid);
}

}  // namespace
