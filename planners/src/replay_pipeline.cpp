#include "replay_pipeline.hpp"

namespace foldkit::planners::detail {

simulation::SimulationOptions replay_options(const PlanOptions& options) {
  simulation::SimulationOptions so;
  so.collisions = options.collisions;
  so.progress = options.progress;
  return so;
}

ReplayPipeline::ReplayPipeline(const PlanSetup& setup, const PlanOptions& options, const ThreadStarter& start)
    : pattern_(setup.pattern), options_(replay_options(options)) {
  if (!options.replay || !options.start_sequence.events.empty()) return;
  replay_.emplace(*setup.pattern, options_, options.speed, start);
}

}  // namespace foldkit::planners::detail
