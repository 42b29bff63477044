#include "straight_plan.hpp"

#include <algorithm>
#include <cerrno>
#include <functional>
#include <system_error>
#include <utility>

#if defined(__linux__)
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

#include <ompl/base/ScopedState.h>

#include "foldkit/planners/objectives.hpp"

namespace foldkit::planners::detail {

namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;

// How much less the straight plan's threads get than the planner's when they compete for a core
// (nice steps; CFS gives a thread at +10 about a tenth of the share of one at 0).
constexpr int kNiceOffset = 10;

// The calling thread's id for setpriority, 0 where threads have none.
int this_thread_id() {
#if defined(__linux__)
  return static_cast<int>(::syscall(SYS_gettid));
#else
  return 0;
#endif
}

// The calling thread at `nice` (Linux: a thread's nice value is its own). Best effort: a system
// that refuses leaves the thread as it is, which changes the timing, not the result.
void set_nice(int tid, int nice) {
#if defined(__linux__)
  if (tid != 0) ::setpriority(PRIO_PROCESS, static_cast<id_t>(tid), nice);
#else
  (void)tid;
  (void)nice;
#endif
}

int caller_nice() {
#if defined(__linux__)
  errno = 0;
  const int nice = ::getpriority(PRIO_PROCESS, static_cast<id_t>(this_thread_id()));
  return errno == 0 ? nice : 0;
#else
  return 0;
#endif
}

// The two-state path plan() gives its planner (set_start_and_goal's states).
og::PathGeometric ends_path(const PlanSetup& setup) {
  ob::ScopedState<> from(setup.space), to(setup.space);
  if (!setup.plan_space->write(setup.prefix.back(), from.get()) || !setup.plan_space->write(setup.goal, to.get()))
    return og::PathGeometric(setup.si);  // plan() refuses such a problem before planning
  return og::PathGeometric(setup.si, from.get(), to.get());
}

}  // namespace

bool StraightPlan::wanted(const PlanSetup& setup, const PlanOptions& options, bool via_flat, bool experience) {
  return setup.plan_space->straight_paths() && setup.continues_to_goal && !via_flat && !experience && options.replay &&
         options.simplify && options.start_sequence.events.empty() && parse_objective(options.objective).is_default() &&
         !options.cost_threshold && setup.blocked.empty() && setup.other_branch.empty();
}

StraightPlan::StraightPlan(const PlanSetup& setup, const PlanOptions& options, const simulation::ThreadStarter& start)
    : setup_(setup),
      options_(options),
      path_(ends_path(setup)),
      nice_(caller_nice()),
      pipeline_(setup, options, [this, start](std::function<void()> body) {
        std::function<void()> lowered = [this, body = std::move(body)] {
          lower_priority();
          body();
          forget_priority();
        };
        return start ? start(std::move(lowered)) : std::thread(std::move(lowered));
      }) {
  if (path_.getStateCount() != 2 || !setup.reader(path_.getState(0), first_) || !setup.reader(path_.getState(1), last_))
    return;  // plan() refuses such ends before planning; nothing to follow
  std::function<void()> body = [this] {
    lower_priority();
    run();
    forget_priority();
  };
  try {
    thread_ = start ? start(std::move(body)) : std::thread(std::move(body));
  } catch (const std::system_error&) {
    return;  // no second thread: the plan makes its waypoints itself, after the planner
  }
  ends_ok_ = thread_.joinable();
}

StraightPlan::~StraightPlan() {
  cancelled_ = true;
  if (thread_.joinable()) thread_.join();
  pipeline_.cancel();
}

void StraightPlan::run() {
  // A dropped plan stops at the continuation's next step and pushes nothing more. With a stop
  // given, the driving space does not halve a segment its continuation falls short of (the
  // halving borrows the space's solvers, which the planner is using): no waypoints then, and the
  // plan makes them itself after the planner, halving as always. Whatever fails here fails there
  // the same way (the same computation), so an exception only means "not made here".
  std::string why;
  try {
    dense_ = path_waypoints(
        setup_, path_, options_, true, &why,
        [this](const geometry::FoldState& s) {
          if (!cancelled_) pipeline_.push(s);
        },
        [this] { return cancelled_.load(); });
  } catch (...) {
    dense_.reset();
  }
}

bool StraightPlan::matches(const og::PathGeometric& path) const {
  if (path.getStateCount() != 2 || !ends_ok_) return false;
  geometry::FoldState a, b;
  if (!setup_.reader(path.getState(0), a) || !setup_.reader(path.getState(1), b)) return false;
  return a.angles.size() == first_.angles.size() && b.angles.size() == last_.angles.size() &&
         (a.angles.array() == first_.angles.array()).all() && (b.angles.array() == last_.angles.array()).all();
}

void StraightPlan::lower_priority() {
  const std::lock_guard<std::mutex> lock(nice_mutex_);
  if (accepted_) return;
  const int tid = this_thread_id();
  set_nice(tid, nice_ + kNiceOffset);
  lowered_.push_back(tid);
}

// A thread about to end: its id may be another thread's soon (Linux reuses them), so it is no
// longer one to restore.
void StraightPlan::forget_priority() {
  const std::lock_guard<std::mutex> lock(nice_mutex_);
  const int tid = this_thread_id();
  lowered_.erase(std::remove(lowered_.begin(), lowered_.end(), tid), lowered_.end());
}

// The plan is this one: its threads are the plan's own from here on. Raising a thread's priority
// back needs the privilege to (root, or RLIMIT_NICE); without it they stay lower, which matters
// only where other processes compete for the core.
void StraightPlan::restore_priority() {
  const std::lock_guard<std::mutex> lock(nice_mutex_);
  accepted_ = true;
  for (int tid : lowered_) set_nice(tid, nice_);
}

std::optional<std::vector<geometry::FoldState>> StraightPlan::waypoints() {
  restore_priority();
  if (thread_.joinable()) thread_.join();
  return std::move(dense_);
}

}  // namespace foldkit::planners::detail
