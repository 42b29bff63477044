#pragma once
// OMPL benchmark logs: read, written back unchanged, and merged across shards.
#include <string>
#include <utility>
#include <vector>

namespace foldkit::bench {

// One log as ompl::tools::Benchmark writes it (OMPL 1.5), kept close to the text so that it can
// be written back unchanged; `ompl_benchmark_statistics` reads what write_bench_log writes.
struct BenchLog {
  struct Planner {
    std::string name;
    std::vector<std::string> common;      // "key = value"
    std::vector<std::string> properties;  // "name TYPE"
    std::vector<std::vector<std::string>> runs;  // one value per property ("" when missing)
    std::vector<std::string> progress_properties;
    std::vector<std::string> progress_runs;  // one line per run
  };
  std::string version = "OMPL 1.5.2";  // library and version (Debian's OMPL writes none)
  std::string experiment;
  std::vector<std::pair<std::string, std::string>> parameters;  // "name TYPE", value
  std::string host, start_time, setup, cpu_info, seed;
  double max_time = 0.0, max_mem = 0.0, total_duration = 0.0;
  long run_count = 0;
  std::vector<std::string> enums;  // "name|value0|value1|…"
  std::vector<Planner> planners;

  const std::string* parameter(const std::string& name_and_type) const;
};

// std::invalid_argument "FILE:LINE: what is wrong" for text that is not such a log.
BenchLog parse_bench_log(const std::string& text, const std::string& file = "log");
std::string write_bench_log(const BenchLog& log);
// Joins shard logs of one scene: runs concatenated per planner (ordered by "run index" when
// present), the header of the first, durations summed. std::invalid_argument when the logs are
// not shards of one experiment (experiment, planners, properties, settings, seed, time limit or
// shard count differ; a shard twice or missing).
BenchLog merge_bench_logs(const std::vector<BenchLog>& shards, const std::vector<std::string>& files);

}  // namespace foldkit::bench
