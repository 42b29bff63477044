// Large CMML files are read a slice of <Fold> elements at a time (io::detail::parse_cmml_sliced).
// Oracle: reading the same text whole, the way every CMML was read before. Whatever the text —
// foldkit's own output, the test data, and thousands of random corruptions of it — the sliced
// reading either declines (and the whole reading decides) or gives exactly the whole reading's
// sequence, file lines included; it never accepts what the whole reading refuses.
#include <algorithm>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "fold_sequence_equal.hpp"

#include "foldkit/io/cmml.hpp"
#include "foldkit/io/parse_error.hpp"

namespace {

using namespace foldkit;

// A sequence of `events` events, each folding `joints` joints, as foldkit writes it.
std::string written(int events, int joints, const std::string& title = "sliced") {
  geometry::FoldSequence s;
  s.title = title;
  for (int e = 0; e < events; ++e) {
    geometry::FoldEvent event{e, {}};
    for (int j = 1; j <= joints; ++j) event.folds.push_back({j, 0.01 * (e + 1) * (j % 2 ? 1 : -1), 0.5 + 0.001 * j});
    s.events.push_back(event);
  }
  return io::write_cmml(s);
}

using foldkit::test::expect_same;

// The whole reading, or its error.
std::optional<geometry::FoldSequence> whole(const std::string& text) {
  try {
    // Below parse_cmml's slicing threshold for every text here but the large ones, which are
    // compared with the sliced reading separately.
    return io::parse_cmml(text, "t.cmml");
  } catch (const io::ParseError&) {
    return std::nullopt;
  }
}

// Sliced and whole readings agree on `text` for every slice size; returns whether the sliced
// reading read it (did not decline) at every size.
bool agree(const std::string& text) {
  const auto reference = whole(text);
  bool read = true;
  for (std::size_t slice : {std::size_t(1), std::size_t(37), std::size_t(400), std::size_t(1) << 20}) {
    const auto sliced = io::detail::parse_cmml_sliced(text, "t.cmml", slice);
    if (!sliced) {
      read = false;
      continue;
    }
    EXPECT_TRUE(reference.has_value()) << "the sliced reading (slices of " << slice << " bytes) accepted a text the whole reading refuses:\n"
                                       << text.substr(0, 400);
    if (reference) expect_same(*sliced, *reference);
  }
  return read;
}

TEST(CmmlSliced, FoldkitsOwnOutputReadsAsWhole) {
  for (const auto& [events, joints] : std::vector<std::pair<int, int>>{{1, 1}, {3, 7}, {20, 40}, {99, 120}}) {
    SCOPED_TRACE(std::to_string(events) + " events × " + std::to_string(joints) + " joints");
    EXPECT_TRUE(agree(written(events, joints)));
  }
  // Windows line ends: lines still counted as the whole reading counts them.
  std::string crlf;
  for (char c : written(20, 40)) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  EXPECT_TRUE(agree(crlf));
  EXPECT_TRUE(agree("<CMML></CMML>"));
  EXPECT_TRUE(agree("\xEF\xBB\xBF<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\n<CMML>\n<Title>t</Title>\n</CMML>\n"));
  // Titles anywhere, and the second one refused across slices as in one piece.
  const std::string folds = written(4, 30);
  std::string late = folds;
  late.insert(late.rfind("</CMML>"), "<Title>late</Title>\n");
  EXPECT_FALSE(agree(late));  // declined: the whole reading refuses the second title
  std::string only_late = folds;
  only_late.erase(only_late.find("  <Title>"), only_late.find("</Title>\n") + 9 - only_late.find("  <Title>"));
  only_late.insert(only_late.rfind("</CMML>"), "<Title>late</Title>\n");
  EXPECT_TRUE(agree(only_late));
}

TEST(CmmlSliced, DeclinesWhatItDoesNotReadAndTheWholeReadingDecides) {
  const std::string text = written(5, 10);
  for (const char* insert : {"<!-- </Fold> -->", "<![CDATA[x]]>", "<?pi x?>", "<CMML>"}) {
    std::string t = text;
    t.insert(t.find("<Fold>"), insert);
    EXPECT_FALSE(io::detail::parse_cmml_sliced(t, "t.cmml", 64).has_value()) << insert;
  }
  EXPECT_FALSE(io::detail::parse_cmml_sliced("<!DOCTYPE CMML>" + text.substr(text.find("<CMML>")), "t.cmml", 64).has_value());
  EXPECT_FALSE(io::detail::parse_cmml_sliced(text + "<x/>", "t.cmml", 64).has_value());
  EXPECT_FALSE(io::detail::parse_cmml_sliced("<PMML/>", "t.cmml", 64).has_value());
}

// Random corruptions of foldkit's output: bytes dropped, markup and text inserted. The sliced
// reading must never accept one the whole reading refuses, and must read the good ones alike.
TEST(CmmlSliced, RandomCorruptionsReadAsWhole) {
  const std::string base = written(6, 9);
  const std::vector<std::string> inserts = {"<", ">", "&", "&amp;", "&#0;", "</Fold>", "<Fold>", "<Title>x</Title>", "\n", " ", "\r", "\r\n", "&#10;",
                                            "<ID>2</ID>", "<X/>", " a=\"1\"", "\xFF", "<Velocity>1</Velocity>", "</CMML>", "-",
                                            "<EventNumber>1</EventNumber>", "9", "</Velocity>"};
  std::mt19937 rng(11);
  int read = 0, refused = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::string t = base;
    const int edits = 1 + static_cast<int>(rng() % 3);
    for (int k = 0; k < edits; ++k) {
      const std::size_t at = rng() % t.size();
      if (rng() % 3 == 0) t.erase(at, 1 + rng() % 6);
      else t.insert(at, inserts[rng() % inserts.size()]);
    }
    SCOPED_TRACE("trial " + std::to_string(trial));
    if (agree(t)) ++read;
    if (!whole(t)) ++refused;
  }
  // Both kinds occur, so both halves of the property were exercised.
  EXPECT_GT(read, 100);
  EXPECT_GT(refused, 1000);
}

TEST(CmmlSliced, TestDataReadsAsWhole) {
  for (const char* name : {"good/cube-fold.cmml", "bad/empty.cmml", "bad/fractional-event.cmml", "bad/nan-angle.cmml",
                           "bad/negative-velocity.cmml"}) {
    SCOPED_TRACE(name);
    std::ifstream in(std::string(FOLDKIT_TEST_DATA) + "/" + name, std::ios::binary);
    ASSERT_TRUE(in) << name;
    std::ostringstream text;
    text << in.rdbuf();
    agree(text.str());
  }
}

// parse_cmml itself slices files from 4 MB on: a 9 MB sequence reads as it did whole, and an error
// deep inside is reported by the whole reading at its line.
TEST(CmmlSliced, LargeFilesReadAsWholeAndErrorsKeepTheirLines) {
  const std::string text = written(200, 300);  // 60,000 folds
  ASSERT_GT(text.size(), std::size_t(8) << 20);
  const auto sliced = io::parse_cmml(text, "big.cmml");
  // One slice of the whole body is one XML document of the whole file (the whole reading).
  const auto in_one = io::detail::parse_cmml_sliced(text, "big.cmml", text.size());
  const auto in_small = io::detail::parse_cmml_sliced(text, "big.cmml", 4096);
  ASSERT_TRUE(in_one.has_value() && in_small.has_value());
  expect_same(sliced, *in_one);
  expect_same(*in_small, *in_one);
  // Every fold's line is the line of its <Fold> in the file.
  const auto& last = sliced.events.back().folds.back();
  const std::size_t at = text.rfind("<Fold>");
  EXPECT_EQ(last.line, 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n')));
  std::string bad = text;
  const std::size_t angle = bad.rfind("<FoldAngle>");
  bad.replace(angle, bad.find("</FoldAngle>", angle) - angle, "<FoldAngle>nan");
  try {
    io::parse_cmml(bad, "big.cmml");
    FAIL() << "a NaN angle was accepted";
  } catch (const io::ParseError& e) {
    EXPECT_EQ(e.line(), 1 + static_cast<int>(std::count(bad.begin(), bad.begin() + static_cast<std::ptrdiff_t>(angle), '\n')));
    EXPECT_NE(e.message().find("not a finite number"), std::string::npos) << e.what();
  }
}

}  // namespace
