// Pixel and voxel shape files: located errors, and random bytes either parse or throw.
#include "foldkit/io/shape_file.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <string>

#include "foldkit/io/parse_error.hpp"

namespace {

using foldkit::geometry::PixelShape;
using foldkit::geometry::VoxelShape;
using foldkit::io::parse_pbm;
using foldkit::io::parse_pixel_grid;
using foldkit::io::parse_voxel_layers;
using foldkit::io::ParseError;

int parse_line(const std::function<void()>& f) {
  try {
    f();
  } catch (const ParseError& e) {
    return e.line();
  }
  return -1;
}

TEST(ShapeFile, AsciiGrid) {
  const PixelShape s = parse_pixel_grid("#.#\n###\r\n# .\n\n", "g.txt");
  EXPECT_EQ(s.width, 3);
  EXPECT_EQ(s.height, 3);
  EXPECT_EQ(s.count(), 6u);
  EXPECT_TRUE(s.filled(0, 2));
  EXPECT_FALSE(s.filled(1, 2));
  EXPECT_EQ(parse_line([] { parse_pixel_grid("##\n###\n", "g.txt"); }), 2);
  EXPECT_EQ(parse_line([] { parse_pixel_grid("##\n#x\n", "g.txt"); }), 2);
  EXPECT_EQ(parse_line([] { parse_pixel_grid("##\n\n##\n", "g.txt"); }), 2);
  EXPECT_EQ(parse_line([] { parse_pixel_grid("", "g.txt"); }), 1);
  EXPECT_EQ(parse_line([] { parse_pixel_grid("..\n..\n", "g.txt"); }), 2);
  try {
    parse_pixel_grid("##\n###\n", "g.txt");
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("g.txt:2: ragged"), std::string::npos) << e.what();
  }
}

TEST(ShapeFile, Pbm) {
  const PixelShape a = parse_pbm("P1\n# a comment\n3 2\n1 0 1\n111\n", "a.pbm");
  EXPECT_EQ(a.width, 3);
  EXPECT_EQ(a.height, 2);
  EXPECT_EQ(a.count(), 5u);
  EXPECT_FALSE(a.filled(1, 0));
  std::string raw = "P4\n10 2\n";
  raw += static_cast<char>(0xC0);
  raw += static_cast<char>(0x40);  // row 0: pixels 0, 1 and 9
  raw += static_cast<char>(0xFF);
  raw += static_cast<char>(0xC0);  // row 1: all ten
  const PixelShape b = parse_pbm(raw, "b.pbm");
  EXPECT_EQ(b.width, 10);
  EXPECT_EQ(b.count(), 13u);
  EXPECT_TRUE(b.filled(9, 0));
  EXPECT_FALSE(b.filled(8, 0));
  EXPECT_EQ(parse_line([] { parse_pbm("P1\n2 2\n1 1\n1 2\n", "c.pbm"); }), 4);
  EXPECT_EQ(parse_line([] { parse_pbm("P1\n2 2\n1 1\n1\n", "c.pbm"); }), 5);
  EXPECT_EQ(parse_line([] { parse_pbm("P2\n2 2\n", "c.pbm"); }), 1);
  EXPECT_EQ(parse_line([] { parse_pbm("P1\n\n2 x\n", "c.pbm"); }), 3);
  EXPECT_EQ(parse_line([] { parse_pbm("P4\n8 2\n\x01", "c.pbm"); }), 3);
  EXPECT_EQ(parse_line([] { parse_pbm("P1 99999 99999\n", "c.pbm"); }), 1);
  EXPECT_EQ(parse_line([] { parse_pbm("P1 2 1 0 0\n", "c.pbm"); }), 1);
}

TEST(ShapeFile, RandomBytesParseOrThrowParseError) {
  std::mt19937 rng(3);
  const std::string alphabet = "#. \n\r01P14x\t";
  for (int trial = 0; trial < 600; ++trial) {
    std::string text = trial % 3 == 0 ? "P1\n" : trial % 3 == 1 ? "P4\n3 2\n" : "";
    const std::size_t n = rng() % 40;
    for (std::size_t i = 0; i < n; ++i)
      text += trial % 2 == 0 ? alphabet[rng() % alphabet.size()] : static_cast<char>(rng() % 256);
    for (int kind = 0; kind < 3; ++kind) {
      try {
        const std::size_t filled = kind == 0   ? parse_pixel_grid(text, "r.txt").count()
                                   : kind == 1 ? parse_pbm(text, "r.pbm").count()
                                               : parse_voxel_layers(text, "r.vox").count();
        EXPECT_GT(filled, 0u);
      } catch (const ParseError& e) {
        EXPECT_GE(e.line(), 1) << e.what();
      }
    }
  }
}

TEST(ShapeFile, VoxelLayers) {
  const VoxelShape v = parse_voxel_layers("##\n#.\n\n.#\n..\n", "v.vox");
  EXPECT_EQ(v.nx, 2);
  EXPECT_EQ(v.ny, 2);
  EXPECT_EQ(v.nz, 2);
  EXPECT_EQ(v.count(), 4u);
  EXPECT_TRUE(v.filled(1, 0, 1));
  EXPECT_EQ(parse_line([] { parse_voxel_layers("##\n\n###\n", "v.vox"); }), 3);
  EXPECT_EQ(parse_line([] { parse_voxel_layers("VOX \x96", "v.vox"); }), 1);
}

}  // namespace
