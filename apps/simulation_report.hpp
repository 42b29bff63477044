#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/simulation/simulate.hpp"

namespace foldkit::apps {

// The report as `foldkit simulate --json` prints it (docs/CLI.md).
nlohmann::json report_json(const geometry::CreasePattern& pattern, const simulation::SimulationReport& report);

// One line for people, plus the problems, on stderr.
void print_summary(const std::string& name, const simulation::SimulationReport& report);

// FOLD with the trajectory as file_frames (at most `max_frames`, evenly thinned, the last kept).
std::string trajectory_fold(const geometry::CreasePattern& pattern, const simulation::SimulationReport& report,
                            std::size_t max_frames);

// SVG snapshots into `dir`: the sheet at the end of each event (event-N.svg) and at the first
// collisions (collision-K.svg, the two facets in red, at most `max_collisions`). Returns the files.
std::vector<std::string> write_snapshots(const geometry::CreasePattern& pattern, const simulation::SimulationReport& report,
                                         const std::string& dir, std::size_t max_collisions = 20);

}  // namespace foldkit::apps
