// The fold's replay runs beside the folding (simulation::PipelinedReplay fed each accepted state):
// against simulate() of the fold's whole sequence (the oracle: every field of the report), for a
// fold that reaches its target and one that stops at a collision, with the progress of both threads
// reaching the caller one call at a time.
#include <atomic>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

#include <gtest/gtest.h>

#include "foldkit/folding/projected_folding.hpp"
#include "foldkit/geometry/generators.hpp"
#include "foldkit/simulation/simulate.hpp"
#include "same_report.hpp"

namespace {

namespace gen = foldkit::geometry::generators;
namespace sim = foldkit::simulation;
using foldkit::folding::fold_projected;
using foldkit::folding::ProjectedFoldingOptions;
using foldkit::folding::ProjectedFoldingResult;
using foldkit::geometry::build_or_throw;
using foldkit::geometry::CreasePattern;

// The fold with a progress callback that records its threads and fails on overlapping calls.
struct Watched {
  ProjectedFoldingResult result;
  std::set<std::thread::id> threads;
  bool overlapped = false;
};

Watched fold_watched(const CreasePattern& p, ProjectedFoldingOptions o) {
  Watched w;
  std::mutex record;
  std::atomic<bool> inside{false};
  o.progress = [&](const foldkit::geometry::Progress&) {
    if (inside.exchange(true)) w.overlapped = true;
    {
      const std::lock_guard<std::mutex> lock(record);
      w.threads.insert(std::this_thread::get_id());
    }
    std::this_thread::yield();  // widen the window an unserialised call would overlap in
    inside = false;
  };
  w.result = fold_projected(p, o);
  return w;
}

TEST(ProjectedFoldingReplay, AlongsideTheFoldingItIsSimulatesReport) {
  const CreasePattern miura = build_or_throw(gen::miura(10, 10));
  ProjectedFoldingOptions o;
  o.target_fraction = 0.9;
  const Watched w = fold_watched(miura, o);
  ASSERT_EQ(w.result.status.code, foldkit::geometry::StatusCode::Success) << w.result.status.message;
  ASSERT_TRUE(w.result.replay.has_value());
  EXPECT_TRUE(w.result.replay->status.ok()) << w.result.replay->status.message;
  sim::SimulationOptions so;
  so.collisions = o.collisions;
  foldkit::test::expect_same_report(*w.result.replay, sim::simulate(miura, w.result.sequence, so));
  EXPECT_FALSE(w.overlapped) << "the folding's and the replay's progress calls overlapped";
  EXPECT_EQ(w.threads.size(), 2u) << "the replay's progress came from the folding's thread: it did not run beside it";
}

// A strip folded toward itself stops at the collision; the replay of what was folded is still
// simulate()'s, and without a replay there is none.
TEST(ProjectedFoldingReplay, StoppedFoldAndNoReplay) {
  const CreasePattern strip = build_or_throw(gen::strip(3));
  ProjectedFoldingOptions o;
  o.velocity = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(strip.joints().size()), 1.0);
  o.target_fraction = 1.0;
  const Watched w = fold_watched(strip, o);
  ASSERT_EQ(w.result.status.code, foldkit::geometry::StatusCode::Collision) << w.result.status.message;
  ASSERT_TRUE(w.result.replay.has_value());
  sim::SimulationOptions so;
  so.collisions = o.collisions;
  foldkit::test::expect_same_report(*w.result.replay, sim::simulate(strip, w.result.sequence, so));
  EXPECT_FALSE(w.overlapped);
  ProjectedFoldingOptions off = o;
  off.replay = false;
  EXPECT_FALSE(fold_projected(strip, off).replay.has_value());
}

// A progress callback that throws ends the fold with its exception, from either thread, and the
// replay's thread with it (the test would hang on a join otherwise).
TEST(ProjectedFoldingReplay, ProgressThatThrowsEndsTheFoldFromEitherThread) {
  const CreasePattern miura = build_or_throw(gen::miura(10, 10));
  const std::thread::id caller = std::this_thread::get_id();
  for (bool on_the_folding_thread : {true, false}) {
    ProjectedFoldingOptions o;
    o.target_fraction = 0.9;
    int calls = 0;
    o.progress = [&](const foldkit::geometry::Progress&) {
      if ((std::this_thread::get_id() == caller) == on_the_folding_thread && ++calls == 5) throw std::runtime_error("stop here");
    };
    EXPECT_THROW(fold_projected(miura, o), std::runtime_error) << (on_the_folding_thread ? "folding" : "replay");
  }
}

}  // namespace
