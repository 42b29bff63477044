// foldkit serve: the JSON API of docs/SERVE.md, driven over HTTP (cpp-httplib's client) against
// a `foldkit serve` process. Oracles: the CLI's own --json output and files on the same inputs
// (the API must answer exactly as the verbs do), the file system (what was written where), and
// HTTP status codes for what must be refused.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <thread>


#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "serve_test_server.hpp"

#include <httplib.h>  // last: its <resolv.h> macros would break headers included after it

namespace {

namespace fs = std::filesystem;
using foldkit::test::comparable;
using foldkit::test::foldkit;
using foldkit::test::Server;
using foldkit::test::slurp;
using nlohmann::json;

// A CMML of one event that folds joint ID to angle (degrees) for each pair.
std::string one_event(const std::vector<std::pair<int, double>>& folds) {
  std::string text = "<?xml version=\"1.0\"?>\n<CMML><Title>test</Title>";
  for (const auto& [id, angle] : folds)
    text += "<Fold><EventNumber>1</EventNumber><ID>" + std::to_string(id) + "</ID><FoldAngle>" + std::to_string(angle) +
            "</FoldAngle><Velocity>30</Velocity></Fold>";
  return text + "</CMML>\n";
}

void generate(const Server& s, const std::vector<std::string>& what, const std::string& name) {
  std::vector<std::string> args = {"generate"};
  args.insert(args.end(), what.begin(), what.end());
  args.insert(args.end(), {"-o", s.path(name)});
  ASSERT_EQ(foldkit(args).exit, 0) << name;
}

TEST(ServeApi, StartsOnThisMachineOnlyAndListsItsVerbs) {
  Server s("start");
  ASSERT_GT(s.port(), 0) << s.log();
  const auto r = s.client().Get("/api");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  const json j = json::parse(r->body);
  EXPECT_EQ(j["verbs"], json({"validate", "info", "dof", "project", "simulate", "fold", "plan", "stiffness", "convert", "generate"}));
  EXPECT_NE(s.log().find("http://127.0.0.1:"), std::string::npos);
  // A second server on the same port is an error, not a silent sharer of its requests.
  const auto second = foldkit({"serve", "--port", std::to_string(s.port()), "--root", s.root()});
  EXPECT_EQ(second.exit, 2) << second.err;
  EXPECT_NE(second.err.find("cannot listen"), std::string::npos) << second.err;
  // Bad roots and files outside the root are usage errors.
  EXPECT_EQ(foldkit({"serve", "--root", s.root() + "/none"}).exit, 2);
  EXPECT_EQ(foldkit({"serve", "none.pmml", "--root", s.root()}).exit, 2);
}

// Every verb answers with the CLI's JSON for the same files, and writes the same files.
TEST(ServeApi, EveryVerbAnswersAsTheCliDoes) {
  Server s("verbs");
  ASSERT_GT(s.port(), 0) << s.log();
  generate(s, {"miura", "--rows", "3", "--cols", "3"}, "m3.pmml");
  generate(s, {"strip", "--panels", "4"}, "strip.pmml");
  fs::copy_file(FOLDKIT_TEST_DATA "/good/strip-tip.loadcase", s.path("tip.loadcase"));
  ASSERT_EQ(foldkit({"fold", s.path("m3.pmml"), "--fraction", "0.5", "-o", s.path("goal.cmml")}).exit, 0);

  struct Case {
    std::string verb;
    json request;
    std::vector<std::string> cli;      // the same, on the command line ("@NAME": a file under the root)
    std::vector<std::string> written;  // files both write, compared byte for byte
  };
  const std::vector<Case> cases = {
      {"validate", {{"files", {"m3.pmml", "goal.cmml"}}, {"pattern", "m3.pmml"}}, {"validate", "@m3.pmml", "@goal.cmml", "--pattern", "@m3.pmml"}, {}},
      {"info", {{"pattern", "m3.pmml"}}, {"info", "@m3.pmml"}, {}},
      {"dof", {{"pattern", "m3.pmml"}, {"state", "goal.cmml"}}, {"dof", "@m3.pmml", "--state", "@goal.cmml"}, {}},
      {"project", {{"pattern", "m3.pmml"}, {"state", "goal.cmml"}, {"output", "p.cmml"}}, {"project", "@m3.pmml", "--state", "@goal.cmml", "-o", "@p.cmml"}, {"p.cmml"}},
      {"simulate", {{"pattern", "m3.pmml"}, {"sequence", "goal.cmml"}, {"frames", "t.fold"}}, {"simulate", "@m3.pmml", "@goal.cmml", "--frames", "@t.fold"}, {"t.fold"}},
      {"fold", {{"pattern", "m3.pmml"}, {"fraction", 0.4}, {"no-collision", true}, {"output", "f.cmml"}}, {"fold", "@m3.pmml", "--fraction", "0.4", "--no-collision", "-o", "@f.cmml"}, {"f.cmml"}},
      {"plan", {{"pattern", "m3.pmml"}, {"goal", "goal.cmml"}, {"seed", 3}, {"output", "plan.cmml"}}, {"plan", "@m3.pmml", "--goal", "@goal.cmml", "--seed", "3", "-o", "@plan.cmml"}, {"plan.cmml"}},
      {"stiffness", {{"pattern", "strip.pmml"}, {"loadcase", "tip.loadcase"}}, {"stiffness", "@strip.pmml", "@tip.loadcase"}, {}},
      {"convert", {{"input", "m3.pmml"}, {"output", "m3.fold"}}, {"convert", "@m3.pmml", "@m3.fold"}, {"m3.fold"}},
      {"generate", {{"kind", "waterbomb"}, {"units", 2}, {"rows", 2}, {"spring", 2.5}, {"output", "wb.pmml"}},
       {"generate", "waterbomb", "--units", "2", "--rows", "2", "--spring", "2.5", "-o", "@wb.pmml"}, {"wb.pmml"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.verb);
    const auto r = s.post(c.verb, c.request);
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 200) << r->body;
    const json api = json::parse(r->body);
    EXPECT_EQ(api["verb"], c.verb);
    std::map<std::string, std::string> by_api;
    for (const auto& w : c.written) by_api[w] = slurp(s.path(w));
    std::vector<std::string> args;  // "@NAME" is a file under the root
    for (const auto& a : c.cli) args.push_back(a[0] == '@' ? s.path(a.substr(1)) : a);
    const bool json_verb = c.verb != "convert";
    if (json_verb) args.push_back("--json");
    const auto cli = foldkit(args);
    EXPECT_EQ(api["exit"].get<int>(), cli.exit) << cli.err;
    if (json_verb) {
      EXPECT_EQ(comparable(api["result"], s.root()), comparable(json::parse(cli.out), s.root()));
    }
    for (const auto& w : c.written) EXPECT_EQ(by_api[w], slurp(s.path(w))) << w;
  }
}

// Bad input is the CLI's FILE:LINE: message, relative to the root, as HTTP 400; a missing file
// 404; a verb that runs but finds the sequence invalid answers 200 with the CLI's exit code 3.
TEST(ServeApi, BadInputIsTheClisMessageAsA400) {
  Server s("bad");
  ASSERT_GT(s.port(), 0) << s.log();
  fs::copy_file(FOLDKIT_TEST_DATA "/bad/truncated.pmml", s.path("truncated.pmml"));
  const auto cli = foldkit({"info", s.path("truncated.pmml")});
  ASSERT_EQ(cli.exit, 1);
  const auto r = s.post("info", {{"pattern", "truncated.pmml"}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  const json j = json::parse(r->body);
  EXPECT_EQ(j["exit"], 1);
  const std::string message = j["error"];
  EXPECT_EQ(message.rfind("truncated.pmml:", 0), 0u) << message;
  EXPECT_EQ(s.root() + "/" + message, cli.err.substr(0, cli.err.find('\n'))) << message;

  // validate's 400 carries its JSON too: every problem with its line, for a client to point at.
  const auto all = s.post("validate", {{"files", {"truncated.pmml"}}});
  ASSERT_TRUE(all);
  EXPECT_EQ(all->status, 400);
  const json listed = json::parse(all->body);
  EXPECT_EQ(listed["error"], message);
  ASSERT_EQ(listed["result"]["files"].size(), 1u) << all->body;
  EXPECT_EQ(listed["result"]["files"][0]["file"], "truncated.pmml");
  EXPECT_GT(listed["result"]["files"][0]["errors"][0]["line"].get<int>(), 0);

  const auto missing = s.post("info", {{"pattern", "nope.pmml"}});
  ASSERT_TRUE(missing);
  EXPECT_EQ(missing->status, 404);

  generate(s, {"miura", "--rows", "3", "--cols", "3"}, "m3.pmml");
  // A strip folded through itself: the simulator's verdict is a result (exit 3), not an error.
  generate(s, {"strip", "--panels", "3"}, "strip.pmml");
  std::ofstream(s.path("through.cmml")) << one_event({{1, 170}, {2, 170}});
  const auto sim_cli = foldkit({"simulate", s.path("strip.pmml"), s.path("through.cmml"), "--json"});
  const auto sim = s.post("simulate", {{"pattern", "strip.pmml"}, {"sequence", "through.cmml"}});
  ASSERT_TRUE(sim);
  ASSERT_EQ(sim_cli.exit, 3) << sim_cli.err;
  EXPECT_EQ(sim->status, 200) << sim->body;
  EXPECT_EQ(json::parse(sim->body)["exit"], 3);
}

TEST(ServeApi, RequestsOfTheWrongShapeAreRefused) {
  Server s("shape");
  ASSERT_GT(s.port(), 0) << s.log();
  generate(s, {"miura", "--rows", "2", "--cols", "2"}, "m2.pmml");
  const auto status = [&](const std::string& verb, const std::string& body) {
    const auto r = s.client().Post(("/api/" + verb).c_str(), body, "application/json");
    return r ? r->status : -1;
  };
  EXPECT_EQ(status("carpenter", "{}"), 404);                                   // not served
  EXPECT_EQ(status("info", "{\"pattern\": "), 400);                            // not JSON
  EXPECT_EQ(status("info", "[1, 2]"), 400);                                    // not an object
  EXPECT_EQ(status("info", "{}"), 400);                                        // pattern missing
  EXPECT_EQ(status("info", R"({"pattern": "m2.pmml", "colour": 1})"), 400);    // no such argument
  EXPECT_EQ(status("fold", R"({"pattern": "m2.pmml", "fraction": "half", "output": "x.cmml"})"), 400);  // wrong type
  EXPECT_EQ(status("fold", R"({"pattern": "m2.pmml", "fraction": 2, "output": "x.cmml"})"), 400);       // the CLI's range
  EXPECT_EQ(status("dof", R"({"pattern": "m2.pmml", "max-iterations": 18446744073709551615})"), 400);  // too large, not wrapped
  // Nested 100,000 deep: refused at parsing, not followed recursively (which crashed the server).
  EXPECT_EQ(status("dof", "{\"pattern\": \"m2.pmml\", \"tolerance\": " + std::string(100000, '[') + std::string(100000, ']') + "}"), 400);
  EXPECT_EQ(status("generate", R"({"kind": "--help", "output": "x.pmml"})"), 400);                // only the generators' names
  EXPECT_EQ(status("generate", R"({"kind": "miura", "units": 2, "output": "x.pmml"})"), 400);     // the CLI refuses another kind's option
  EXPECT_EQ(status("info", R"({"pattern": "m2.pmml"})"), 200);
  EXPECT_FALSE(fs::exists(s.path("x.cmml")));
  EXPECT_FALSE(fs::exists(s.path("x.pmml")));
  const auto unknown = s.client().Get("/api/Info");  // unknown endpoints answer in JSON too
  ASSERT_TRUE(unknown);
  EXPECT_EQ(unknown->status, 404);
  EXPECT_EQ(json::parse(unknown->body)["exit"], 2);
}

// Nothing outside the root is read, written or listed: absolute paths, "..", and links that lead
// out are refused.
TEST(ServeApi, PathsOutsideTheRootAreRefused) {
  Server s("paths");
  ASSERT_GT(s.port(), 0) << s.log();
  const std::string outside = s.root() + "-outside";
  fs::remove_all(outside);
  fs::create_directories(outside);
  ASSERT_EQ(foldkit({"generate", "miura", "--rows", "2", "--cols", "2", "-o", outside + "/secret.pmml"}).exit, 0);
  fs::create_symlink(outside + "/secret.pmml", s.path("link.pmml"));
  fs::create_directory_symlink(outside, s.path("out"));
  generate(s, {"miura", "--rows", "2", "--cols", "2"}, "m2.pmml");

  for (const std::string& bad : std::vector<std::string>{outside + "/secret.pmml", "../serve-paths-outside/secret.pmml", "link.pmml", "out/secret.pmml"}) {
    SCOPED_TRACE(bad);
    const auto r = s.post("info", {{"pattern", bad}});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 400) << r->body;
    const auto get = s.client().Get(("/api/file?path=" + httplib::detail::encode_query_param(bad)).c_str());
    ASSERT_TRUE(get);
    EXPECT_EQ(get->status, 400) << get->body;
  }
  for (const std::string& bad : std::vector<std::string>{outside + "/new.cmml", "../new.cmml", "out/new.cmml", "link.pmml"}) {
    SCOPED_TRACE(bad);
    const auto fold = s.post("fold", {{"pattern", "m2.pmml"}, {"fraction", 0.3}, {"output", bad}});
    ASSERT_TRUE(fold);
    EXPECT_EQ(fold->status, 400) << fold->body;
    const auto put = s.client().Put(("/api/file?path=" + httplib::detail::encode_query_param(bad)).c_str(), "x", "text/plain");
    ASSERT_TRUE(put);
    EXPECT_EQ(put->status, 400) << put->body;
  }
  // simulate's svg folder: the verb names the files it writes there, so a link planted in it
  // (event-1.svg → a file outside) would be written through; such a folder is refused.
  ASSERT_EQ(foldkit({"fold", s.path("m2.pmml"), "--fraction", "0.3", "-o", s.path("f.cmml")}).exit, 0);
  std::ofstream(outside + "/victim.svg") << "untouched";
  fs::create_directories(s.path("shots"));
  fs::create_symlink(outside + "/victim.svg", s.path("shots/event-1.svg"));
  const auto svg = s.post("simulate", {{"pattern", "m2.pmml"}, {"sequence", "f.cmml"}, {"svg", "shots"}});
  ASSERT_TRUE(svg);
  EXPECT_EQ(svg->status, 400) << svg->body;
  EXPECT_EQ(slurp(outside + "/victim.svg"), "untouched");
  EXPECT_FALSE(fs::exists(outside + "/new.cmml"));
  EXPECT_EQ(fs::read_symlink(s.path("link.pmml")), outside + "/secret.pmml");  // the link itself untouched
  const auto listing = s.client().Get("/api/files?folder=out");
  ASSERT_TRUE(listing);
  EXPECT_EQ(listing->status, 400);
  const auto top = json::parse(s.client().Get("/api/files")->body);
  for (const auto& e : top["entries"]) EXPECT_NE(e["name"], "link.pmml");  // links are not listed
}

// Files go in and out whole: PUT writes atomically (only foldkit's formats), GET returns the bytes.
TEST(ServeApi, FilesAreWrittenAndReadWhole) {
  Server s("files");
  ASSERT_GT(s.port(), 0) << s.log();
  ASSERT_EQ(foldkit({"generate", "miura", "--rows", "2", "--cols", "2", "-o", s.root() + "-m2.pmml"}).exit, 0);
  const std::string pmml = slurp(s.root() + "-m2.pmml");
  fs::create_directories(s.path("work"));
  const auto put = s.client().Put("/api/file?path=work/m2.pmml", pmml, "application/xml");
  ASSERT_TRUE(put);
  ASSERT_EQ(put->status, 200) << put->body;
  EXPECT_EQ(slurp(s.path("work/m2.pmml")), pmml);
  const auto get = s.client().Get("/api/file?path=work/m2.pmml");
  ASSERT_TRUE(get);
  EXPECT_EQ(get->status, 200);
  EXPECT_EQ(get->body, pmml);
  // Never compressed, whatever the client accepts (Debian's httplib's Brotli took 80 s for 49 MB).
  const auto plain = s.client().Get("/api/file?path=work/m2.pmml", {{"Accept-Encoding", "br, gzip, deflate"}});
  ASSERT_TRUE(plain);
  EXPECT_EQ(plain->get_header_value("Content-Encoding"), "");
  EXPECT_EQ(plain->body, pmml);
  const auto listing = json::parse(s.client().Get("/api/files?folder=work")->body);
  ASSERT_EQ(listing["entries"].size(), 1u);
  EXPECT_EQ(listing["entries"][0]["name"], "m2.pmml");
  EXPECT_EQ(listing["entries"][0]["bytes"], pmml.size());
  const auto info = s.post("info", {{"pattern", "work/m2.pmml"}});
  EXPECT_EQ(info->status, 200);
  EXPECT_EQ(s.client().Put("/api/file?path=run.sh", "echo", "text/plain")->status, 400);  // not a foldkit format
  // A form (curl -F) would be parsed into fields and leave the body empty: refused, file untouched.
  httplib::MultipartFormDataItems form = {{"a", pmml, "m2.pmml", "application/xml"}};
  EXPECT_EQ(s.client().Put("/api/file?path=work/m2.pmml", form)->status, 400);
  EXPECT_EQ(slurp(s.path("work/m2.pmml")), pmml);
  EXPECT_EQ(s.client().Put("/api/file?path=nofolder/m.pmml", pmml, "application/xml")->status, 404);
  EXPECT_EQ(s.client().Get("/api/file?path=none.pmml")->status, 404);
  EXPECT_FALSE(fs::exists(s.path("run.sh")));
}

// Bodies beyond --max-body are refused before anything runs (413).
TEST(ServeApi, OversizedBodiesAreRefused) {
  Server s("size", {"--max-body", "0.01"});  // 10 KB
  ASSERT_GT(s.port(), 0) << s.log();
  const std::string big(20000, 'x');
  const auto put = s.client().Put("/api/file?path=big.svg", big, "image/svg+xml");
  ASSERT_TRUE(put);
  EXPECT_EQ(put->status, 413);
  EXPECT_FALSE(fs::exists(s.path("big.svg")));
  const auto post = s.client().Post("/api/info", "{\"pattern\": \"" + big + "\"}", "application/json");
  ASSERT_TRUE(post);
  EXPECT_EQ(post->status, 413);
  EXPECT_EQ(s.client().Put("/api/file?path=small.svg", "<svg/>", "image/svg+xml")->status, 200);
}

// With one worker and no queue, a request while a plan runs is told the server is busy (503, with
// Retry-After) at once, and a plan asks for at most --max-plan-time seconds. (Queues and many
// workers: serve_load_test.cpp.)
TEST(ServeApi, BusyWithoutAQueueAndPlansAreTimeLimited) {
  Server s("busy", {"--max-plan-time", "1.5", "--workers", "1", "--queue", "0"});
  ASSERT_GT(s.port(), 0) << s.log();
  generate(s, {"single-vertex", "--sectors", "90,60,90,60,60"}, "v.pmml");
  std::ofstream(s.path("guess.cmml")) << one_event({{1, 28}, {2, -23}, {3, 28}, {4, 17}, {5, -17}});
  ASSERT_EQ(foldkit({"project", s.path("v.pmml"), "--state", s.path("guess.cmml"), "-o", s.path("goal.cmml")}).exit, 0);
  const auto start = std::chrono::steady_clock::now();
  std::thread slow([&] {
    // Steps of 1e-7 rad: RRTConnect finds nothing and runs its whole (capped) time.
    const auto r = s.post("plan", {{"pattern", "v.pmml"}, {"goal", "goal.cmml"}, {"param", {"range=1e-7"}}, {"no-fallback", true},
                                   {"time", 30}, {"output", "never.cmml"}});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200) << r->body;
    EXPECT_EQ(json::parse(r->body)["exit"], 4);
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  const auto busy = s.post("info", {{"pattern", "v.pmml"}});
  ASSERT_TRUE(busy);
  EXPECT_EQ(busy->status, 503) << busy->body;
  EXPECT_FALSE(busy->get_header_value("Retry-After").empty());
  slow.join();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 10.0);  // 1.5 s of planning, not the 30 asked for
  EXPECT_GT(seconds, 1.4);
  EXPECT_EQ(s.post("info", {{"pattern", "v.pmml"}})->status, 200);
}

// A verb that runs past --max-time is killed (504) and the server goes on.
TEST(ServeApi, AVerbPastTheTimeLimitIsStopped) {
  Server s("timeout", {"--max-time", "1"});
  ASSERT_GT(s.port(), 0) << s.log();
  generate(s, {"miura", "--rows", "2", "--cols", "2"}, "m2.pmml");
  ASSERT_EQ(foldkit({"fold", s.path("m2.pmml"), "--fraction", "0.5", "-o", s.path("f.cmml")}).exit, 0);
  const auto start = std::chrono::steady_clock::now();
  // Steps of a microsecond through a fold of seconds: millions of steps.
  const auto r = s.post("simulate", {{"pattern", "m2.pmml"}, {"sequence", "f.cmml"}, {"time-step", 1e-6}});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 504) << r->body;
  EXPECT_NE(json::parse(r->body)["error"].get<std::string>().find("--max-time"), std::string::npos);
  EXPECT_LT(seconds, 5.0);
  EXPECT_EQ(s.post("info", {{"pattern", "m2.pmml"}})->status, 200);
}

// Requests assembled at random from the verbs' argument names and values of every JSON type
// (paths out of the root, option-like strings, huge and negative numbers) never crash the server
// or get an answer outside the documented codes.
TEST(ServeApi, RandomRequestsGetDocumentedAnswers) {
  Server s("random", {"--max-time", "5", "--max-plan-time", "0.2"});
  ASSERT_GT(s.port(), 0) << s.log();
  generate(s, {"miura", "--rows", "2", "--cols", "2"}, "m2.pmml");
  ASSERT_EQ(foldkit({"fold", s.path("m2.pmml"), "--fraction", "0.3", "-o", s.path("f.cmml")}).exit, 0);
  const std::vector<std::string> verbs = {"validate", "info", "dof", "project", "simulate", "fold", "plan", "stiffness", "convert", "generate", "nope"};
  const std::vector<std::string> names = {"pattern", "files", "state", "sequence", "output", "goal", "fraction", "time-step", "tolerance",
                                          "no-collision", "velocity", "param", "input", "frames", "svg", "seed", "max-steps", "model",
                                          "kind", "rows", "title"};
  const std::vector<json> values = {"m2.pmml", "f.cmml", "miura", "../m2.pmml", "/etc/passwd", "--json", "-o=/tmp/x", "", "out.cmml",
                                    "sub/out.fold", json::array({"m2.pmml"}), json::array({1, 2}), 0.5, -1, 0, 1e308, 3, true,
                                    false, nullptr, json::object({{"a", 1}}), std::string(5000, 'a')};
  std::mt19937 rng(7);
  const auto pick = [&](auto& v) { return v[std::uniform_int_distribution<std::size_t>(0, v.size() - 1)(rng)]; };
  for (int i = 0; i < 150; ++i) {
    json body = json::object();
    const int keys = std::uniform_int_distribution<int>(0, 4)(rng);
    for (int k = 0; k < keys; ++k) body[pick(names)] = pick(values);
    const std::string verb = pick(verbs);
    const auto r = s.client().Post(("/api/" + verb).c_str(), i % 10 == 9 ? "{not json" : body.dump(), "application/json");
    ASSERT_TRUE(r) << "no answer to " << verb << " " << body.dump();
    EXPECT_TRUE(r->status == 200 || r->status == 400 || r->status == 404) << r->status << " for " << verb << " " << body.dump() << "\n" << r->body;
  }
  EXPECT_EQ(s.client().Get("/api")->status, 200);
  EXPECT_FALSE(fs::exists("/tmp/x"));
  for (const auto& e : fs::recursive_directory_iterator(s.root()))  // nothing written but under the root, and no link
    EXPECT_FALSE(fs::is_symlink(e.symlink_status())) << e.path();
}

// GET / serves the browser app from --web: its page, its modules and three.js's, and nothing else
// of the folder (not the browser tests' packages, not a file beside the page, nothing outside).
TEST(ServeApi, ServesTheBrowserAppAndNothingElse) {
  const std::string web = foldkit::test::temp_dir() + "/serve-web-app";
  fs::remove_all(web);
  for (const char* d : {"src", "node_modules/three/build", "node_modules/three/examples/jsm/controls", "node_modules/puppeteer-core"})
    fs::create_directories(web + "/" + d);
  const std::map<std::string, std::string> files = {{"index.html", "<!doctype html><title>t</title>"},
                                                    {"src/app.js", "export const a = 1;"},
                                                    {"node_modules/three/build/three.module.js", "export const three = 1;"},
                                                    {"node_modules/three/examples/jsm/controls/OrbitControls.js", "export const o = 1;"},
                                                    {"node_modules/puppeteer-core/index.js", "private"},
                                                    {"package.json", "{}"},
                                                    {"src/notes.txt", "private"}};
  for (const auto& [name, text] : files) std::ofstream(web + "/" + name) << text;
  fs::create_symlink("/etc/hostname", web + "/src/leak.js");
  Server s("web", {"--web", web});
  ASSERT_GT(s.port(), 0) << s.log();
  const auto get = [&](const std::string& path) { return s.client().Get(path.c_str()); };
  const auto page = get("/");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  EXPECT_EQ(page->body, files.at("index.html"));
  EXPECT_EQ(page->get_header_value("Content-Type"), "text/html; charset=utf-8");
  for (const char* ok : {"/index.html", "/src/app.js", "/node_modules/three/build/three.module.js",
                         "/node_modules/three/examples/jsm/controls/OrbitControls.js"}) {
    SCOPED_TRACE(ok);
    const auto r = get(ok);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200);
    EXPECT_EQ(r->body, files.at(std::string(ok).substr(1)));
  }
  EXPECT_EQ(get("/src/app.js")->get_header_value("Content-Type"), "text/javascript; charset=utf-8");
  for (const char* refused : {"/node_modules/puppeteer-core/index.js", "/package.json", "/src/notes.txt", "/src/leak.js",
                              "/src/../package.json", "/src/%2e%2e/package.json", "/src/none.js", "/%2e%2e/serve-web.log"}) {
    SCOPED_TRACE(refused);
    const auto r = get(refused);
    ASSERT_TRUE(r);
    EXPECT_GE(r->status, 400);
    EXPECT_NE(r->body, "private");
  }
  EXPECT_EQ(get("/api")->status, 200);  // the API is still the API
  EXPECT_EQ(json::parse(get("/api/nothing")->body)["exit"], 2);
  // No app folder: the page says where the API is; a folder without a page is a usage error.
  Server bare("web-none", {"--web", ""});
  ASSERT_GT(bare.port(), 0) << bare.log();
  const auto none = bare.client().Get("/");
  ASSERT_TRUE(none);
  EXPECT_EQ(none->status, 404);
  EXPECT_NE(json::parse(none->body)["error"].get<std::string>().find("/api"), std::string::npos);
  EXPECT_EQ(foldkit({"serve", "--web", web + "/src", "--root", s.root()}).exit, 2);
}

// Only this machine's own pages and programs are served: a page of another site that posts to the
// server (CSRF), a name that resolves to it (DNS rebinding) and a verb not sent as JSON are refused
// before anything runs; files come back as data, never as a page that could script the API.
TEST(ServeApi, RequestsFromOtherSitesAreRefused) {
  Server s("foreign");
  ASSERT_GT(s.port(), 0) << s.log();
  generate(s, {"miura", "--rows", "2", "--cols", "2"}, "m2.pmml");
  const std::string here = "127.0.0.1:" + std::to_string(s.port());
  const std::string body = R"({"kind": "grid", "rows": 1, "cols": 1, "output": "m2.pmml"})";
  const std::string before = slurp(s.path("m2.pmml"));
  const auto post = [&](const httplib::Headers& headers, const std::string& type = "application/json") {
    const auto r = s.client().Post("/api/generate", headers, body, type.c_str());
    return r ? r->status : -1;
  };
  EXPECT_EQ(post({{"Host", "evil.example"}}), 403);
  EXPECT_EQ(post({{"Host", "evil.example:" + std::to_string(s.port())}}), 403);
  EXPECT_EQ(post({{"Origin", "http://evil.example"}}), 403);
  EXPECT_EQ(post({{"Origin", "http://localhost:3000"}}), 403);  // another port of this machine is another site
  EXPECT_EQ(post({{"Origin", "null"}}), 403);
  EXPECT_EQ(post({{"Sec-Fetch-Site", "cross-site"}}), 403);
  EXPECT_EQ(post({}, "text/plain"), 415);  // what a form or a no-cors fetch can send
  EXPECT_EQ(slurp(s.path("m2.pmml")), before);
  const auto read = s.client().Get("/api/file?path=m2.pmml", {{"Host", "rebound.example:" + std::to_string(s.port())}});
  ASSERT_TRUE(read);
  EXPECT_EQ(read->status, 403);
  EXPECT_EQ(read->body.find("<PMML>"), std::string::npos);
  // The server's own page, and local names.
  EXPECT_EQ(post({{"Origin", "http://" + here}}), 200);
  EXPECT_EQ(s.client().Get("/api", {{"Host", "localhost:" + std::to_string(s.port())}})->status, 200);
  EXPECT_EQ(s.client().Get("/api", {{"Host", "[::1]:" + std::to_string(s.port())}})->status, 200);
  // A page among the root's files comes back as text that cannot run.
  std::ofstream(s.path("page.html")) << "<script>fetch('/api/file?path=m2.pmml')</script>";
  const auto html = s.client().Get("/api/file?path=page.html");
  ASSERT_TRUE(html);
  EXPECT_EQ(html->status, 200);
  EXPECT_EQ(html->get_header_value("Content-Type"), "text/plain; charset=utf-8");
  EXPECT_EQ(html->get_header_value("X-Content-Type-Options"), "nosniff");
  EXPECT_EQ(html->get_header_value("Content-Security-Policy"), "sandbox");
}

}  // namespace
