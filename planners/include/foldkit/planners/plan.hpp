#pragma once
#include <optional>
#include <string>
#include <vector>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/geometry/status.hpp"
#include "foldkit/simulation/simulate.hpp"

namespace foldkit::planners {

// Which space the planner searches (docs/PLANNING.md).
enum class SpaceKind {
  Auto,           // single-vertex for a pattern with one interior vertex, else projected
  SingleVertex,   // the exact (n − 3)-dimensional space of one vertex
  Projected,      // OMPL ProjectedStateSpace on the closure constraint (analytic Jacobian)
  Atlas,          // OMPL AtlasStateSpace
  TangentBundle,  // OMPL TangentBundleStateSpace
};
// "auto", "single-vertex", "projected", "atlas", "tangent-bundle"; std::invalid_argument otherwise.
SpaceKind parse_space(const std::string& name);
const char* to_string(SpaceKind kind);

struct PlanRequest {
  const geometry::CreasePattern* pattern = nullptr;
  // Where the plan starts, and the CMML that reaches it from the flat sheet (empty: flat start).
  std::optional<geometry::FoldState> start;
  geometry::FoldSequence start_sequence;
  geometry::FoldState goal;  // closed, one angle per joint
  SpaceKind space = SpaceKind::Auto;
  std::string planner = "RRTConnect";
  double time = 5.0;          // seconds for the planner
  unsigned int seed = 1;
  bool collisions = true;
  bool use_assignment = true;  // mountain/valley assignments of the pattern become angle bounds
  bool numerical_jacobian = false;  // constrained spaces: OMPL's finite differences (a baseline)
  bool simplify = true;
  // Constrained spaces: when ≥ 0, the ambient box the sampler draws from (and the plan stays in)
  // is narrowed to [min(start, goal) − margin, max(start, goal) + margin] per crease (within the
  // bounds). On patterns whose closure variety has many branches through flat (Miura) uniform
  // ambient samples project onto those other branches and RRTConnect never heads for the goal.
  double search_margin = -1.0;
  double resolution = 0.02;     // motion validator: radians per check (single-vertex); manifold step/2.5 otherwise
  double waypoint_step = 0.02;  // largest joint change between two CMML waypoints, radians
  double velocity = 1.0;        // fastest joint's speed in the CMML, rad/s
  bool replay = true;           // replay the plan in the simulator before accepting it
  bool quiet = true;            // silence OMPL's console messages
  geometry::ProgressFn progress;  // the replay's progress (the planner itself runs for `time` at most)
};

struct PlanResult {
  // Success: a valid plan, replayed by the simulator when requested. Otherwise LimitReached (no
  // plan within the time), Collision (the way out of the start collides, or the replay found
  // one), ClosureViolated (the path leaves the closure manifold, or the replay says so).
  geometry::Status status;
  std::string planner, space;
  double time = 0.0;            // seconds the planner ran
  double path_length = 0.0;     // Σ Euclidean joint-angle distance between waypoints, radians
  double max_closure_error = 0.0;  // largest loop error over the waypoints and the replay
  std::vector<geometry::FoldState> waypoints;  // start … goal, dense
  geometry::FoldSequence sequence;             // from the flat sheet (start_sequence first)
  std::optional<simulation::SimulationReport> replay;
};

// The pipeline: space → planner → path → simplify → densify → CMML → simulator replay.
// Throws std::invalid_argument for a request that cannot be planned (a start or goal that is
// not closed, an unknown planner, a single-vertex space on a multi-vertex pattern).
PlanResult plan(const PlanRequest& request);

}  // namespace foldkit::planners
