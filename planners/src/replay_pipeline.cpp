#include "replay_pipeline.hpp"

namespace foldkit::planners::detail {

ReplayPipeline::ReplayPipeline(const PlanSetup& setup, const PlanOptions& options, const ThreadStarter& start) {
  if (!options.replay || !options.start_sequence.events.empty()) return;
  simulation::SimulationOptions so;
  so.collisions = options.collisions;
  so.progress = options.progress;
  replay_.emplace(*setup.pattern, so, options.speed, start);
}

}  // namespace foldkit::planners::detail
