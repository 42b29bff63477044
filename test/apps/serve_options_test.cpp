// foldkit serve takes each verb's arguments from the CLI's own declarations (serve_verbs.cpp):
// options the server's code never names are served, with the checks their declared kind calls
// for. Oracles: the CLI's --json on the same files, and the file system.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "serve_test_server.hpp"

namespace {

namespace fs = std::filesystem;
using foldkit::test::comparable;
using foldkit::test::foldkit;
using foldkit::test::Server;
using nlohmann::json;

// fold --toward (a file read under the root) and generate cube-sheet --chain-cmml (a file
// written under the root) were never typed into the server.
TEST(ServeOptions, OptionsComeFromTheCliDeclarations) {
  Server s("options");
  ASSERT_GT(s.port(), 0) << s.log();
  ASSERT_EQ(foldkit({"generate", "miura", "--rows", "3", "--cols", "3", "-o", s.path("m.svg")}).exit, 0);

  const auto r = s.post("fold", {{"pattern", "m.svg"}, {"toward", "m.svg"}, {"fraction", 0.5}, {"output", "f.cmml"}});
  ASSERT_TRUE(r) << s.log();
  ASSERT_EQ(r->status, 200) << r->body;
  const auto cli = foldkit({"fold", s.path("m.svg"), "--toward", s.path("m.svg"), "--fraction", "0.5", "-o", s.path("g.cmml"), "--json"});
  ASSERT_EQ(cli.exit, 0) << cli.err;
  json expected = comparable(json::parse(cli.out), s.root());
  json got = json::parse(r->body)["result"];
  for (json* j : {&expected, &got}) j->erase("output");
  EXPECT_EQ(comparable(got, s.root()), expected);
  EXPECT_EQ(foldkit::test::slurp(s.path("f.cmml")), foldkit::test::slurp(s.path("g.cmml")));

  // A read file outside the root is refused like any other, whatever option names it.
  const auto outside = s.post("fold", {{"pattern", "m.svg"}, {"toward", "../m.svg"}, {"output", "h.cmml"}});
  ASSERT_TRUE(outside);
  EXPECT_EQ(outside->status, 400) << outside->body;

  const auto chain = s.post("generate", {{"kind", "cube-sheet"}, {"cubes", 2}, {"output", "c.pmml"}, {"chain-cmml", "chain.cmml"}});
  ASSERT_TRUE(chain);
  EXPECT_EQ(chain->status, 200) << chain->body;
  EXPECT_TRUE(fs::exists(s.path("chain.cmml")));
  // Declared types: a number for --fraction, a flag for --no-collision; kinds are the generators.
  EXPECT_EQ(s.post("fold", {{"pattern", "m.svg"}, {"fraction", "half"}, {"output", "f.cmml"}})->status, 400);
  EXPECT_EQ(s.post("fold", {{"pattern", "m.svg"}, {"no-collision", 1}, {"output", "f.cmml"}})->status, 400);
  EXPECT_EQ(s.post("generate", {{"kind", "--help"}, {"output", "x.pmml"}})->status, 400);
  EXPECT_EQ(s.post("fold", {{"pattern", "m.svg"}, {"json", true}, {"output", "f.cmml"}})->status, 400) << "--json is always given";
}

// An option's deprecated long name (project --velocity, now --speed) is served too, for one
// release: the same file as under its new name; both names at once are refused.
TEST(ServeOptions, DeprecatedOptionNamesAreServedToo) {
  Server s("aliases");
  ASSERT_GT(s.port(), 0) << s.log();
  ASSERT_EQ(foldkit({"generate", "miura", "--rows", "2", "--cols", "2", "-o", s.path("m.pmml")}).exit, 0);
  ASSERT_EQ(foldkit({"fold", s.path("m.pmml"), "--fraction", "0.3", "-o", s.path("f.cmml")}).exit, 0);
  const json base = {{"pattern", "m.pmml"}, {"state", "f.cmml"}};
  json by_speed = base, by_velocity = base, both = base;
  by_speed["speed"] = 45;
  by_speed["output"] = "a.cmml";
  by_velocity["velocity"] = 45;
  by_velocity["output"] = "b.cmml";
  both["speed"] = 45;
  both["velocity"] = 45;
  both["output"] = "c.cmml";
  const auto a = s.post("project", by_speed), b = s.post("project", by_velocity), c = s.post("project", both);
  ASSERT_TRUE(a && b && c) << s.log();
  EXPECT_EQ(a->status, 200) << a->body;
  EXPECT_EQ(b->status, 200) << b->body;
  EXPECT_EQ(c->status, 400) << c->body;
  EXPECT_EQ(foldkit::test::slurp(s.path("a.cmml")), foldkit::test::slurp(s.path("b.cmml")));
  EXPECT_NE(foldkit::test::slurp(s.path("a.cmml")).find("<Velocity>45</Velocity>"), std::string::npos);
}

// GET /api lists the planners `plan --planner` takes from the planners' own table: exactly the
// names `foldkit bench --list` lists (planners::planner_names()), in that order, one of them the
// default `plan --help` shows, and for each planner the CLI refuses, the CLI's own reason.
TEST(ServeOptions, PlannersAreTheClisOwn) {
  Server s("planners");
  ASSERT_GT(s.port(), 0) << s.log();
  const auto r = s.client().Get("/api");
  ASSERT_TRUE(r) << s.log();
  ASSERT_EQ(r->status, 200) << r->body;
  const json served = json::parse(r->body)["planners"];
  const auto list = foldkit({"bench", "--list", "--json"});
  ASSERT_EQ(list.exit, 0) << list.err;
  json names = json::array(), defaults = json::array();
  for (const json& p : served) {
    names.push_back(p["name"]);
    if (p["default"].get<bool>()) defaults.push_back(p["name"]);
  }
  EXPECT_EQ(names, json::parse(list.out)["planners"]["sampling"]);
  ASSERT_EQ(defaults.size(), 1u) << served.dump();
  const std::string help = foldkit({"plan", "--help"}).out;
  const std::size_t at = help.find("--planner");
  ASSERT_NE(at, std::string::npos) << help;
  const std::string planner_line = help.substr(at, help.find('\n', at) - at);
  EXPECT_NE(planner_line.find("=" + defaults[0].get<std::string>() + " "), std::string::npos) << planner_line;

  ASSERT_EQ(foldkit({"generate", "single-vertex", "--degree", "4", "-o", s.path("v.pmml")}).exit, 0);
  std::size_t refused = 0;
  for (const json& p : served) {
    const std::string why = p["refused"].get<std::string>();
    if (why.empty()) continue;
    ++refused;
    const auto plan =
        foldkit({"plan", s.path("v.pmml"), "--goal-angles", "1:30", "--planner", p["name"].get<std::string>(), "-o", s.path("p.cmml")});
    EXPECT_EQ(plan.exit, 2) << p.dump();
    EXPECT_NE(plan.err.find(why), std::string::npos) << plan.err;
  }
  EXPECT_GT(refused, 0u) << "the table's planners that cannot plan on a crease pattern are served with their reason";
}

}  // namespace
