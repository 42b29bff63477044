#pragma once
/// @file
/// OMPL benchmark logs: read, written back, and merged across shards.
#include <string>
#include <utility>
#include <vector>

namespace foldkit::bench {

/// One log as ompl::tools::Benchmark writes it (OMPL 1.5), kept close to the text so that it can
/// be written back with the same content; `ompl_benchmark_statistics` reads what
/// write_bench_log writes.
struct BenchLog {
  /// One planner's block of the log.
  struct Planner {
    std::string name;                     ///< as OMPL writes it, e.g. "geometric_RRTConnect"
    std::vector<std::string> common;      ///< "key = value"
    std::vector<std::string> properties;  ///< "name TYPE"
    std::vector<std::vector<std::string>> runs;  ///< one value per property ("" when missing)
    std::vector<std::string> progress_properties;  ///< "name TYPE" of the progress properties; empty when none
    std::vector<std::string> progress_runs;  ///< one line per run
  };
  /// Library and version, e.g. "OMPL 1.5.2" (kept when the log has no version line: Debian's
  /// OMPL writes none).
  std::string version = "OMPL 1.5.2";
  std::string experiment;  ///< the experiment's name (foldkit: the scene)
  std::vector<std::pair<std::string, std::string>> parameters;  ///< experiment properties: ("name TYPE", value)
  std::string host,        ///< the machine it ran on
      start_time,          ///< when it started, as OMPL wrote it
      setup,               ///< the setup block's text, each line ending in "\n"
      cpu_info,            ///< the CPU information block's text ("" when the log has none)
      seed;                ///< the random seed, as written
  double max_time = 0.0,       ///< seconds per run
      max_mem = 0.0,           ///< MB per run
      total_duration = 0.0;    ///< seconds spent to collect the data
  long run_count = 0;              ///< runs per planner (0 when the log does not say)
  std::vector<std::string> enums;  ///< "name|value0|value1|…"
  std::vector<Planner> planners;   ///< in log order

  /// The value of the experiment property `name_and_type` ("shard STRING"); null when absent.
  const std::string* parameter(const std::string& name_and_type) const;
};

/// Parses an OMPL benchmark log; optional parts (version line, experiment properties, CPU
/// information, run count, enums, progress properties) may be missing.
/// @param text  the log's content
/// @param file  names the source in error messages only
/// @throws std::invalid_argument "FILE:LINE: what is wrong" for text that is not such a log
BenchLog parse_bench_log(const std::string& text, const std::string& file = "log");
/// The text of `log` in OMPL's format. Every optional line is written (an empty CPU block, 0
/// experiment properties, …), numbers with 12 significant digits, so a parsed log comes back
/// with the same content though not always byte for byte.
std::string write_bench_log(const BenchLog& log);
/// Joins shard logs of one scene: runs concatenated per planner (ordered by "run index" when
/// present), planners in the order of the "planners" property, the header of the first,
/// durations summed; the "shard" property becomes "1/1" and, for more than one shard, a
/// "merged_shards" property records how many. A shard may be missing only when the others hold
/// every run (a shard writes no log of a scene none of whose runs fell to it).
/// @param shards  the logs (at least one)
/// @param files   their names for messages (missing ones are called "log N")
/// @throws std::invalid_argument when there is no log, or the logs are not shards of one
///         experiment (experiment, planners, properties, settings, seed, time limit or shard
///         count differ; a shard or a run twice; a shard missing)
BenchLog merge_bench_logs(const std::vector<BenchLog>& shards, const std::vector<std::string>& files);

}  // namespace foldkit::bench
