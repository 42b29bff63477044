// foldkit serve under load (issue 35 item 5): verbs run on --workers at once with --queue more
// waiting, so that a burst of clients on this machine is answered rather than told 503; beyond the
// queue, 503 with Retry-After; a queued request keeps to --max-time from its arrival. Oracles: HTTP
// status codes and headers, counted per request sent (none may go unanswered), and GET /api.
#include <atomic>
#include <chrono>
#include <fstream>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "serve_test_server.hpp"

#include <httplib.h>  // last: its <resolv.h> macros would break headers included after it

namespace {

using foldkit::test::foldkit;
using foldkit::test::Server;
using nlohmann::json;

// The load: a Miura-ori 10 × 10, and its fold to 0.5 to simulate.
void miura_files(const Server& s) {
  ASSERT_EQ(foldkit({"generate", "miura", "--rows", "10", "--cols", "10", "-o", s.path("m10.pmml")}).exit, 0);
  ASSERT_EQ(foldkit({"fold", s.path("m10.pmml"), "--fraction", "0.5", "-o", s.path("m10-folded.cmml")}).exit, 0);
}

// One request of the mix: i % 3 == 0 GET /api, 1 info, 2 simulate. No answer (a connection
// refused, a read past the client's timeout) is status 0.
httplib::Result send(const Server& s, int i) {
  httplib::Client c("127.0.0.1", s.port());
  c.set_connection_timeout(10, 0);
  c.set_read_timeout(60, 0);  // a hung request fails the test rather than blocking it
  switch (i % 3) {
    case 0:
      return c.Get("/api");
    case 1:
      return c.Post("/api/info", json({{"pattern", "m10.pmml"}}).dump(), "application/json");
    default:
      return c.Post("/api/simulate", json({{"pattern", "m10.pmml"}, {"sequence", "m10-folded.cmml"}}).dump(), "application/json");
  }
}

struct Tally {
  std::mutex mutex;
  std::map<int, int> statuses;  // HTTP status → requests (0: no answer)
  int sent = 0;
  int without_retry_after = 0;  // 503s that lack a whole number of seconds in Retry-After
  std::string last_body;        // of an answer other than 200 and 503

  void add(const httplib::Result& r) {
    std::lock_guard<std::mutex> lock(mutex);
    ++sent;
    const int status = r ? r->status : 0;
    ++statuses[status];
    if (status == 503) {
      const std::string retry = r->get_header_value("Retry-After");
      if (retry.empty() || retry.find_first_not_of("0123456789") != std::string::npos || std::stol(retry) < 1) ++without_retry_after;
    } else if (status != 200) {
      last_body = r ? r->body : "no answer: " + httplib::to_string(r.error());
    }
  }
  int count(int status) {
    std::lock_guard<std::mutex> lock(mutex);
    return statuses.count(status) ? statuses[status] : 0;
  }
};

// `clients` threads, each sending `each` requests of the mix one after the other, all started
// together.
void load(const Server& s, int clients, int each, Tally& tally) {
  std::vector<std::thread> threads;
  for (int c = 0; c < clients; ++c)
    threads.emplace_back([&, c] {
      for (int i = 0; i < each; ++i) tally.add(send(s, c + i));
    });
  for (auto& t : threads) t.join();
}

// The measurement (then: 2-3 of 200 verb requests answered, the rest 503), with the
// default workers and queue: 24 clients × 10 requests, every one answered 200.
TEST(ServeLoad, TwentyFourClientsAllAnswered) {
  Server s("load");
  ASSERT_GT(s.port(), 0) << s.log();
  miura_files(s);
  Tally tally;
  load(s, 24, 10, tally);
  EXPECT_EQ(tally.sent, 240);
  EXPECT_EQ(tally.count(200), 240) << "statuses: " << json(tally.statuses).dump() << "\n" << tally.last_body;
  EXPECT_EQ(tally.count(0), 0) << "requests without an answer";
  // Still serving afterwards, the API and the verbs.
  EXPECT_EQ(send(s, 0)->status, 200);
  EXPECT_EQ(send(s, 1)->status, 200);
}

// Beyond the queue: 503 with Retry-After, every request answered one way or the other. One
// worker and one place in the queue, the worker held by a plan that runs its whole (capped) 1.5 s
// while 12 clients send 3 requests each.
TEST(ServeLoad, BeyondTheQueueIsRefusedWithRetryAfter) {
  Server s("full", {"--workers", "1", "--queue", "1", "--max-plan-time", "1.5"});
  ASSERT_GT(s.port(), 0) << s.log();
  miura_files(s);
  // A closed goal of a single vertex (as ServeApi's busy test makes it).
  ASSERT_EQ(foldkit({"generate", "single-vertex", "--sectors", "90,60,90,60,60", "-o", s.path("v.pmml")}).exit, 0);
  std::string guess = "<?xml version=\"1.0\"?>\n<CMML><Title>test</Title>";
  for (const auto& [id, angle] : std::vector<std::pair<int, int>>{{1, 28}, {2, -23}, {3, 28}, {4, 17}, {5, -17}})
    guess += "<Fold><EventNumber>1</EventNumber><ID>" + std::to_string(id) + "</ID><FoldAngle>" + std::to_string(angle) +
             "</FoldAngle><Velocity>30</Velocity></Fold>";
  std::ofstream(s.path("guess.cmml")) << guess << "</CMML>\n";
  ASSERT_EQ(foldkit({"project", s.path("v.pmml"), "--state", s.path("guess.cmml"), "-o", s.path("goal.cmml")}).exit, 0);
  std::thread slow([&] {
    // Steps of 1e-7 rad: RRTConnect finds nothing and runs its whole (capped) time.
    const auto r = s.post("plan", {{"pattern", "v.pmml"}, {"goal", "goal.cmml"}, {"param", {"range=1e-7"}}, {"no-fallback", true},
                                   {"time", 30}, {"output", "never.cmml"}});
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 200) << r->body;
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  Tally tally;
  load(s, 12, 3, tally);
  slow.join();
  EXPECT_EQ(tally.sent, 36);
  EXPECT_EQ(tally.count(200) + tally.count(503), tally.sent) << "statuses: " << json(tally.statuses).dump() << "\n" << tally.last_body;
  EXPECT_GE(tally.count(503), 1) << "statuses: " << json(tally.statuses).dump();
  EXPECT_EQ(tally.without_retry_after, 0);
  EXPECT_GE(tally.count(200), 12) << "GET /api is answered while the worker and the queue are taken";
  EXPECT_EQ(send(s, 1)->status, 200) << "the server goes on";
}

// A queued request's --max-time counts from its arrival: behind a verb that runs out the limit,
// it is answered 504 (with the limit's wording) about when that one is, not a whole limit later.
TEST(ServeLoad, QueuedRequestsKeepToTheTimeLimit) {
  Server s("queued-limit", {"--workers", "1", "--queue", "4", "--max-time", "2"});
  ASSERT_GT(s.port(), 0) << s.log();
  ASSERT_EQ(foldkit({"generate", "miura", "--rows", "2", "--cols", "2", "-o", s.path("m2.pmml")}).exit, 0);
  ASSERT_EQ(foldkit({"fold", s.path("m2.pmml"), "--fraction", "0.5", "-o", s.path("f.cmml")}).exit, 0);
  // Steps of a microsecond through a fold of seconds: it runs until the limit stops it.
  const json endless = {{"pattern", "m2.pmml"}, {"sequence", "f.cmml"}, {"time-step", 1e-6}};
  std::thread first([&] {
    const auto r = s.post("simulate", endless);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 504) << r->body;
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const auto start = std::chrono::steady_clock::now();
  const auto r = s.post("simulate", endless);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  first.join();
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 504) << r->body;
  EXPECT_NE(json::parse(r->body)["error"].get<std::string>().find("(foldkit serve --max-time)"), std::string::npos) << r->body;
  EXPECT_LT(seconds, 3.2) << "it waited 1.8 s of its 2 and must not then run 2 s more";
  EXPECT_EQ(s.post("info", {{"pattern", "m2.pmml"}})->status, 200);
}

// GET /api reports the workers and the queue under the option's names; bad values are usage errors.
TEST(ServeLoad, WorkersAndQueueAreOptions) {
  Server s("options-pool", {"--workers", "3", "--queue", "5"});
  ASSERT_GT(s.port(), 0) << s.log();
  const json j = json::parse(s.client().Get("/api")->body);
  EXPECT_EQ(j["workers"], 3);
  EXPECT_EQ(j["queue"], 5);
  Server d("default-pool");
  ASSERT_GT(d.port(), 0) << d.log();
  const json k = json::parse(d.client().Get("/api")->body);
  EXPECT_EQ(k["workers"], std::max(1u, std::thread::hardware_concurrency()));
  EXPECT_EQ(k["queue"], 64);
  EXPECT_EQ(foldkit({"serve", "--workers", "0", "--root", s.root()}).exit, 2);
  EXPECT_EQ(foldkit({"serve", "--queue", "-1", "--root", s.root()}).exit, 2);
}

}  // namespace
