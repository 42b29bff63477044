#pragma once
// The JSON API of `foldkit serve` (docs/SERVE.md) on a cpp-httplib server.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "serve_paths.hpp"
#include "serve_verbs.hpp"

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
  std::vector<std::string> files;       // files named on the command line (under root), listed by GET /api
  std::filesystem::path web;            // the browser app's folder (web/); empty: the API only
  std::string host = "127.0.0.1";       // the address it listens on: on a loopback one, only loopback names are served
};

class ServeApi {
 public:
  // Throws std::invalid_argument when the root is not a folder or a file is not under it.
  explicit ServeApi(ServeOptions options);

  // Installs the routes and the body limit on `server`.
  void install(httplib::Server& server);

  const RootedPaths& paths() const { return paths_; }

 private:
  void index(httplib::Response& res) const;                                       // GET /api
  void list_files(const httplib::Request& req, httplib::Response& res) const;     // GET /api/files
  void get_file(const httplib::Request& req, httplib::Response& res) const;       // GET /api/file
  void put_file(const httplib::Request& req, httplib::Response& res) const;       // PUT /api/file
  void post_verb(const httplib::Request& req, httplib::Response& res);            // POST /api/VERB
  void get_app_file(const httplib::Request& req, httplib::Response& res) const;   // GET / and the app's files

  ServeOptions options_;
  RootedPaths paths_;
  std::unique_ptr<RootedPaths> web_;  // options_.web; null without one
  std::vector<std::string> files_;  // options_.files, relative to the root
  std::string executable_;          // the foldkit CLI the verbs run as
  std::mutex job_;                  // one verb at a time
};

}  // namespace foldkit::apps
