#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "foldkit/dynamics/dynamic_simulate.hpp"
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

// `foldkit simulate --model dynamic --json`'s report (docs/CLI.md): per event whether its joints
// reached their angles, the stalls (joint, angle, time, needed against available torque), per
// joint the peak torque, closure drift and energy. Angles in degrees, as in final_angles. The
// settings it names are `options` as the run resolved them (dynamics::resolve_options()).
nlohmann::json dynamic_report_json(const geometry::CreasePattern& pattern, const dynamics::DynamicReport& report,
                                   const dynamics::DynamicOptions& options);

// The dynamic run's one line for people, its stalls and problems, on stderr.
void print_dynamic_summary(const std::string& name, const dynamics::DynamicReport& report);

// The dynamic run's frames as CSV: time (s), event, then per joint its angle (degrees) and the
// torque of its motor or spring (N·m), columns named angle_ID and torque_ID.
std::string dynamic_series_csv(const geometry::CreasePattern& pattern, const dynamics::DynamicReport& report);

// The same series as JSON, by column, for plotting (the browser app's torque plot):
// {"time": [s…], "event": [n…], "joints": [{"joint": ID, "angle": [degrees…], "torque": [N·m…]}…]},
// the joints in the pattern's order, every array one entry per frame.
nlohmann::json dynamic_series_json(const geometry::CreasePattern& pattern, const dynamics::DynamicReport& report);

// Whether `path` names a file --series writes: .csv or .json.
bool is_series_file(const std::string& path);

// The text --series writes into `path`: JSON for a .json name, else CSV.
std::string dynamic_series(const geometry::CreasePattern& pattern, const dynamics::DynamicReport& report,
                           const std::string& path);

// The dynamic run as a kinematic report holding what --frames and --svg read (events, frames,
// final state, status), so that both write it as they write the kinematic models' runs.
simulation::SimulationReport frames_view(const dynamics::DynamicReport& report);

}  // namespace foldkit::apps
