#pragma once
/// @file
/// Motion planning between two closed fold states with OMPL: the space, the planner, and the
/// path turned into a CMML sequence the simulator replays (docs/PLANNING.md).
#include <functional>
#include <future>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/geometry/status.hpp"
#include "foldkit/simulation/simulate.hpp"

/// Planning with OMPL: the pipeline from a problem to a checked, replayed CMML plan, and the
/// planners by name.
namespace foldkit::planners {

/// Which space the planner searches (docs/PLANNING.md).
enum class SpaceKind {
  Auto,           ///< single-vertex for a pattern with one interior vertex and no hole, else driving
  SingleVertex,   ///< the exact (n − 3)-dimensional space of one vertex
  Driving,        ///< statespaces::DrivingStateSpace: DOF-many driving creases, the rest by closure
  Projected,      ///< OMPL ProjectedStateSpace on the closure constraint (analytic Jacobian)
  Atlas,          ///< OMPL AtlasStateSpace
  TangentBundle,  ///< OMPL TangentBundleStateSpace
};
/// The space named "auto", "single-vertex", "driving", "projected", "atlas" or "tangent-bundle".
/// @throws std::invalid_argument for any other name
SpaceKind parse_space(const std::string& name);
/// The names parse_space() reads, in the order of SpaceKind ("auto" first): for command lines.
std::vector<std::string> space_names();
/// The kind's name, as parse_space() reads it.
const char* to_string(SpaceKind kind);

/// A problem plan() refuses because of its start or its goal (not closed, breaking the
/// assignment, colliding, singular for the space): which one, so that a caller can point at the
/// file it came from. Any other refusal is a plain std::invalid_argument.
class PlanInputError : public std::invalid_argument {
 public:
  /// Which end of the plan is at fault.
  enum class End { Start, Goal };
  /// The error, at `end`, with its message.
  PlanInputError(End end, const std::string& what) : std::invalid_argument(what), end_(end) {}
  /// Which end of the plan is at fault.
  End end() const { return end_; }

 private:
  End end_;
};

/// How plan() plans: where it starts (flat by default), the space and planner, the limits and what
/// it checks. The pattern and the goal are plan()'s own arguments.
struct PlanOptions {
  /// Where the plan starts (closed, one angle per joint, radians); empty: the flat sheet.
  std::optional<geometry::FoldState> start;
  /// The CMML that reaches `start` from the flat sheet; empty for a flat start. When given, it
  /// comes first in the plan's sequence, in place of its first event (flat → start) when the
  /// start is not flat, and the events are renumbered from 1.
  geometry::FoldSequence start_sequence;
  SpaceKind space = SpaceKind::Auto;  ///< which space to search
  std::string planner = "RRTConnect";  ///< an OMPL planner by name (make_planner())
  /// The planner's parameters by name, set through OMPL's ParamSet (planner->params()), e.g.
  /// {"range", "0.3"}; applied in order after the planner's defaults.
  std::vector<std::pair<std::string, std::string>> params;
  /// Seconds the search may take at most (positive, finite): the planner, the Carpenter fallback
  /// and both legs of the way through flat together (to one check or one Carpenter step); it
  /// stops at the first exact solution (with `cost_threshold`: the first whose cost meets it).
  /// Not bounded by it: the start's lead-in, simplifying, densifying and the replay.
  double time = 5.0;
  /// What the planner optimises, by name (parse_objective(); docs/PLANNING.md, "Objectives"):
  /// "length", "rotation", "clearance" or a weighted sum such as "length:1,rotation:0.5".
  /// The default, "length" without a threshold, is set only on the planners that sample
  /// informed; any other objective on every planner, so that OMPL's optimising planners (RRT*,
  /// PRM*, …) improve it until `time` or the threshold.
  std::string objective = "length";
  /// Stop once the path's cost is below this (clearance: above it), OMPL's cost threshold;
  /// finite and ≥ 0. Empty: none is ever satisfied, and the search stops at the first exact
  /// solution a planner reports (RRT*, RRT#, PRM*, … report theirs only at `time`).
  std::optional<double> cost_threshold;
  unsigned int seed = 1;      ///< seed of OMPL's random numbers (0 counts as 1)
  bool collisions = true;     ///< whether crossing facets make a state invalid (planning and replay)
  bool use_assignment = true;  ///< mountain/valley assignments of the pattern become angle bounds
  bool numerical_jacobian = false;  ///< constrained spaces: OMPL's finite differences (a baseline)
  /// Shorten the path with OMPL's PathSimplifier (reduce vertices, shortcut); a path already as
  /// short as the distance between its ends is left as found, or, in the driving space (whose
  /// motion over collinear segments is the one continuation over their union), cut to its ends.
  bool simplify = true;
  /// When the planner finds no plan in a quarter of `time` (kSamplerShare), go through flat:
  /// - single-vertex space: the path of Carpenter's rule on the sphere (start → flat → goal,
  ///   CarpenterFallbackPlanner), which reaches every closed, non-crossing state;
  /// - driving space, from a start that is not flat and whose straight continuation to the
  ///   goal's driving angles does not reach the goal (PlanSetup::reachable; one that does keeps
  ///   all of `time`): a plan from flat to the start, reversed, then one from flat to the goal,
  ///   with the rest of `time` split between them (also at once, without searching, when the goal
  ///   is known to lie on another branch). Every branch of a sheet's closed states meets the
  ///   others at flat, so this joins ends that no motion of one driving space joins.
  ///
  /// Off: the planner has all of `time`, and a goal on another branch is named (NoProgress).
  bool fallback = true;
  /// Constrained spaces: when ≥ 0, the ambient box the sampler draws from (and the plan stays in)
  /// is narrowed to [min(start, goal) − margin, max(start, goal) + margin] per crease (within the
  /// bounds; radians). On patterns whose closure variety has many branches through flat (Miura)
  /// uniform ambient samples project onto those other branches and RRTConnect never heads for the
  /// goal.
  double search_margin = -1.0;
  /// Motion validator: radians per check (single-vertex); for constrained spaces the manifold
  /// step is 2.5 × this. Positive.
  double resolution = 0.02;
  double waypoint_step = 0.02;  ///< largest joint change between two CMML waypoints, radians; positive
  double speed = 1.0;           ///< the fastest joint's speed in each CMML event, rad/s (written °/s); positive
  /// Replay the plan in the simulator before accepting it. Without a start sequence the replay runs
  /// on a thread of its own while the later waypoints are computed (in the driving space, from a
  /// start that continues straight to the goal, already while the planner searches: its waypoints
  /// and replay on two threads of lower priority, kept when the planner's path is that straight
  /// one); its report is simulate()'s of the whole sequence all the same.
  bool replay = true;
  /// Silence OMPL's console messages (sets OMPL's log level to none, for the whole process).
  bool quiet = true;
  /// The replay's progress (the planner itself runs for `time` at most); called by the thread that
  /// replays (see `replay`: not the caller's), one call at a time, while plan() runs. Until the
  /// waypoints are all known, the whole it reports is the events known so far. A plan from a start
  /// that continues straight to the goal in the driving space may begin its replay while the
  /// planner searches (docs/PLANNING.md, "the straight plan"); when the planner's path turns out
  /// to be another, that replay is dropped and the count starts again.
  geometry::ProgressFn progress;
  /// Called once with the plan's sequence (what PlanResult::sequence will hold) as soon as it is
  /// made, so that the caller can use it while the replay finishes judging it: `foldkit plan`
  /// writes its file on the other core, and keeps it only when the plan is accepted. Without a
  /// start sequence the replay has begun before (it runs while the waypoints are computed):
  /// `progress` may then have been called already, and may be called, from the replay's thread,
  /// while this runs; share nothing between the two without a lock. The sequence
  /// may be read from another thread until the future returned (when valid) is ready: plan()
  /// waits for it once the replay has ended, before it returns. Not called when no closed path
  /// was found.
  std::function<std::future<void>(const geometry::FoldSequence&)> sequence_ready;
  /// Planning from experience (docs/PLANNING.md, "Planning from experience"): when set, the
  /// database file's bytes (empty: a new database) and its name for messages. Recall by the
  /// framework: Lightning's stored path whose ends are nearest to this query's, repaired
  /// (LightningRetrieveRepair, repairs by RRTConnect), or a path through Thunder's roadmap of the
  /// stored paths (ThunderRetrieveRepair); when that fails, `planner` plans from scratch with the
  /// time left. PlanResult::experience gives the database back with this plan's path added. The
  /// way through flat and the Carpenter fallback's path are not stored.
  struct Experience {
    std::string name;   ///< the database file's name (messages: "NAME: reason")
    std::string bytes;  ///< its content; empty for a new database
    /// "lightning" or "thunder" (planners::experience_framework_names(), case-insensitive); both
    /// read and write the same file.
    std::string framework = "lightning";
  };
  std::optional<Experience> experience;  ///< none: no experience (the default)
};

/// What planning from experience did (PlanOptions::experience; planners/experience.hpp).
struct ExperienceOutcome {
  std::string framework;        ///< the framework that recalled: "lightning" or "thunder"
  bool recalled = false;        ///< the path was recalled from the database and repaired (else from scratch)
  double recall_seconds = 0.0;  ///< seconds spent recalling and repairing (also when it failed)
  /// Seconds spent reading the database's bytes into the framework's database (Thunder builds its
  /// roadmap from the stored paths then).
  double load_seconds = 0.0;
  /// States the framework's database holds now: every stored path's (Lightning), the roadmap's
  /// vertices (Thunder).
  std::size_t states = 0;
  std::size_t loaded = 0;       ///< paths the database held when the plan began
  std::size_t paths = 0;        ///< paths it holds now (the plan's own added when it succeeded)
  /// The database file's new bytes, the plan's path added (write them back atomically); empty
  /// when the plan failed or went through flat (the file stays as it was, or is not made). After
  /// the Carpenter fallback they are the database as loaded (its path is not stored).
  std::string bytes;
};

/// What plan() found.
struct PlanResult {
  /// StatusCode::Success: a valid plan, replayed by the simulator when requested. Otherwise
  /// StatusCode::LimitReached (no plan within the time), StatusCode::Collision (the way out of
  /// the start collides, or the replay found one), StatusCode::ClosureViolated (the path leaves
  /// the closure manifold, or the replay says so), StatusCode::NoProgress (the planner found
  /// nothing and the fallback failed, or the goal lies on another branch and the fallback is
  /// off: the message says why).
  geometry::Status status;
  std::string planner,          ///< the planner's name, as requested
      space;                    ///< the space searched: "single-vertex", "driving", "projected", "atlas" or "tangent-bundle"
  double seconds = 0.0;         ///< wall-clock seconds the search ran (the fallback and the way through flat included; at most about PlanOptions::time)
  /// Whether the path came from a fallback (PlanOptions::fallback) rather than from one run of
  /// the planner.
  bool fallback = false;
  /// Whether the path goes start → flat → goal as two plans from flat (PlanOptions::fallback in
  /// the driving space); `seconds` counts the direct attempt and both plans.
  bool via_flat = false;
  double path_length = 0.0;     ///< Σ Euclidean joint-angle distance between waypoints, radians
  std::string objective;        ///< the objective's canonical name (Objective::name())
  /// The objective's cost of `waypoints`, every crease counted (planners::path_cost: length and
  /// rotation in radians, clearance in pattern units); NaN without a path.
  double cost = std::numeric_limits<double>::quiet_NaN();
  /// The planner's best cost over its search, as OMPL's progress property "best cost" reports it
  /// (in the space's own terms: length in its metric), sampled every 20 ms: (seconds since the
  /// search began, cost) at each change; empty for planners that report none (they do not
  /// optimise) and for the way through flat.
  std::vector<std::pair<double, double>> cost_history;
  double max_closure_error = 0.0;  ///< largest loop error over the waypoints and the replay, radians
  std::vector<geometry::FoldState> waypoints;  ///< start … goal, dense (at most waypoint_step apart per joint)
  geometry::FoldSequence sequence;             ///< from the flat sheet (start_sequence first)
  std::optional<simulation::SimulationReport> replay;  ///< the simulator's report; empty when not replayed
  std::optional<ExperienceOutcome> experience;  ///< with PlanOptions::experience: what it did
};

/// The pipeline: space → planner → path → simplify → densify → CMML → simulator replay. A plan
/// that cannot be found or does not check out is a status, not an exception.
/// @param pattern  the crease pattern (only read during the call)
/// @param goal     where the plan ends: closed (to 1e-6 rad), one angle per joint, radians
/// @param options  where it starts, the space, the planner and its settings
/// @throws std::invalid_argument for a problem that cannot be planned: a pattern without closed
///         loops, a start or goal of the wrong size, not closed, breaking the assignment or
///         colliding, a time, resolution, waypoint step or speed that is not positive, an unknown
///         planner, a single-vertex space on a pattern that is not one vertex (or a goal singular
///         for it), or no closed way out of a singular start; an objective that does not parse
///         (parse_objective()) or a cost threshold that is negative or not finite
/// @throws ExperienceError (a std::runtime_error) for an experience database that cannot be used
/// @throws PlannerRefused (a std::invalid_argument) for a planner that cannot plan on the space
///         or cannot optimise the objective (objective_refusal())
PlanResult plan(const geometry::CreasePattern& pattern, const geometry::FoldState& goal, const PlanOptions& options = {});

}  // namespace foldkit::planners
