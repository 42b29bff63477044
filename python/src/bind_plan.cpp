// foldkit.plan: sampling-based planning on the crease pattern's closure manifold (OMPL).
#include "bindings.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/planners/experience.hpp"
#include "foldkit/planners/objectives.hpp"
#include "foldkit/planners/plan.hpp"
#include "foldkit/planners/planner_factory.hpp"
#include "foldkit/simulation/simulate.hpp"

namespace foldkit::python {
namespace {

using planners::PlanResult;

// The spaces plan() accepts, quoted for a docstring: 'auto', 'single-vertex', … (from the C++
// table, not retyped). `from` skips the first `from` names ("auto" is no searched space).
std::string quoted_spaces(std::size_t from) {
  const std::vector<std::string> names = planners::space_names();
  std::string list;
  for (std::size_t i = from; i < names.size(); ++i)
    list += (i == from ? "'" : i + 1 == names.size() ? " or '" : ", '") + names[i] + "'";
  return list;
}

// The objectives plan() accepts, quoted for a docstring (from the C++ table).
std::string quoted_objectives() {
  const std::vector<std::string> names = planners::objective_names();
  std::string list;
  for (std::size_t i = 0; i < names.size(); ++i) list += (i == 0 ? "'" : ", '") + names[i] + "'";
  return list;
}

void bind_result(py::module_& m) {
  def_seconds(py::class_<PlanResult>(m, "PlanResult", "A plan: the waypoints from start to goal, their CMML, and the simulator's replay."),
              "Wall-clock seconds the search ran (the fallback included).")
      .def_readonly("status", &PlanResult::status, "'success' when solved (and the replay is valid).")
      .def_property_readonly("solved", [](const PlanResult& r) { return r.status.ok(); }, "Whether a valid plan was found.")
      .def_readonly("planner", &PlanResult::planner, "The planner's name.")
      .def_readonly("space", &PlanResult::space, ("The space searched: " + quoted_spaces(1) + ".").c_str())
      .def_readonly("fallback", &PlanResult::fallback,
                    "Whether the path came from a fallback: Carpenter's rule on the sphere (single vertex) or via flat.")
      .def_readonly("via_flat", &PlanResult::via_flat,
                    "Whether the path goes start, flat, goal as two plans from flat (driving space, folded start).")
      .def_readonly("path_length", &PlanResult::path_length, "Σ joint-angle distance between waypoints, radians.")
      .def_readonly("objective", &PlanResult::objective, "The objective's canonical name, e.g. 'rotation' or 'length:1,rotation:0.5'.")
      .def_readonly("cost", &PlanResult::cost,
                    "The objective's cost of the waypoints, every crease counted (length and rotation in radians, "
                    "clearance in pattern units); nan without a path.")
      .def_property_readonly(
          "cost_history",
          [](const PlanResult& r) {
            Eigen::MatrixX2d history(static_cast<Eigen::Index>(r.cost_history.size()), 2);
            for (std::size_t i = 0; i < r.cost_history.size(); ++i)
              history.row(static_cast<Eigen::Index>(i)) << r.cost_history[i].first, r.cost_history[i].second;
            return history;
          },
          "The planner's best cost over its search (OMPL's progress property), shape (changes, 2): seconds since the "
          "search began, cost; empty for planners that do not optimise.")
      .def_readonly("max_closure_error", &PlanResult::max_closure_error, "Largest loop error over waypoints and replay, radians.")
      .def_property_readonly(
          "waypoints", [](const PlanResult& r) { return states_array(r.waypoints); },
          "Start … goal, shape (waypoints, joints), radians; at most waypoint_step apart per joint.")
      .def_readonly("sequence", &PlanResult::sequence, "The plan as a FoldSequence from the flat sheet.")
      .def_readonly("replay", &PlanResult::replay, "The simulator's SimulationReport of the sequence, or None when not replayed.")
      .def_property_readonly(
          "experience",
          [](const PlanResult& r) -> py::object {
            if (!r.experience) return py::none();
            py::dict d;
            d["framework"] = r.experience->framework;
            d["recalled"] = r.experience->recalled;
            d["recall_seconds"] = r.experience->recall_seconds;
            d["load_seconds"] = r.experience->load_seconds;
            d["loaded"] = r.experience->loaded;
            d["states"] = r.experience->states;
            d["paths"] = r.experience->paths;
            d["bytes"] = r.experience->bytes.size();
            return d;
          },
          "With `experience`: a dict as the CLI's JSON `experience` (framework, recalled, recall_seconds, load_seconds, loaded, "
          "paths, states, bytes); else None.")
      .def("__repr__", [](const PlanResult& r) {
        return "PlanResult(" + std::string(geometry::to_string(r.status.code)) + ", " + r.planner + " in " + r.space + ", " +
               std::to_string(r.waypoints.size()) + " waypoints)";
      });
}

// plan()'s goal: an array of angles, or a FoldSequence's end state (as the CLI's --goal CMML).
geometry::FoldState goal_of(const geometry::CreasePattern& p, const py::object& goal) {
  if (py::isinstance<geometry::FoldSequence>(goal))
    return checked_end_state(p, goal.cast<geometry::FoldSequence>(), source_of(goal));
  Eigen::VectorXd angles;
  try {
    angles = goal.cast<Eigen::VectorXd>();
  } catch (const py::cast_error&) {
    throw py::type_error("goal must be an array of fold angles (radians) or a FoldSequence");
  }
  return to_state(p, angles, "goal");
}

// plan() with `experience`, a database file, read and written back as the CLI's --experience:
// only a missing file is a new database; atomically, after a plan that checks out.
planners::PlanResult plan_with_experience(const geometry::CreasePattern& p, const geometry::FoldState& goal,
                                          planners::PlanOptions& options, const std::optional<std::string>& experience,
                                          const std::string& framework) {
  if (experience)  // a missing file is a new database
    options.experience =
        planners::PlanOptions::Experience{*experience, io::read_file_if_present(*experience).value_or(""), framework};
  py::gil_scoped_release release;
  planners::PlanResult r;
  try {
    r = planners::plan(p, goal, options);
  } catch (const planners::ExperienceError& e) {
    throw io::ParseError(*experience, 0, e.reason());  // "DB: reason"
  }
  if (r.experience && !r.experience->bytes.empty()) io::write_file_atomic(*experience, r.experience->bytes);
  return r;
}

}  // namespace

void bind_plan(py::module_& m) {
  bind_result(m);
  m.def(
      "plan",
      [](const geometry::CreasePattern& p, const py::object& goal, const py::object& start, const std::string& space,
         const std::string& planner, double time, unsigned seed, bool collisions, bool use_assignment, bool simplify,
         double search_margin, double waypoint_step, double speed, bool replay, const std::map<std::string, std::string>& params,
         bool fallback, const py::object& velocity, const std::string& objective, const std::optional<double>& cost_threshold,
         const std::optional<std::string>& experience, const std::string& experience_framework) {
        speed = renamed(speed, planners::PlanOptions{}.speed, velocity, "velocity", "speed");  // `velocity`: fold()'s desired velocity
        require_positive(time, "time");
        require_positive(waypoint_step, "waypoint_step");
        require_positive(speed, "speed");
        require(std::isfinite(search_margin), "search_margin", "finite (negative: automatic)", search_margin);
        const geometry::FoldState goal_state = goal_of(p, goal);  // its errors come before the start's, as they did
        planners::PlanOptions options;
        if (!start.is_none()) {
          if (py::isinstance<geometry::FoldSequence>(start)) {
            options.start_sequence = start.cast<geometry::FoldSequence>();
            options.start = checked_end_state(p, options.start_sequence, source_of(start));
          } else {
            options.start = state_or_flat(p, start, "start");
          }
        }
        options.space = planners::parse_space(space);
        options.planner = planners::canonical_planner(planner);
        options.time = time;
        options.seed = seed;
        options.collisions = collisions;
        options.use_assignment = use_assignment;
        options.simplify = simplify;
        options.search_margin = search_margin;
        options.waypoint_step = waypoint_step;
        options.speed = speed;
        options.replay = replay;
        options.params.assign(params.begin(), params.end());
        options.fallback = fallback;
        options.objective = planners::parse_objective(objective).name();  // ValueError before any work
        if (cost_threshold) planners::check_cost_threshold(*cost_threshold, "cost_threshold");
        options.cost_threshold = cost_threshold;
        planners::parse_experience_framework(experience_framework);  // ValueError before any work
        return plan_with_experience(p, goal_state, options, experience, experience_framework);
      },
      // The defaults are PlanOptions'.
      py::arg("pattern"), py::arg("goal"), py::arg("start") = py::none(), py::arg("space") = std::string(planners::to_string(planners::PlanOptions{}.space)),
      py::arg("planner") = planners::PlanOptions{}.planner, py::arg("time") = planners::PlanOptions{}.time,
      py::arg("seed") = planners::PlanOptions{}.seed, py::arg("collisions") = planners::PlanOptions{}.collisions,
      py::arg("use_assignment") = planners::PlanOptions{}.use_assignment, py::arg("simplify") = planners::PlanOptions{}.simplify,
      py::arg("search_margin") = planners::PlanOptions{}.search_margin, py::arg("waypoint_step") = planners::PlanOptions{}.waypoint_step,
      py::arg("speed") = planners::PlanOptions{}.speed, py::arg("replay") = planners::PlanOptions{}.replay,
      py::arg("params") = std::map<std::string, std::string>{}, py::arg("fallback") = planners::PlanOptions{}.fallback,
      py::arg("velocity") = py::none(), py::arg("objective") = planners::PlanOptions{}.objective,
      py::arg("cost_threshold") = planners::PlanOptions{}.cost_threshold, py::arg("experience") = py::none(),
      py::arg("experience_framework") = planners::PlanOptions::Experience{}.framework,
      ("Plans from `start` to the closed state `goal`: an array of angles (radians) or a FoldSequence (its end state, as "
       "the CLI's --goal CMML). `start` is None (flat), a FoldSequence (its end state is the start; "
      "the plan's sequence begins with it, as the CLI's --start CMML), or a closed state: then the plan's sequence reaches "
      "it from flat in one straight event, which the replay accepts only where that line stays closed (pass the "
      "FoldSequence otherwise). Planning runs "
      "an OMPL planner by name, as `foldkit plan`: space " + quoted_spaces(0) + " (spaces()); `time` seconds at most; the same seed gives the same plan. `params` sets planner parameters by "
      "OMPL's names, e.g. {'range': '0.3'} (ValueError for one the planner does not have). When the planner finds "
      "none in a quarter of `time`, `fallback` goes through flat: on a single vertex the path of Carpenter's rule on the "
      "sphere (start, flat, goal); in the driving space from a folded start, a plan from flat to the start, reversed, then "
      "one from flat to the goal (at once for a goal known to lie on another branch). The result's `fallback` and "
      "`via_flat` say so. `speed` is the fastest crease's speed in each CMML event, rad/s (`velocity`: its deprecated "
      "name). `objective` is what the planner optimises, as `foldkit plan --objective`: " + quoted_objectives() +
      ", or a weighted sum 'NAME:WEIGHT,…' of the additive ones (objectives()); `cost_threshold` stops an optimising "
      "planner once its path costs less (clearance: more), None for never. `experience` is a database file, as "
      "`foldkit plan --experience`: a path is recalled first, by `experience_framework` ('lightning': the stored path "
      "nearest to this query, repaired; 'thunder': a path through a sparse roadmap of the stored paths), and this "
      "plan's path is stored (ParseError for a damaged or foreign database). Returns a PlanResult (check `status`).")
          .c_str());
  m.def("planners", &planners::planner_names, "The planner names plan() accepts.");
  m.def("spaces", &planners::space_names, "The space names plan() accepts ('auto' first).");
  m.def("objectives", &planners::objective_names, "The objective names plan() accepts ('length' first: the default).");
}

}  // namespace foldkit::python
