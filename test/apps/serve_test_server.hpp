#pragma once
// A `foldkit serve` process for the tests of test/apps/serve_*_test.cpp, and the CLI's JSON as
// the API should answer it.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "serve_process.hpp"

#include <httplib.h>  // last: its <resolv.h> macros would break headers included after it

namespace foldkit::test {

// A `foldkit serve --port 0` process on its own root folder, stopped (SIGTERM, then SIGKILL) at
// the end of the test.
class Server {
 public:
  explicit Server(const std::string& name, const std::vector<std::string>& extra = {})
      : root_(fresh_root(name)), process_(foldkit::test::cli_path(), root_, root_ + ".log", extra) {}

  int port() const { return process_.port(); }
  const std::string& root() const { return root_; }
  std::string path(const std::string& name) const { return root_ + "/" + name; }
  std::string log() const { return process_.log(); }

  httplib::Result post(const std::string& verb, const nlohmann::json& body) const {
    httplib::Client c("127.0.0.1", port());
    c.set_read_timeout(120, 0);
    return c.Post(("/api/" + verb).c_str(), body.dump(), "application/json");
  }
  httplib::Client client() const {
    httplib::Client c("127.0.0.1", port());
    c.set_read_timeout(120, 0);
    return c;
  }

 private:
  static std::string fresh_root(const std::string& name) {
    const std::string root = foldkit::test::temp_dir() + "/serve-" + name;
    std::filesystem::remove_all(root);
    std::filesystem::create_directories(root);
    return root;
  }

  std::string root_;
  foldkit::bench::ServeProcess process_;
};

// The CLI's --json with the server's root taken out of paths and the wall-clock keys dropped, as
// the API's result should be.
inline nlohmann::json comparable(nlohmann::json j, const std::string& root) {
  j = nlohmann::json::parse([&] {
    std::string text = j.dump();
    const std::string prefix = root + "/";
    for (std::size_t at; (at = text.find(prefix)) != std::string::npos;) text.erase(at, prefix.size());
    return text;
  }());
  for (const char* key : {"time", "seconds", "planner_time", "wall_time"}) j.erase(key);
  return j;
}

}  // namespace foldkit::test
