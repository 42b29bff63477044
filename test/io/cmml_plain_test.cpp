// The <Fold> elements of a large CMML read without XML (io::detail::read_plain_folds), and the
// plan's file written while its replay runs (io::PendingCmmlFile). Oracles: the XML reading of the
// same folds (parse_cmml, tinyxml2), and write_cmml's text.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "random_corruption.hpp"

#include "fold_sequence_equal.hpp"

#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/parse_error.hpp"

namespace {

using namespace foldkit;

// One fold as write_cmml writes it, with its four texts as given.
std::string fold_text(const std::string& event, const std::string& id, const std::string& angle, const std::string& speed) {
  return "  <Fold>\n    <EventNumber>" + event + "</EventNumber>\n    <ID>" + id + "</ID>\n    <FoldAngle>" + angle +
         "</FoldAngle>\n    <Velocity>" + speed + "</Velocity>\n  </Fold>\n";
}

// The XML reading of `body` as the content of a <CMML> starting on line 1, or nothing when it
// refuses it.
std::optional<geometry::FoldSequence> by_xml(const std::string& body) {
  try {
    return io::parse_cmml("<CMML>" + body + "</CMML>", "t.cmml");
  } catch (const io::ParseError&) {
    return std::nullopt;
  }
}

// The plain reading of `body`, grouped as parse_cmml groups it, or nothing when it declines.
std::optional<geometry::FoldSequence> by_plain(const std::string& body) {
  std::vector<std::pair<int, geometry::FoldCommand>> folds;
  if (!io::detail::read_plain_folds(body, 1, folds)) {
    EXPECT_TRUE(folds.empty()) << "a declined slice must leave the folds as they were";
    return std::nullopt;
  }
  return geometry::make_sequence("", std::move(folds));
}

// Whenever the plain reading reads, the XML reading reads the same (lines included); returns
// whether the plain reading read.
bool plain_agrees(const std::string& body) {
  const auto plain = by_plain(body);
  if (!plain) return false;
  const auto xml = by_xml(body);
  EXPECT_TRUE(xml.has_value()) << "read without XML what the XML reading refuses:\n" << body;
  if (xml) test::expect_same(*plain, *xml);
  return true;
}

TEST(CmmlPlain, ReadsWhatWriteCmmlWritesAsXmlDoes) {
  geometry::FoldSequence s;
  for (int e = 0; e < 7; ++e) {
    geometry::FoldEvent event{e * 3, {}};
    for (int j = 1; j <= 25; ++j) event.folds.push_back({j, 0.37 * std::sin(e + 0.3 * j), 0.1 + 0.01 * j});
    s.events.push_back(event);
  }
  const std::string text = io::write_cmml(s);
  const std::size_t begin = text.find("</Title>") + 8, end = text.rfind("</CMML>");
  const std::string body = text.substr(begin, end - begin);
  EXPECT_TRUE(plain_agrees(body));
  // Starting on another line, as later slices do.
  std::vector<std::pair<int, geometry::FoldCommand>> folds;
  ASSERT_TRUE(io::detail::read_plain_folds(body, 41, folds));
  EXPECT_EQ(folds.front().second.line, 42);  // the body starts with the title line's line feed
}

// Numbers at and beyond every check of the XML reading: the plain reading declines or agrees.
TEST(CmmlPlain, NumbersAtTheEdgesOfTheChecksDeclineOrAgree) {
  const std::vector<std::string> numbers = {"0",     "-0",    "+5",    "++5",  "+-5",  "5.",      ".5",       "-.5",  "1e2",
                                            "1E2",   "1e999", "-1e999", "1e-400", "5e-324", "180",   "180.0000000001", "-180",
                                            "-180.0000000001", "2147483647", "2147483648", "-1", "-2147483648", "0x10", "inf", "nan",
                                            "1-2",   "e5",    "",      "3.5e",  "7",    "2.5",     "-3"};
  int read = 0, declined = 0;
  for (const auto& n : numbers)
    for (int field = 0; field < 4; ++field) {
      std::string f[4] = {"2", "11", "45.5", "57.29577951308232"};
      f[field] = n;
      const std::string body = fold_text(f[0], f[1], f[2], f[3]);
      SCOPED_TRACE("field " + std::to_string(field) + ": '" + n + "'");
      if (plain_agrees(body)) ++read;
      else ++declined;
      // Whatever the plain reading declines is left to the XML reading, right or wrong.
    }
  EXPECT_GT(read, 20);
  EXPECT_GT(declined, 20);
}

// Anything but foldkit's own shape declines: the XML reading decides it.
TEST(CmmlPlain, DeclinesAnyOtherShape) {
  const std::string good = fold_text("1", "2", "30", "10");
  for (const std::string& body :
       {good + "<Title>t</Title>", good + "<!-- c -->", "<Fold >" + good.substr(good.find("\n")), good + "x",
        std::string("  <Fold>\n    <ID>2</ID>\n    <EventNumber>1</EventNumber>\n    <FoldAngle>30</FoldAngle>\n    "
                    "<Velocity>10</Velocity>\n  </Fold>\n"),
        std::string("  <Fold>\r\n    <EventNumber>1</EventNumber>\n    <ID>2</ID>\n    <FoldAngle>30</FoldAngle>\n    "
                    "<Velocity>10</Velocity>\n  </Fold>\n"),
        std::string("  <Fold>\n    <EventNumber> 1</EventNumber>\n    <ID>2</ID>\n    <FoldAngle>30</FoldAngle>\n    "
                    "<Velocity>10</Velocity>\n  </Fold>\n"),
        std::string("  <Fold>\n    <EventNumber>1</EventNumber>\n    <ID>&#50;</ID>\n    <FoldAngle>30</FoldAngle>\n    "
                    "<Velocity>10</Velocity>\n  </Fold>\n"),
        good.substr(0, good.size() - 3)}) {
    SCOPED_TRACE(body);
    std::vector<std::pair<int, geometry::FoldCommand>> folds = {{0, {}}};
    EXPECT_FALSE(io::detail::read_plain_folds(body, 1, folds));
    EXPECT_EQ(folds.size(), 1u);
  }
  // White space alone (the end of a slice) reads as no folds.
  std::vector<std::pair<int, geometry::FoldCommand>> none;
  EXPECT_TRUE(io::detail::read_plain_folds(" \n\t\n", 3, none));
  EXPECT_TRUE(none.empty());
}

// Random corruptions of a plain body: never read what the XML reading refuses, and read the rest alike.
TEST(CmmlPlain, RandomCorruptionsDeclineOrAgree) {
  std::string base;
  for (int k = 0; k < 6; ++k) base += fold_text(std::to_string(k / 2), std::to_string(k + 1), std::to_string(-20.5 * k), "3.25");
  const std::vector<std::string> inserts = {"<", ">", "&", "</Fold>", "<Fold>", "\n", " ", "\t", "-", "+", "9", ".", "e",
                                            "<ID>2</ID>", "</ID>", "0", "\r"};
  std::mt19937 rng(5);
  int read = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const std::string t = foldkit::test::corrupted(base, inserts, rng);
    SCOPED_TRACE("trial " + std::to_string(trial));
    read += plain_agrees(t);
  }
  EXPECT_GT(read, 50);  // both outcomes were exercised (117 read of 3000)
  EXPECT_LT(read, 2900);
}

std::string file_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Committed, the file holds write_cmml's bytes; dropped uncommitted, nothing is left beside it and
// an old file is untouched.
TEST(CmmlPlain, PendingFileIsWriteCmmlOnceCommittedAndNothingOtherwise) {
  const auto dir = std::filesystem::temp_directory_path() / ("foldkit-pending-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  geometry::FoldSequence s{"pending", {{1, {{3, 0.25, 1.0}, {4, -0.5, 0.5}}}, {2, {{3, 1.0, 1.0}}}}};
  const auto path = dir / "p.cmml";
  io::write_file_atomic(path.string(), "old");
  {
    io::PendingCmmlFile pending(path.string(), s);
    EXPECT_EQ(file_text(path), "old");
  }
  EXPECT_EQ(file_text(path), "old");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 1);
  {
    io::PendingCmmlFile pending(path.string(), s);
    pending.commit();
  }
  EXPECT_EQ(file_text(path), io::write_cmml(s));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 1);
  std::filesystem::remove_all(dir);
}

}  // namespace
