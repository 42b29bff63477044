// foldkit.plan: sampling-based planning on the crease pattern's closure manifold (OMPL).
#include "bindings.hpp"
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

void bind_result(py::module_& m) {
  py::class_<PlanResult>(m, "PlanResult", "A plan: the waypoints from start to goal, their CMML, and the simulator's replay.")
      .def_readonly("status", &PlanResult::status, "'success' when solved (and the replay is valid).")
      .def_property_readonly("solved", [](const PlanResult& r) { return r.status.ok(); }, "Whether a valid plan was found.")
      .def_readonly("planner", &PlanResult::planner, "The planner's name.")
      .def_readonly("space", &PlanResult::space, ("The space searched: " + quoted_spaces(1) + ".").c_str())
      .def_readonly("time", &PlanResult::time, "Seconds the planner ran (the fallback included).")
      .def_readonly("fallback", &PlanResult::fallback,
                    "Whether the path came from a fallback: Carpenter's rule on the sphere (single vertex) or via flat.")
      .def_readonly("via_flat", &PlanResult::via_flat,
                    "Whether the path goes start, flat, goal as two plans from flat (driving space, folded start).")
      .def_readonly("path_length", &PlanResult::path_length, "Σ joint-angle distance between waypoints, radians.")
      .def_readonly("max_closure_error", &PlanResult::max_closure_error, "Largest loop error over waypoints and replay, radians.")
      .def_property_readonly(
          "waypoints", [](const PlanResult& r) { return states_array(r.waypoints); },
          "Start … goal, shape (waypoints, joints), radians; at most waypoint_step apart per joint.")
      .def_readonly("sequence", &PlanResult::sequence, "The plan as a FoldSequence from the flat sheet.")
      .def_readonly("replay", &PlanResult::replay, "The simulator's SimulationReport of the sequence, or None when not replayed.")
      .def("__repr__", [](const PlanResult& r) {
        return "PlanResult(" + std::string(geometry::to_string(r.status.code)) + ", " + r.planner + " in " + r.space + ", " +
               std::to_string(r.waypoints.size()) + " waypoints)";
      });
}

}  // namespace

void bind_plan(py::module_& m) {
  bind_result(m);
  m.def(
      "plan",
      [](const geometry::CreasePattern& p, const Eigen::VectorXd& goal, const py::object& start, const std::string& space,
         const std::string& planner, double time, unsigned seed, bool collisions, bool use_assignment, bool simplify,
         double search_margin, double waypoint_step, double velocity, bool replay,
         const std::map<std::string, std::string>& params, bool fallback) {
        require_positive(time, "time");
        require_positive(waypoint_step, "waypoint_step");
        require_positive(velocity, "velocity");
        require(std::isfinite(search_margin), "search_margin", "finite (negative: automatic)", search_margin);
        planners::PlanRequest req;
        req.pattern = &p;
        req.goal = to_state(p, goal, "goal");
        if (!start.is_none()) {
          if (py::isinstance<geometry::FoldSequence>(start)) {
            req.start_sequence = start.cast<geometry::FoldSequence>();
            require_valid(p, req.start_sequence, source_of(start));
            req.start = geometry::end_state(p, req.start_sequence);
          } else {
            req.start = state_or_flat(p, start, "start");
          }
        }
        req.space = planners::parse_space(space);
        req.planner = planners::canonical_planner(planner);
        req.time = time;
        req.seed = seed;
        req.collisions = collisions;
        req.use_assignment = use_assignment;
        req.simplify = simplify;
        req.search_margin = search_margin;
        req.waypoint_step = waypoint_step;
        req.velocity = velocity;
        req.replay = replay;
        req.params.assign(params.begin(), params.end());
        req.fallback = fallback;
        py::gil_scoped_release release;
        return planners::plan(req);
      },
      // The defaults are PlanRequest's.
      py::arg("pattern"), py::arg("goal"), py::arg("start") = py::none(), py::arg("space") = std::string(planners::to_string(planners::PlanRequest{}.space)),
      py::arg("planner") = planners::PlanRequest{}.planner, py::arg("time") = planners::PlanRequest{}.time,
      py::arg("seed") = planners::PlanRequest{}.seed, py::arg("collisions") = planners::PlanRequest{}.collisions,
      py::arg("use_assignment") = planners::PlanRequest{}.use_assignment, py::arg("simplify") = planners::PlanRequest{}.simplify,
      py::arg("search_margin") = planners::PlanRequest{}.search_margin, py::arg("waypoint_step") = planners::PlanRequest{}.waypoint_step,
      py::arg("velocity") = planners::PlanRequest{}.velocity, py::arg("replay") = planners::PlanRequest{}.replay,
      py::arg("params") = std::map<std::string, std::string>{}, py::arg("fallback") = planners::PlanRequest{}.fallback,
      ("Plans from `start` to the closed state `goal`. `start` is None (flat), a FoldSequence (its end state is the start; "
      "the plan's sequence begins with it, as the CLI's --start CMML), or a closed state: then the plan's sequence reaches "
      "it from flat in one straight event, which the replay accepts only where that line stays closed (pass the "
      "FoldSequence otherwise). Planning runs "
      "an OMPL planner by name, as `foldkit plan`: space " + quoted_spaces(0) + " (spaces()); `time` seconds at most; the same seed gives the same plan. `params` sets planner parameters by "
      "OMPL's names, e.g. {'range': '0.3'} (ValueError for one the planner does not have). When the planner finds "
      "none in a quarter of `time`, `fallback` goes through flat: on a single vertex the path of Carpenter's rule on the "
      "sphere (start, flat, goal); in the driving space from a folded start, a plan from flat to the start, reversed, then "
      "one from flat to the goal (at once for a goal known to lie on another branch). The result's `fallback` and "
      "`via_flat` say so. Returns a PlanResult (check `solved`).")
          .c_str());
  m.def("planners", &planners::planner_names, "The planner names plan() accepts.");
  m.def("spaces", &planners::space_names, "The space names plan() accepts ('auto' first).");
}

}  // namespace foldkit::python
