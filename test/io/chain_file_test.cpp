// Planar chain files: points read back, errors located at their line.
#include "foldkit/io/chain_file.hpp"

#include <gtest/gtest.h>

#include <string>

#include "foldkit/io/parse_error.hpp"

namespace {

using foldkit::io::Frame2;
using foldkit::io::parse_chain_points;
using Vec = Eigen::Vector2d;

TEST(ChainFile, ChainFilesParseWithLocatedErrors) {
  const Frame2 p = parse_chain_points("# a chain\n0 0\n\n1 0.5  # trailing comment\n+2 -1e0\n", "c.txt");
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[1], Vec(1, 0.5));
  EXPECT_EQ(p[2], Vec(2, -1));
  auto error = [](const std::string& text) {
    try {
      parse_chain_points(text, "c.txt");
    } catch (const foldkit::io::ParseError& e) {
      return std::string(e.what());
    }
    return std::string("parsed");
  };
  EXPECT_EQ(error("0 0\n1 x\n").rfind("c.txt:2:", 0), 0u);
  EXPECT_EQ(error("0 0\n1 2 3\n").rfind("c.txt:2: expected two numbers", 0), 0u);
  EXPECT_EQ(error("0 0\n\n5\n").rfind("c.txt:3:", 0), 0u);
  EXPECT_EQ(error("# nothing\n").rfind("c.txt:1: no points", 0), 0u);
  EXPECT_EQ(error("0 nan\n").rfind("c.txt:1:", 0), 0u);
}

}  // namespace
