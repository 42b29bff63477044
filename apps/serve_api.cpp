#include "serve_api.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_common.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/formats.hpp"
#include "foldkit/planners/plan.hpp"
#include "foldkit/planners/planner_factory.hpp"

// Last: httplib.h brings <resolv.h>, whose macro `_res` breaks Eigen's headers included after it.
#include <httplib.h>

namespace foldkit::apps {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

void reply(httplib::Response& res, int status, const json& body) {
  res.status = status;
  res.set_content(body.dump(2) + "\n", "application/json");
}

void refuse(httplib::Response& res, int status, const std::string& message, int exit = kUsage) {
  reply(res, status, {{"error", message}, {"exit", exit}});
}

// A refused path: 404 (exit 1, as the CLI for a missing file) or 400 (exit 2: the request's fault).
void refuse(httplib::Response& res, const PathRefused& e) { refuse(res, e.missing ? 404 : 400, e.what(), e.missing ? kInvalidInput : kUsage); }

// Form encodings make httplib read the body as fields (and cap it at 8 KB); a file or a request
// object is sent as it is.
bool form_encoded(const httplib::Request& req) {
  const std::string type = req.get_header_value("Content-Type");
  return type.rfind("multipart/form-data", 0) == 0 || type.rfind("application/x-www-form-urlencoded", 0) == 0;
}

// A JSON body nested at most 64 deep (deeper values would be copied and printed recursively).
json parse_request(const std::string& body) {
  return json::parse(body, [](int depth, json::parse_event_t, json&) {
    if (depth > 64) throw std::invalid_argument("nested more than 64 deep");
    return true;
  });
}

// Files a client may write or read as text: the formats of io's table, load cases and the
// results verbs write (JSON, CSV).
bool text_format(const std::string& path) {
  if (io::format_of(path)) return true;
  for (const char* e : {".loadcase", ".json", ".csv"})
    if (has_extension(path, e)) return true;
  return false;
}

// A file of the root as data: never as a page or a script, whatever its name (GET /api/file adds
// nosniff and a sandbox, so not even an SVG runs script on the API's origin).
std::string content_type(const std::string& path) {
  if (const io::FileFormat* f = io::format_of(path)) return f->media_type;
  if (has_extension(path, ".json")) return "application/json";
  return "text/plain; charset=utf-8";
}

std::string app_content_type(const std::string& path) {
  if (has_extension(path, ".html")) return "text/html; charset=utf-8";
  if (has_extension(path, ".js")) return "text/javascript; charset=utf-8";
  if (has_extension(path, ".css")) return "text/css; charset=utf-8";
  if (has_extension(path, ".png")) return "image/png";
  return content_type(path);
}

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

bool loopback_name(const std::string& host) {
  return host == "localhost" || host == "::1" || host == "[::1]" || host.rfind("127.", 0) == 0;
}

// Why a request did not come from this server's own pages or a local program: a web page elsewhere
// that posts to it (CSRF) or a name that resolves here (DNS rebinding) must not run verbs or read
// files. Empty when it may be served.
std::string foreign_request(const httplib::Request& req, const std::string& bound) {
  const std::string host = req.get_header_value("Host");
  std::string name = host.substr(0, host[0] == '[' ? host.find(']') + 1 : host.rfind(':'));
  if (name.empty()) name = host;
  if (loopback_name(bound) && !loopback_name(lowercase(name)) && lowercase(name) != lowercase(bound))
    return "Host '" + host + "' is not this machine: the server listens on " + bound + " and answers only its own names";
  const std::string origin = req.get_header_value("Origin");
  if (!origin.empty() && origin != "http://" + host)
    return "requests from pages of " + origin + " are refused: only the server's own page may use the API";
  if (req.get_header_value("Sec-Fetch-Site") == "cross-site") return "cross-site requests are refused";
  return "";
}

// The CLI's messages name files by the absolute paths the server passed; a client named them
// relative to the root.
std::string relative_messages(std::string text, const RootedPaths& paths) {
  const std::string prefix = paths.root().string() + "/";
  for (std::size_t at; (at = text.find(prefix)) != std::string::npos;) text.erase(at, prefix.size());
  return text;
}

// What GET serves of the app's folder: the page, its modules and three.js's (never the browser
// tests' packages nor anything else npm put there).
bool app_file(const std::string& path) {
  if (path == "index.html" || path == "style.css") return true;
  bool known = false;
  for (const char* e : {".js", ".css", ".svg", ".png", ".html"}) known = known || has_extension(path, e);
  if (!known) return false;
  for (const char* folder : {"src/", "node_modules/three/build/", "node_modules/three/examples/jsm/"})
    if (path.rfind(folder, 0) == 0) return true;
  return false;
}

// One read of the whole file: a character at a time (istreambuf_iterator) took 0.43 s for a
// 40 × 40 Miura-ori's 49 MB fold, before the first byte went out.
std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::error_code ec;
  const auto size = fs::file_size(p, ec);
  std::string bytes(ec ? 0 : static_cast<std::size_t>(size), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  // A file that grew since its size was taken: the rest too.
  if (in) bytes.append(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return bytes;
}

std::string first_line(const std::string& text) {
  const auto end = text.find('\n');
  return end == std::string::npos ? text : text.substr(0, end);
}

json listing(const fs::path& folder, const RootedPaths& paths) {
  json entries = json::array();
  std::vector<fs::directory_entry> all(fs::directory_iterator(folder), fs::directory_iterator{});
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.path().filename() < b.path().filename(); });
  for (const auto& e : all) {
    std::error_code ec;
    if (e.is_symlink(ec)) continue;  // links may lead out of the root; they are not listed
    if (e.is_directory(ec)) {
      entries.push_back({{"name", e.path().filename().string()}, {"type", "folder"}});
    } else if (e.is_regular_file(ec)) {
      entries.push_back({{"name", e.path().filename().string()}, {"type", "file"}, {"bytes", e.file_size(ec)}});
    }
  }
  return {{"folder", paths.relative(folder) == "." ? "" : paths.relative(folder)}, {"entries", entries}};
}

// The planners `plan --planner` takes, from the planners' own table (planner_names()), so that the
// page offers what the CLI plans with and a planner added there is served with no other edit.
// `default`: PlanOptions's, the one a plan without `planner` runs; `refused`: why make_planner()
// refuses one on any crease pattern (planner_refusal()), empty for one it makes.
json served_planners() {
  const std::string chosen = planners::canonical_planner(planners::PlanOptions{}.planner);
  json list = json::array();
  for (const std::string& name : planners::planner_names())
    list.push_back({{"name", name}, {"default", name == chosen}, {"refused", planners::planner_refusal(name)}});
  return list;
}

}  // namespace

ServeApi::ServeApi(ServeOptions options)
    : options_(std::move(options)), paths_(options_.root), executable_(this_executable()), pool_(options_.workers, options_.queue) {
  for (const auto& f : options_.files) {
    try {
      files_.push_back(paths_.relative(paths_.input(f)));
    } catch (const PathRefused& e) {
      throw std::invalid_argument(e.what());
    }
  }
  if (!options_.web.empty()) {
    if (!fs::is_regular_file(options_.web / "index.html"))
      throw std::invalid_argument(options_.web.string() + ": not the browser app's folder (it has no index.html)");
    web_ = std::make_unique<RootedPaths>(options_.web);
  }
}

void ServeApi::install(httplib::Server& server) {
  server.set_payload_max_length(options_.max_body);
  // httplib's pool (by default max(8, cores - 1) threads) serves one connection per thread and
  // queues the rest unread: with fewer threads than workers + queue, queued verbs would hold
  // every thread and GET /api and the app's files would wait behind them (http_threads()).
  server.new_task_queue = [threads = http_threads()] { return new httplib::ThreadPool(threads); };
  // httplib's default also sets SO_REUSEPORT, with which a second server binds a port that is in
  // use and the two share its requests; a port in use must be an error.
  // It is called on the listening socket before bind (on each address tried; the last is the one
  // bound), which deepen_backlog() then listens on again.
  server.set_socket_options([this](socket_t sock) {
    int yes = 1;
    setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof(yes));
    listening_ = sock;
  });

  // Answers go uncompressed: Debian's cpp-httplib 0.11 compresses with Brotli at its slowest
  // quality, 2 s for three.js's 1.5 MB module and 80 s for a 49 MB fold sequence (gzip: 0.06 s and
  // 0.5 s; none: 0.01 s and 0.2 s), and on this machine's own network compression gains nothing.
  // The library asks the request's Accept-Encoding, and its pre-routing hook sees that request
  // before any handler (the request object is not const, only the hook's view of it).
  // The same hook refuses requests from elsewhere (foreign_request), and verbs not sent as JSON: a
  // page of another site can post a form or text/plain without the browser asking first.
  server.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    const_cast<httplib::Request&>(req).headers.erase("Accept-Encoding");
    const std::string why = foreign_request(req, options_.host);
    if (!why.empty()) {
      refuse(res, 403, why);
      return httplib::Server::HandlerResponse::Handled;
    }
    if (req.method == "POST" && req.get_header_value("Content-Type").rfind("application/json", 0) != 0) {
      refuse(res, 415, "send the verb's arguments as a JSON object with Content-Type: application/json");
      return httplib::Server::HandlerResponse::Handled;
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });

  // A handler that throws (out of memory, a file system error) answers 500 with the reason; the
  // server goes on.
  server.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr ep) {
    std::string what = "internal error";
    try {
      std::rethrow_exception(ep);
    } catch (const std::exception& e) {
      what += std::string(": ") + e.what();
    } catch (...) {
    }
    refuse(res, 500, what, kInvalidInput);
  });

  // Unknown paths and httplib's own refusals (413 and the like) answer in JSON too.
  server.set_error_handler([](const httplib::Request& req, httplib::Response& res) {
    if (!res.body.empty()) return;
    const std::string why = res.status == 404 ? req.path + ": no such endpoint (see GET /api)"
                          : res.status == 413 ? "the request body is larger than the server accepts (foldkit serve --max-body)"
                                              : "HTTP " + std::to_string(res.status);
    refuse(res, res.status, why);
  });

  server.Get("/api", [this](const httplib::Request&, httplib::Response& res) { index(res); });
  server.Get("/api/files", [this](const httplib::Request& req, httplib::Response& res) { list_files(req, res); });
  server.Get("/api/file", [this](const httplib::Request& req, httplib::Response& res) { get_file(req, res); });
  server.Put("/api/file", [this](const httplib::Request& req, httplib::Response& res) { put_file(req, res); });
  server.Post(R"(/api/([a-z]+))", [this](const httplib::Request& req, httplib::Response& res) { post_verb(req, res); });
  server.Get(R"(/(?!api(/|$)).*)", [this](const httplib::Request& req, httplib::Response& res) { get_app_file(req, res); });
}

void ServeApi::deepen_backlog() const {
  if (listening_ >= 0) ::listen(listening_, kListenBacklog);
}

void ServeApi::index(httplib::Response& res) const {
  json verbs = json::array();
  for (const auto& v : served_verbs()) verbs.push_back(v.verb);
  // io's table of formats, so that the page opens what the CLI opens (a new format is one entry there).
  json formats = json::array();
  for (const io::FileFormat& f : io::file_formats())
    formats.push_back({{"name", f.name},
                       {"extension", f.extension},
                       {"reads_patterns", io::reads_patterns(f)},
                       {"writes_patterns", io::writes_patterns(f)},
                       {"sequence", f.sequence}});
  reply(res, 200, {{"foldkit", "0.1.0"}, {"verbs", verbs}, {"formats", formats}, {"planners", served_planners()}, {"files", files_},
                   {"max_body", options_.max_body},
                   {"max_time", options_.limits.max_time}, {"max_plan_time", options_.limits.max_plan_time},
                   {"workers", options_.workers}, {"queue", options_.queue}});
}

void ServeApi::list_files(const httplib::Request& req, httplib::Response& res) const {
  try {
    reply(res, 200, listing(paths_.folder(req.get_param_value("folder")), paths_));
  } catch (const PathRefused& e) {
    refuse(res, e);
  }
}

void ServeApi::get_file(const httplib::Request& req, httplib::Response& res) const {
  try {
    const std::string name = req.get_param_value("path");
    const fs::path p = paths_.input(name);
    if (fs::file_size(p) > options_.max_file) return refuse(res, 413, name + ": larger than the server returns", kInvalidInput);
    std::string bytes = read_file(p);
    // A compressed file (.cmml.gz, told by its magic bytes as io reads it) is sent as stored, as
    // its format's text with gzip content coding: the browser's fetch decompresses it.
    const bool gzip = bytes.size() >= 2 && bytes[0] == '\x1f' && bytes[1] == '\x8b';
    res.set_content(std::move(bytes), content_type(name));
    if (gzip) res.set_header("Content-Encoding", "gzip");
    res.set_header("X-Content-Type-Options", "nosniff");
    res.set_header("Content-Security-Policy", "sandbox");
  } catch (const PathRefused& e) {
    refuse(res, e);
  }
}

void ServeApi::get_app_file(const httplib::Request& req, httplib::Response& res) const {
  if (!web_)
    return refuse(res, 404, "the browser app is not installed with this foldkit (build it with npm, FOLDKIT_BUILD_WEB=ON, or name its folder with --web); the JSON API is at /api", kInvalidInput);
  const std::string name = req.path == "/" ? "index.html" : req.path.substr(1);
  if (!app_file(name)) return refuse(res, 404, req.path + ": not a file of the browser app", kInvalidInput);
  try {
    const fs::path p = web_->input(name);
    res.set_content(read_file(p), app_content_type(name));
    res.set_header("Cache-Control", "no-cache");  // an edited module shows on reload
    res.set_header("X-Content-Type-Options", "nosniff");
  } catch (const PathRefused& e) {
    refuse(res, 404, req.path + ": " + e.what(), kInvalidInput);
  }
}

void ServeApi::put_file(const httplib::Request& req, httplib::Response& res) const {
  try {
    if (form_encoded(req)) return refuse(res, 400, "send the file's bytes as the body, not as a form (Content-Type: " + req.get_header_value("Content-Type") + ")");
    const std::string name = req.get_param_value("path");
    if (!text_format(name))
      return refuse(res, 400, name + ": the server writes only .pmml, .cmml, .fold, .svg, .loadcase, .json and .csv files");
    // The server compresses a .gz name itself (io::write_file_atomic): gzip bytes sent as the body
    // would be stored compressed twice.
    if (req.body.size() >= 2 && req.body[0] == '\x1f' && req.body[1] == '\x8b')
      return refuse(res, 400, name + ": send the file's text, not gzip bytes (the server compresses a .gz name itself)");
    const fs::path p = paths_.output(name);
    io::write_file_atomic(p.string(), req.body);
    reply(res, 200, {{"written", paths_.relative(p)}, {"bytes", req.body.size()}});
  } catch (const PathRefused& e) {
    refuse(res, e);
  } catch (const io::WriteError& e) {
    refuse(res, 500, relative_messages(e.what(), paths_), kInvalidInput);
  }
}

std::string ServeApi::past_time_limit(const std::string& verb) const {
  std::ostringstream out;
  out << verb << ": stopped after the server's limit of " << options_.limits.max_time << " s (foldkit serve --max-time)";
  return out.str();
}

// A worker's turn for the verb: at once when one is free, else after the requests queued before
// it. Answers the request itself and returns nothing when the queue is full (503 with
// Retry-After: a client should come back rather than wait on an open connection) or when the
// deadline came while it waited (504, as for a verb that ran past it: the same limit).
std::optional<VerbRun> ServeApi::run_in_turn(const std::string& verb, const std::vector<std::string>& words,
                                             VerbPool::Clock::time_point deadline, httplib::Response& res) {
  switch (pool_.acquire(deadline)) {
    case VerbPool::Grant::QueueFull: {
      const long retry = pool_.retry_after_seconds();
      refuse(res, 503,
             "busy: all " + std::to_string(pool_.workers()) + " workers run verbs and the queue of " + std::to_string(pool_.queue()) +
                 " is full (foldkit serve --workers, --queue); try again in " + std::to_string(retry) + " s",
             kUsage);
      res.set_header("Retry-After", std::to_string(retry));
      return std::nullopt;
    }
    case VerbPool::Grant::DeadlinePassed:
      refuse(res, 504, past_time_limit(verb), kInvalidInput);
      return std::nullopt;
    case VerbPool::Grant::Granted:
      break;
  }
  VerbPool::Slot slot(pool_);
  const double left = std::chrono::duration<double>(deadline - VerbPool::Clock::now()).count();
  return run_verb(executable_, words, std::max(left, 0.0));
}

void ServeApi::post_verb(const httplib::Request& req, httplib::Response& res) {
  // --max-time counts from the request's arrival: the time it waits for a worker is part of it.
  const auto deadline = VerbPool::Clock::now() + std::chrono::duration_cast<VerbPool::Clock::duration>(
                                                     std::chrono::duration<double>(options_.limits.max_time));
  const std::string verb = req.matches[1];
  const VerbSpec* spec = find_served_verb(verb);
  if (!spec) return refuse(res, 404, verb + ": not a verb the server runs");
  json request;
  try {
    request = req.body.empty() ? json::object() : parse_request(req.body);
  } catch (const std::exception& e) {
    return refuse(res, 400, std::string("the request body is not a JSON object: ") + e.what());
  }
  std::vector<std::string> words;
  try {
    words = command_line(*spec, request, paths_, options_.limits);
  } catch (const PathRefused& e) {
    return refuse(res, e);
  } catch (const UsageError& e) {
    return refuse(res, 400, verb + ": " + e.what());
  }
  const std::optional<VerbRun> ran = run_in_turn(verb, words, deadline, res);
  if (!ran) return;  // refused (503) or out of time while it waited (504)
  const VerbRun& run = *ran;
  if (run.timed_out) return refuse(res, 504, past_time_limit(verb), kInvalidInput);
  if (run.flooded) return refuse(res, 500, verb + ": stopped for printing more than the server keeps", kInvalidInput);
  if (run.exit < 0) return refuse(res, 500, verb + ": ended by signal " + std::to_string(run.signal), kInvalidInput);
  const std::string log = relative_messages(run.err, paths_);
  if (run.exit == kInvalidInput || run.exit == kUsage) {
    json body = {{"error", first_line(log)}, {"exit", run.exit}};
    // validate's JSON lists every problem with its line, for a client to point at each of them.
    if (spec->json && !run.out.empty()) {
      json result = json::parse(relative_messages(run.out, paths_), nullptr, false);
      if (result.is_object()) body["result"] = std::move(result);
    }
    return reply(res, 400, body);
  }
  json body = {{"verb", verb}, {"exit", run.exit}, {"log", log}};
  if (spec->json) {
    try {
      body["result"] = json::parse(relative_messages(run.out, paths_));
    } catch (const json::parse_error&) {
      return refuse(res, 500, verb + " printed no JSON object", kInvalidInput);
    }
  }
  reply(res, 200, body);
}

}  // namespace foldkit::apps
