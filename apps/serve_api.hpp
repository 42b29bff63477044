#pragma once
// The JSON API of `foldkit serve` (docs/SERVE.md) on a cpp-httplib server.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "serve_paths.hpp"
#include "serve_verbs.hpp"
#include "verb_pool.hpp"

namespace httplib {
class Server;
struct Request;
struct Response;
}

namespace foldkit::apps {

struct ServeOptions {
  std::filesystem::path root = ".";     // every file a request names is under it
  std::size_t max_body = 256u << 20;    // bytes of a request body; larger ones are refused (413)
  std::size_t max_file = 64u << 20;     // bytes a GET /api/file returns at most
  WorkLimits limits;
  std::size_t workers = default_verb_workers();  ///< verbs run at once (--workers; default: one per core)
  std::size_t queue = 64;               ///< verb requests that wait for a worker at most (--queue); more are refused (503)
  std::vector<std::string> files;       // files named on the command line (under root), listed by GET /api
  std::filesystem::path web;            // the browser app's folder (web/); empty: the API only
  std::string host = "127.0.0.1";       // the address it listens on: on a loopback one, only loopback names are served
};

class ServeApi {
 public:
  // Throws std::invalid_argument when the root is not a folder or a file is not under it.
  explicit ServeApi(ServeOptions options);

  // Installs the routes, the body limit and the HTTP threads (http_threads()) on `server`.
  void install(httplib::Server& server);

  /// Threads of cpp-httplib's pool: one per worker and per place in the queue, so that a queued
  /// verb request waits in its handler rather than unread behind the others, and kHttpSpare more,
  /// so that GET /api, the files and the app are answered while every worker and place is taken.
  std::size_t http_threads() const { return options_.workers + options_.queue + kHttpSpare; }
  /// Threads beyond the workers and the queue (also httplib's own default pool size).
  static constexpr std::size_t kHttpSpare = 8;

  /// Once `server` is bound (after install()): lets kListenBacklog connections wait to be
  /// accepted rather than cpp-httplib's 5, which a burst of clients overflowed (the kernel then
  /// dropped connections unanswered while the verbs kept the cores busy). Linux takes a second
  /// listen() on a listening socket as a new backlog, capped at net.core.somaxconn.
  void deepen_backlog() const;
  /// Connections the kernel holds for the server to accept (see deepen_backlog()).
  static constexpr int kListenBacklog = 1024;

  const RootedPaths& paths() const { return paths_; }

 private:
  void index(httplib::Response& res) const;                                       // GET /api
  void list_files(const httplib::Request& req, httplib::Response& res) const;     // GET /api/files
  void get_file(const httplib::Request& req, httplib::Response& res) const;       // GET /api/file
  void put_file(const httplib::Request& req, httplib::Response& res) const;       // PUT /api/file
  void post_verb(const httplib::Request& req, httplib::Response& res);            // POST /api/VERB
  void get_app_file(const httplib::Request& req, httplib::Response& res) const;   // GET / and the app's files
  std::optional<VerbRun> run_in_turn(const std::string& verb, const std::vector<std::string>& words,
                                     VerbPool::Clock::time_point deadline, httplib::Response& res);
  std::string past_time_limit(const std::string& verb) const;  // the 504's message

  ServeOptions options_;
  RootedPaths paths_;
  std::unique_ptr<RootedPaths> web_;  // options_.web; null without one
  std::vector<std::string> files_;  // options_.files, relative to the root
  std::string executable_;          // the foldkit CLI the verbs run as
  VerbPool pool_;                   // at most options_.workers verbs at once, options_.queue waiting
  int listening_ = -1;              // the server's socket, as install()'s socket options saw it
};

}  // namespace foldkit::apps
