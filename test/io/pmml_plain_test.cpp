// A PMML read without XML (io::detail::read_plain_pmml, what parse_pmml() tries first). Oracle:
// the XML reading of the same text (io::detail::parse_pmml_xml: tinyxml2 and XmlInput), which
// shares only the number parsers with it. Whatever the plain reading reads, the XML reading must
// read identically, lines included; whatever the XML reading refuses, the plain one must decline.
#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "random_corruption.hpp"

#include "foldkit/geometry/generators.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/io/pmml.hpp"

namespace {

using namespace foldkit;
namespace gen = geometry::generators;

// Every field of two specs, doubles bit for bit (both come from the same text).
void expect_same(const geometry::PatternSpec& a, const geometry::PatternSpec& b) {
  const auto same_double = [](double x, double y) { return std::signbit(x) == std::signbit(y) && x == y; };
  EXPECT_EQ(a.title, b.title);
  ASSERT_EQ(a.actors.size(), b.actors.size());
  for (std::size_t i = 0; i < a.actors.size(); ++i) {
    const auto &x = a.actors[i], &y = b.actors[i];
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.line, y.line) << "actor " << x.id;
    ASSERT_EQ(x.triangles.size(), y.triangles.size());
    for (std::size_t t = 0; t < x.triangles.size(); ++t) {
      EXPECT_EQ(x.triangles[t].line, y.triangles[t].line);
      for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 2; ++c) EXPECT_TRUE(same_double(x.triangles[t].corners[k][c], y.triangles[t].corners[k][c]));
    }
  }
  ASSERT_EQ(a.joints.size(), b.joints.size());
  for (std::size_t j = 0; j < a.joints.size(); ++j) {
    const auto &x = a.joints[j], &y = b.joints[j];
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.line, y.line) << "joint " << x.id;
    for (int k = 0; k < 2; ++k)
      for (int c = 0; c < 2; ++c) EXPECT_TRUE(same_double(x.coords[k][c], y.coords[k][c]));
    EXPECT_EQ(x.actor_ids, y.actor_ids);
    EXPECT_TRUE(same_double(x.spring, y.spring) && same_double(x.damping, y.damping));
    EXPECT_EQ(x.assignment, y.assignment);
    ASSERT_EQ(x.max_torque.has_value(), y.max_torque.has_value());
    if (x.max_torque) {
      EXPECT_TRUE(same_double(*x.max_torque, *y.max_torque));
    }
  }
  const auto &p = a.physics, &q = b.physics;
  EXPECT_EQ(p.density, q.density);
  EXPECT_EQ(p.gravity.has_value(), q.gravity.has_value());
  if (p.gravity && q.gravity) {
    EXPECT_EQ(*p.gravity, *q.gravity);
  }
  EXPECT_EQ(p.fixed_actor, q.fixed_actor);
  EXPECT_EQ(std::vector<int>({p.density_line, p.gravity_line, p.fixed_actor_line}),
            std::vector<int>({q.density_line, q.gravity_line, q.fixed_actor_line}));
}

std::optional<geometry::PatternSpec> by_xml(const std::string& text) {
  try {
    return io::detail::parse_pmml_xml(text, "t.pmml");
  } catch (const io::ParseError&) {
    return std::nullopt;
  }
}

// Whenever the plain reading reads, the XML reading reads the same; returns whether it read.
bool plain_agrees(const std::string& text) {
  const auto plain = io::detail::read_plain_pmml(text);
  if (!plain) return false;
  const auto xml = by_xml(text);
  EXPECT_TRUE(xml.has_value()) << "read without XML what the XML reading refuses:\n" << text;
  if (xml) expect_same(*plain, *xml);
  return true;
}

// A two-panel strip with every extension: physics, an assignment and a joint's max torque.
geometry::PatternSpec extended_strip() {
  geometry::PatternSpec s = gen::strip(3);
  s.title = "  strip\twith  extensions ";
  s.physics.density = 0.08;
  s.physics.gravity = geometry::Vec3(9.81, 0.0, -0.5);
  s.physics.fixed_actor = s.actors.back().id;
  s.joints.front().assignment = geometry::Assignment::Valley;
  s.joints.back().max_torque = 2.5;
  return s;
}

TEST(PmmlPlain, ReadsWhatWritePmmlWritesAsXmlDoes) {
  const std::vector<geometry::PatternSpec> specs = {
      gen::single_vertex({0.5, 1.2, 2.0, 2 * M_PI - 3.7}), gen::miura(5, 6, 1.0, 1.3, 1.1), gen::waterbomb(3, 4),
      gen::boat(), gen::cube_sheet(3, 2.0), gen::circular_lattice(3, 7, 0.4), extended_strip(), gen::miura(40, 40)};
  for (const auto& spec : specs) {
    SCOPED_TRACE(spec.title);
    const std::string text = io::write_pmml(spec);
    EXPECT_TRUE(plain_agrees(text));
    // parse_pmml takes the plain reading for these, and it gives the file's lines.
    const geometry::PatternSpec read = io::parse_pmml(text, "t.pmml");
    EXPECT_EQ(read.actors.front().line, text.find("<Density>") == std::string::npos ? 4 : 7);
  }
  // Without the declaration, and with the physics elements after the joints, too.
  std::string text = io::write_pmml(extended_strip());
  text.erase(0, text.find("<PMML>"));
  EXPECT_TRUE(plain_agrees(text));
  const std::size_t d = text.find("  <Density>"), end = text.find("\n", text.find("<FixedActor>")) + 1;
  const std::string physics = text.substr(d, end - d);
  text.erase(d, end - d);
  text.insert(text.find("</PMML>"), physics);
  EXPECT_TRUE(plain_agrees(text));
}

// Numbers at and beyond the XML reading's checks, in every numeric field: declined or alike.
TEST(PmmlPlain, NumbersAtTheEdgesOfTheChecksDeclineOrAgree) {
  const std::string base = io::write_pmml(extended_strip());
  const std::vector<std::string> fields = {"<ID>", "<Triangle>", "<Coords>", "<ActorIDs>", "<SpringConst>", "<DampConst>",
                                           "<MaxTorque>", "<Density>", "<Gravity>", "<FixedActor>"};
  const std::vector<std::string> numbers = {"0", "-0", "+5", "++5", "+-5", "5.", ".5", "1e2", "1e999", "-1e999", "1e-400",
                                            "2147483647", "2147483648", "-2147483648", "0x10", "1-2", "e5", "", "3.5e",
                                            "1 2", "1  2\t3", "1 2 3 4 5 6", "1 2 3 4", "7 8 9", "-3"};
  int read = 0, declined = 0;
  for (const auto& field : fields)
    for (const auto& n : numbers) {
      std::string t = base;
      const std::size_t at = t.find(field) + field.size();
      t.replace(at, t.find('<', at) - at, n);
      SCOPED_TRACE(field + " '" + n + "'");
      if (plain_agrees(t)) ++read;
      else ++declined;
    }
  EXPECT_GT(read, 30);
  EXPECT_GT(declined, 100);
}

// Anything but foldkit's own shape declines, and the XML reading decides it.
TEST(PmmlPlain, DeclinesAnyOtherShape) {
  const std::string good = io::write_pmml(extended_strip());
  ASSERT_TRUE(io::detail::read_plain_pmml(good));
  const auto edit = [&](const std::string& from, const std::string& to) {
    std::string t = good;
    const std::size_t at = t.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return t.replace(at, from.size(), to);
  };
  const std::vector<std::string> others = {
      edit("<PMML>", "<PMML version=\"1\">"), edit("<Actor>", "<!-- c --><Actor>"), edit("\n", "\r\n"),
      "\xEF\xBB\xBF" + good, edit("strip", "str&amp;ip"), edit("strip", "str\xC3\xA9ip"), edit("<ID>", "<ID> "),
      edit("<Title>", "<Title>\n"), edit("</PMML>", "</PMML><!-- after -->"), edit("<Triangle>", "<Triangle >"),
      edit("UTF-8", "ISO-8859-1"), edit("<Title>", "<Title>a<b/>"), good.substr(0, good.size() - 3),
      edit("</Title>", "</Title>\n  <Title>again</Title>"), edit("<Density>", "<Density>1</Density><Density>"),
      edit("<Assignment>V</Assignment>", "<Assignment>X</Assignment>"), edit("<ActorIDs>", "<ActorIDs>7 "),
      edit("<SpringConst>", "<Spring>"), edit("<Actor>\n    <ID>1</ID>", "<Actor><Triangle>0 0 1 0 0 1</Triangle><ID>1</ID>"),
      std::string("<PMML>\n  <Title>no actor</Title>\n</PMML>\n")};
  for (const std::string& t : others) {
    SCOPED_TRACE(t.substr(0, 200));
    EXPECT_FALSE(io::detail::read_plain_pmml(t));
  }
  // The joints' children in another order: declined, and read by XML all the same.
  const std::string reordered = edit("    <SpringConst>1</SpringConst>\n    <DampConst>0.1</DampConst>\n",
                                     "    <DampConst>0.1</DampConst>\n    <SpringConst>1</SpringConst>\n");
  EXPECT_FALSE(io::detail::read_plain_pmml(reordered));
  EXPECT_EQ(io::parse_pmml(reordered, "t.pmml").joints.size(), extended_strip().joints.size());
}

// An error in a file of foldkit's shape is still the XML reading's, at its line.
TEST(PmmlPlain, ErrorsKeepTheirLinesAndWords) {
  std::string text = io::write_pmml(extended_strip());
  const std::size_t at = text.find("<SpringConst>") + 13;
  text.replace(at, 1, "x");
  const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
  try {
    io::parse_pmml(text, "bad.pmml");
    FAIL() << "read a bad spring constant";
  } catch (const io::ParseError& e) {
    EXPECT_EQ(e.line(), line);
    EXPECT_NE(std::string(e.what()).find("<SpringConst>"), std::string::npos) << e.what();
  }
}

// Random corruptions of foldkit's text: never read what the XML reading refuses, the rest alike.
TEST(PmmlPlain, RandomCorruptionsDeclineOrAgree) {
  const std::string base = io::write_pmml(extended_strip());
  const std::vector<std::string> inserts = {"<", ">", "&", "</Actor>", "<Joint>", "\n", " ", "\t", "-", "+", "9", ".", "e",
                                            "<ID>2</ID>", "</ID>", "0", "\r", "<Title>t</Title>", "M", "<Density>1</Density>"};
  std::mt19937 rng(7);
  int read = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const std::string t = foldkit::test::corrupted(base, inserts, rng);
    SCOPED_TRACE("trial " + std::to_string(trial));
    read += plain_agrees(t);
  }
  EXPECT_GT(read, 100);  // both outcomes were exercised
  EXPECT_LT(read, 2900);
}

}  // namespace
