// OMPL benchmark logs: the text ompl::tools::Benchmark::saveResultsToStream writes (OMPL 1.5) and
// ompl_benchmark_statistics reads, parsed into BenchLog and written back; shards merged.
#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <stdexcept>

#include <ompl/config.h>

#include "foldkit/bench/log.hpp"

namespace foldkit::bench {

namespace {

std::string default_version() {
  return std::to_string(OMPL_MAJOR_VERSION) + "." + std::to_string(OMPL_MINOR_VERSION) + "." +
         std::to_string(OMPL_PATCH_VERSION);
}

std::vector<std::string> tokens(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> t;
  for (std::string w; in >> w;) t.push_back(w);
  return t;
}

class Reader {
 public:
  Reader(const std::string& text, std::string file) : file_(std::move(file)) {
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) {
      if (!l.empty() && l.back() == '\r') l.pop_back();
      lines_.push_back(l);
    }
  }
  bool done() const { return next_ >= lines_.size(); }
  const std::string& peek() const {
    static const std::string empty;
    return done() ? empty : lines_[next_];
  }
  std::string take(const char* what) {
    if (done()) fail(std::string("the log ends where ") + what + " should be");
    return lines_[next_++];
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw std::invalid_argument(file_ + ":" + std::to_string(std::min(next_ + 1, lines_.size() + 1)) + ": " + what);
  }
  // "N words…": N, the line's tokens after N being `words`.
  long count(const std::string& words, const char* what) {
    const std::string line = take(what);
    const auto t = tokens(line);
    std::string rest;
    for (std::size_t i = 1; i < t.size(); ++i) rest += (i > 1 ? " " : "") + t[i];
    char* end = nullptr;
    const long n = t.empty() ? -1 : std::strtol(t[0].c_str(), &end, 10);
    if (t.empty() || *end != '\0' || n < 0 || rest != words) {
      --next_;
      fail("expected '<count> " + words + "', found '" + line + "'");
    }
    return n;
  }
  double number(const std::string& words, const char* what) {
    const std::string line = take(what);
    const auto t = tokens(line);
    std::string rest;
    for (std::size_t i = 1; i < t.size(); ++i) rest += (i > 1 ? " " : "") + t[i];
    char* end = nullptr;
    const double v = t.empty() ? 0.0 : std::strtod(t[0].c_str(), &end);
    if (t.empty() || *end != '\0' || rest != words) {
      --next_;
      fail("expected '<number> " + words + "', found '" + line + "'");
    }
    return v;
  }
  bool ends_with_words(const std::string& words) const {
    const auto t = tokens(peek());
    std::string rest;
    for (std::size_t i = 1; i < t.size(); ++i) rest += (i > 1 ? " " : "") + t[i];
    return !t.empty() && rest == words;
  }
  std::string block(const char* what) {
    if (take(what) != "<<<|") {
      --next_;
      fail(std::string("expected '<<<|' opening ") + what);
    }
    std::string value;
    for (;;) {
      const std::string l = take(what);
      if (l.rfind("|>>>", 0) == 0) return value;
      value += l + "\n";
    }
  }

 private:
  std::string file_;
  std::vector<std::string> lines_;
  std::size_t next_ = 0;
};

std::string after(const std::string& line, const std::string& prefix) { return line.substr(prefix.size()); }

}  // namespace

const std::string* BenchLog::parameter(const std::string& name_and_type) const {
  for (const auto& [k, v] : parameters)
    if (k == name_and_type) return &v;
  return nullptr;
}

BenchLog parse_bench_log(const std::string& text, const std::string& file) {
  Reader r(text, file);
  BenchLog log;
  {
    const auto t = tokens(r.peek());
    if (t.size() >= 2 && t[1] == "version") {
      const std::string line = r.take("the version");
      const std::string v = line.substr(std::min(line.size(), line.find("version") + 7));
      const auto vt = tokens(v);
      log.version = t[0] + " " + (vt.empty() ? default_version() : vt[0]);
    }
  }
  const std::string exp = r.take("the experiment name");
  if (exp.rfind("Experiment ", 0) != 0) r.fail("expected 'Experiment NAME' (not an OMPL benchmark log?)");
  log.experiment = after(exp, "Experiment ");
  if (r.ends_with_words("experiment properties")) {
    const long n = r.count("experiment properties", "the experiment properties");
    for (long i = 0; i < n; ++i) {
      const std::string l = r.take("an experiment property");
      const auto eq = l.find(" = ");
      if (eq == std::string::npos) r.fail("expected 'name TYPE = value'");
      log.parameters.emplace_back(l.substr(0, eq), l.substr(eq + 3));
    }
  }
  const std::string host = r.take("the host");
  if (host.rfind("Running on ", 0) != 0) r.fail("expected 'Running on HOST'");
  log.host = after(host, "Running on ");
  const std::string start = r.take("the start time");
  if (start.rfind("Starting at ", 0) != 0) r.fail("expected 'Starting at DATE'");
  log.start_time = after(start, "Starting at ");
  log.setup = r.block("the setup");
  if (r.peek() == "<<<|") log.cpu_info = r.block("the CPU information");
  {
    const std::string l = r.take("the random seed");
    const auto t = tokens(l);
    if (t.size() != 5 || l.find(" is the random seed") == std::string::npos) r.fail("expected 'SEED is the random seed'");
    log.seed = t[0];
  }
  log.max_time = r.number("seconds per run", "the time limit");
  log.max_mem = r.number("MB per run", "the memory limit");
  if (r.ends_with_words("runs per planner")) log.run_count = r.count("runs per planner", "the run count");
  log.total_duration = r.number("seconds spent to collect the data", "the total time");
  if (r.ends_with_words("enum type") || r.ends_with_words("enum types")) {
    const long n = r.count(r.ends_with_words("enum type") ? "enum type" : "enum types", "the enums");
    for (long i = 0; i < n; ++i) log.enums.push_back(r.take("an enum"));
  }
  const long planners = r.count("planners", "the planner count");
  for (long p = 0; p < planners; ++p) {
    BenchLog::Planner pl;
    pl.name = r.take("a planner name");
    const long common = r.count("common properties", "the common properties");
    for (long i = 0; i < common; ++i) pl.common.push_back(r.take("a common property"));
    const long props = r.count("properties for each run", "the run properties");
    for (long i = 0; i < props; ++i) {
      pl.properties.push_back(r.take("a run property"));
      if (tokens(pl.properties.back()).size() < 2) r.fail("expected 'name TYPE'");
    }
    const long runs = r.count("runs", "the run count");
    for (long i = 0; i < runs; ++i) {
      const std::string l = r.take("a run");
      std::vector<std::string> values;
      std::size_t b = 0;
      for (std::size_t e; (e = l.find("; ", b)) != std::string::npos; b = e + 2) values.push_back(l.substr(b, e - b));
      if (b != l.size() && !(b + 1 == l.size() && l[b] == ';')) r.fail("a run line must end with '; '");
      if (static_cast<long>(values.size()) != props)
        r.fail("run " + std::to_string(i + 1) + " of " + pl.name + " holds " + std::to_string(values.size()) +
               " values for " + std::to_string(props) + " properties");
      pl.runs.push_back(std::move(values));
    }
    if (r.peek() != ".") {
      const long n = r.count("progress properties for each run", "the progress properties");
      for (long i = 0; i < n; ++i) pl.progress_properties.push_back(r.take("a progress property"));
      const long pr = r.count("runs", "the progress runs");
      for (long i = 0; i < pr; ++i) pl.progress_runs.push_back(r.take("a progress run"));
    }
    if (r.take("the planner's closing '.'") != ".") r.fail("expected '.' after the runs of " + pl.name);
    log.planners.push_back(std::move(pl));
  }
  return log;
}

std::string write_bench_log(const BenchLog& log) {
  std::ostringstream out;
  out.precision(12);
  const auto vt = tokens(log.version);
  out << (vt.empty() ? "OMPL" : vt[0]) << " version " << (vt.size() > 1 ? vt[1] : default_version()) << '\n';
  out << "Experiment " << log.experiment << '\n';
  out << log.parameters.size() << " experiment properties\n";
  for (const auto& [k, v] : log.parameters) out << k << " = " << v << '\n';
  out << "Running on " << log.host << '\n' << "Starting at " << log.start_time << '\n';
  out << "<<<|\n" << log.setup << "|>>>\n";
  out << "<<<|\n" << log.cpu_info << "|>>>\n";
  out << log.seed << " is the random seed\n";
  out << log.max_time << " seconds per run\n" << log.max_mem << " MB per run\n";
  out << log.run_count << " runs per planner\n";
  out << log.total_duration << " seconds spent to collect the data\n";
  out << log.enums.size() << (log.enums.size() == 1 ? " enum type\n" : " enum types\n");
  for (const auto& e : log.enums) out << e << '\n';
  out << log.planners.size() << " planners\n";
  for (const auto& p : log.planners) {
    out << p.name << '\n' << p.common.size() << " common properties\n";
    for (const auto& c : p.common) out << c << '\n';
    out << p.properties.size() << " properties for each run\n";
    for (const auto& c : p.properties) out << c << '\n';
    out << p.runs.size() << " runs\n";
    for (const auto& run : p.runs) {
      for (const auto& v : run) out << v << "; ";
      out << '\n';
    }
    if (!p.progress_properties.empty()) {
      out << p.progress_properties.size() << " progress properties for each run\n";
      for (const auto& c : p.progress_properties) out << c << '\n';
      out << p.progress_runs.size() << " runs\n";
      for (const auto& l : p.progress_runs) out << l << '\n';
    }
    out << ".\n";
  }
  return out.str();
}

namespace {

std::pair<long, long> shard_of(const BenchLog& log, const std::string& file) {
  const std::string* s = log.parameter("shard STRING");
  if (!s) return {1, 1};
  long k = 0, n = 0;
  char slash = 0;
  std::istringstream in(*s);
  if (!(in >> k >> slash >> n) || slash != '/' || k < 1 || k > n)
    throw std::invalid_argument(file + ": the shard parameter '" + *s + "' is not K/N");
  return {k, n};
}

// Planner settings agree when they name the same keys with the same values, except OMPL's
// projection cell sizes, which SpaceInformation estimates from random samples in every process.
bool same_settings(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto ka = a[i].substr(0, a[i].find(" = ")), kb = b[i].substr(0, b[i].find(" = "));
    if (ka != kb) return false;
    if (a[i] != b[i] && ka.rfind("projection.cellsize", 0) != 0) return false;
  }
  return true;
}

std::string param_or(const BenchLog& log, const std::string& key) {
  const std::string* v = log.parameter(key);
  return v ? *v : "(none)";
}

}  // namespace

namespace {

// The name of shard i in messages: its file, or "log N".
std::string shard_name(const std::vector<std::string>& files, std::size_t i) {
  return i < files.size() ? files[i] : "log " + std::to_string(i + 1);
}

// The planner names of the benchmark's "planners" parameter, in order (empty without it).
std::vector<std::string> listed_planners(const BenchLog& log) {
  std::vector<std::string> order;
  if (const std::string* p = log.parameter("planners STRING")) {
    std::istringstream in(*p);
    for (std::string name; std::getline(in, name, ',');) order.push_back(name);
  }
  return order;
}

// Checks that the logs are shards of one experiment (std::invalid_argument naming the files
// otherwise) and returns how many shards it was split into.
long check_shards(const std::vector<BenchLog>& shards, const std::vector<std::string>& files) {
  auto file = [&](std::size_t i) { return shard_name(files, i); };
  const BenchLog& first = shards.front();
  const long n = shard_of(first, file(0)).second;
  std::map<long, std::size_t> seen;
  for (std::size_t i = 0; i < shards.size(); ++i) {
    const BenchLog& s = shards[i];
    if (s.experiment != first.experiment)
      throw std::invalid_argument("merge: " + file(i) + " holds experiment '" + s.experiment + "', " + file(0) + " '" +
                                  first.experiment + "'");
    const auto [k, count] = shard_of(s, file(i));
    if (count != n)
      throw std::invalid_argument("merge: " + file(i) + " is shard " + std::to_string(k) + "/" + std::to_string(count) +
                                  " but " + file(0) + " belongs to a split into " + std::to_string(n));
    if (seen.count(k))
      throw std::invalid_argument("merge: " + file(i) + " and " + file(seen[k]) + " are both shard " + std::to_string(k) +
                                  "/" + std::to_string(n) + " of " + s.experiment);
    seen[k] = i;
    for (const char* key : {"suite STRING", "scene_seed INTEGER", "planners STRING", "space STRING", "simplify BOOLEAN"})
      if (param_or(s, key) != param_or(first, key))
        throw std::invalid_argument("merge: " + file(i) + " and " + file(0) + " differ in '" + key + "' (" + param_or(s, key) +
                                    " vs " + param_or(first, key) + "): not shards of one benchmark");
    if (s.max_time != first.max_time || s.run_count != first.run_count)
      throw std::invalid_argument("merge: " + file(i) + " and " + file(0) +
                                  " differ in the time limit or the runs per planner: not shards of one benchmark");
  }
  // A shard writes no log of a scene when none of that scene's runs fell to it (few runs, many
  // shards), so a missing shard is an error only when runs are missing.
  std::size_t runs_found = 0;
  for (const auto& s : shards)
    for (const auto& p : s.planners) runs_found += p.runs.size();
  const std::size_t planner_count = listed_planners(first).size();
  const bool all_runs = planner_count > 0 && first.run_count > 0 &&
                        runs_found >= planner_count * static_cast<std::size_t>(first.run_count);
  for (long k = 1; k <= n && !all_runs; ++k)
    if (!seen.count(k))
      throw std::invalid_argument("merge: shard " + std::to_string(k) + "/" + std::to_string(n) + " of " + first.experiment +
                                  " is missing");
  return n;
}

// Planners in the benchmark's order (the "planners" parameter), else in order of appearance.
std::vector<std::string> merged_planner_order(const std::vector<BenchLog>& shards) {
  const std::vector<std::string> order = listed_planners(shards.front());
  std::map<std::string, std::size_t> rank;
  for (std::size_t i = 0; i < order.size(); ++i) rank["geometric_" + order[i]] = i;
  std::vector<std::string> names;
  for (const auto& s : shards)
    for (const auto& p : s.planners)
      if (std::find(names.begin(), names.end(), p.name) == names.end()) names.push_back(p.name);
  std::stable_sort(names.begin(), names.end(), [&](const std::string& a, const std::string& b) {
    const std::size_t ra = rank.count(a) ? rank[a] : order.size(), rb = rank.count(b) ? rank[b] : order.size();
    return ra < rb;
  });
  return names;
}

// Puts the runs in the order of the unsharded benchmark (by run index) and refuses a run that
// two shards hold.
void order_runs(BenchLog::Planner& merged, const std::vector<std::string>& progress_lines, const std::string& experiment) {
  const auto idx = std::find(merged.properties.begin(), merged.properties.end(), "run index INTEGER");
  std::vector<std::size_t> perm(merged.runs.size());
  std::iota(perm.begin(), perm.end(), 0);
  if (idx != merged.properties.end()) {
    const auto col = static_cast<std::size_t>(idx - merged.properties.begin());
    std::stable_sort(perm.begin(), perm.end(), [&](std::size_t a, std::size_t b) {
      return std::atol(merged.runs[a][col].c_str()) < std::atol(merged.runs[b][col].c_str());
    });
    std::set<long> indices;
    for (const auto& run : merged.runs)
      if (!indices.insert(std::atol(run[col].c_str())).second)
        throw std::invalid_argument("merge: run " + run[col] + " of " + merged.name + " in " + experiment +
                                    " appears in two shards");
  }
  std::vector<std::vector<std::string>> runs;
  for (std::size_t i : perm) {
    runs.push_back(merged.runs[i]);
    if (!merged.progress_properties.empty()) merged.progress_runs.push_back(progress_lines[i]);
  }
  merged.runs = std::move(runs);
}

// One planner's runs from every shard, its header from the first shard that has it.
BenchLog::Planner merge_planner(const std::string& name, const std::vector<BenchLog>& shards,
                                const std::vector<std::string>& files) {
  auto file = [&](std::size_t i) { return shard_name(files, i); };
  BenchLog::Planner merged;
  std::size_t from = 0;
  bool have = false;
  std::vector<std::string> progress_lines;
  for (std::size_t i = 0; i < shards.size(); ++i)
    for (const auto& p : shards[i].planners) {
      if (p.name != name) continue;
      if (!have) {
        merged = p;
        merged.runs.clear();
        merged.progress_runs.clear();
        from = i;
        have = true;
      } else if (p.properties != merged.properties) {
        throw std::invalid_argument("merge: " + name + " records other run properties in " + file(i) + " than in " +
                                    file(from) + " (logs of different foldkit or OMPL versions?)");
      } else if (!same_settings(p.common, merged.common)) {
        throw std::invalid_argument("merge: " + name + " is configured differently in " + file(i) + " and " + file(from));
      } else if (p.progress_properties != merged.progress_properties) {
        throw std::invalid_argument("merge: " + name + " records other progress properties in " + file(i) + " than in " +
                                    file(from));
      }
      for (std::size_t r = 0; r < p.runs.size(); ++r) {
        merged.runs.push_back(p.runs[r]);
        progress_lines.push_back(r < p.progress_runs.size() ? p.progress_runs[r] : "");
      }
    }
  order_runs(merged, progress_lines, shards.front().experiment);
  return merged;
}

}  // namespace

BenchLog merge_bench_logs(const std::vector<BenchLog>& shards, const std::vector<std::string>& files) {
  if (shards.empty()) throw std::invalid_argument("merge: no logs");
  const long n = check_shards(shards, files);
  BenchLog out = shards.front();
  out.planners.clear();
  out.total_duration = 0.0;
  for (const auto& s : shards) out.total_duration += s.total_duration;
  for (auto& [k, v] : out.parameters)
    if (k == "shard STRING") v = "1/1";
  if (n > 1) out.parameters.emplace_back("merged_shards INTEGER", std::to_string(n));
  for (const std::string& name : merged_planner_order(shards)) out.planners.push_back(merge_planner(name, shards, files));
  return out;
}

}  // namespace foldkit::bench
