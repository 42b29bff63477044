// foldkit serve: the JSON API of docs/SERVE.md on a local HTTP server (cpp-httplib).
#include <iostream>

#include "cli_common.hpp"
#include "serve_api.hpp"

// Last: httplib.h brings <resolv.h>, whose macro `_res` breaks Eigen's headers included after it.
#include <httplib.h>

namespace foldkit::apps {

namespace {

// The installed app (PREFIX/share/foldkit/web beside PREFIX/bin/foldkit) first, then the source
// tree's web/ of the build this executable came from, once npm has installed three.js there.
std::string default_web_folder() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto installed = exe.parent_path().parent_path() / "share" / "foldkit" / "web";
    if (std::filesystem::is_regular_file(installed / "index.html", ec)) return installed.string();
  }
#ifdef FOLDKIT_WEB_SOURCE_DIR
  const std::filesystem::path source = FOLDKIT_WEB_SOURCE_DIR;
  if (std::filesystem::is_regular_file(source / "index.html", ec) &&
      std::filesystem::is_regular_file(source / "node_modules" / "three" / "build" / "three.module.js", ec))
    return source.string();
#endif
  return "";
}

}  // namespace

Command add_serve(CLI::App& root) {
  struct Options {
    std::vector<std::string> files;
    std::string host = "127.0.0.1", root = ".", web = default_web_folder();
    int port = 8080;
    double max_body_mb = 256.0, max_plan_time = 60.0, max_time = 300.0;
    std::size_t workers = ServeOptions{}.workers, queue = ServeOptions{}.queue;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* app = root.add_subcommand("serve", "Serve the JSON API of the verbs on a local HTTP server (docs/SERVE.md)");
  reads(app->add_option("files", opt->files, "Files under --root to list as open (GET /api)"));
  app->add_option("--host", opt->host, "Address to listen on (127.0.0.1: this machine only)")->capture_default_str();
  app->add_option("--port", opt->port, "Port (0: any free one, printed on stderr)")->check(CLI::Range(0, 65535))->capture_default_str();
  app->add_option("--root", opt->root, "Folder every file a request names lies in")->capture_default_str();
  app->add_option("--web", opt->web, "The browser app's folder (\"\": serve the API only)")->capture_default_str();
  app->add_option("--max-body", opt->max_body_mb, "Largest request body, MB")->check(CLI::Range(0.001, 1024.0))->capture_default_str();
  app->add_option("--max-plan-time", opt->max_plan_time, "Seconds a plan request may ask for at most")
      ->check(CLI::Range(0.01, 3600.0))
      ->capture_default_str();
  app->add_option("--max-time", opt->max_time, "Seconds a verb may run before it is stopped (HTTP 504)")
      ->check(CLI::Range(0.1, 86400.0))
      ->capture_default_str();
  // Each verb is a child process on a core of its own; requests beyond the workers wait in the
  // queue (each holds an HTTP thread and its connection), and beyond the queue get 503.
  app->add_option("--workers", opt->workers, "Verbs run at once (default: one per core)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1024}))
      ->capture_default_str();
  app->add_option("--queue", opt->queue, "Verb requests that wait for a worker at most; more get 503 with Retry-After")
      ->check(CLI::Range(std::size_t{0}, std::size_t{1024}))
      ->capture_default_str();
  return {app, [opt] {
            ServeOptions o;
            o.root = opt->root;
            o.files = opt->files;
            o.web = opt->web;
            o.host = opt->host;
            o.max_body = static_cast<std::size_t>(opt->max_body_mb * 1024 * 1024);
            o.limits.max_plan_time = opt->max_plan_time;
            o.limits.max_time = opt->max_time;
            o.workers = opt->workers;
            o.queue = opt->queue;
            std::unique_ptr<ServeApi> api;
            try {
              api = std::make_unique<ServeApi>(o);
            } catch (const std::invalid_argument& e) {
              throw UsageError(e.what());
            }
            httplib::Server server;
            api->install(server);
            const int port = opt->port == 0 ? server.bind_to_any_port(opt->host) : (server.bind_to_port(opt->host, opt->port) ? opt->port : -1);
            if (port < 0) throw UsageError("cannot listen on " + opt->host + ":" + std::to_string(opt->port));
            api->deepen_backlog();
            std::cerr << "foldkit serve: http://" << opt->host << ':' << port << (opt->web.empty() ? "/api" : "/") << " (root "
                      << api->paths().root().string() << "); Ctrl-C stops it" << std::endl;
            return server.listen_after_bind() ? kOk : kInvalidInput;
          }};
}

}  // namespace foldkit::apps
