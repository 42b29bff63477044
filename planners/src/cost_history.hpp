#pragma once
// The best cost over time of an optimising planner while it runs, from OMPL's planner progress
// property "best cost" (what ompl::tools::Benchmark records in its logs). Private to
// foldkit::planners.
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include <ompl/base/Planner.h>

namespace foldkit::planners::detail {

// While it lives, a thread reads the planner's "best cost" progress property every `interval`
// seconds (as OMPL's Benchmark does, from another thread) and appends (seconds since
// construction, cost) to `history` whenever the finite cost changes; stop() (or the destructor)
// adds the last reading and joins. Nothing is recorded for a planner without the property.
class CostRecorder {
 public:
  CostRecorder(const ompl::base::Planner& planner, double interval, std::vector<std::pair<double, double>>& history);
  ~CostRecorder();
  CostRecorder(const CostRecorder&) = delete;
  CostRecorder& operator=(const CostRecorder&) = delete;
  void stop();

 private:
  void sample();

  ompl::base::Planner::PlannerProgressProperty best_cost_;
  std::chrono::duration<double> interval_;
  std::vector<std::pair<double, double>>& history_;
  std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  std::thread thread_;
};

}  // namespace foldkit::planners::detail
