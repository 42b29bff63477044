#include "cost_history.hpp"

#include <cmath>
#include <cstdlib>
#include <string>

namespace foldkit::planners::detail {

CostRecorder::CostRecorder(const ompl::base::Planner& planner, double interval, std::vector<std::pair<double, double>>& history)
    : interval_(interval), history_(history) {
  // RRT*, RRT#, PRM*, FMT… declare "best cost REAL"; BIT*, ABIT*, AIT* "best cost DOUBLE".
  for (const auto& [name, property] : planner.getPlannerProgressProperties())
    if (name.rfind("best cost", 0) == 0) best_cost_ = property;
  if (!best_cost_) return;
  thread_ = std::thread([this] {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, interval_, [this] { return done_; })) sample();
  });
}

CostRecorder::~CostRecorder() { stop(); }

void CostRecorder::stop() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
  }
  wake_.notify_all();
  thread_.join();
  sample();
}

void CostRecorder::sample() {
  const std::string text = best_cost_();
  char* end = nullptr;
  const double cost = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || !std::isfinite(cost)) return;  // no solution yet
  if (!history_.empty() && history_.back().second == cost) return;
  history_.emplace_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count(), cost);
}

}  // namespace foldkit::planners::detail
