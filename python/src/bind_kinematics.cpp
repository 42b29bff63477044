// Closure kinematics: residual and Jacobian, mobility (dof), projection onto closed states, and
// the facets' poses at a state.
#include "bindings.hpp"
#include "foldkit/geometry/closure.hpp"
#include "foldkit/geometry/closure_path.hpp"
#include "foldkit/geometry/mobility.hpp"
#include "foldkit/geometry/projection.hpp"

namespace foldkit::python {
namespace {

using geometry::ClosureSystem;
using geometry::CreasePattern;

// What `foldkit dof --json` reports, under the same names.
struct DofReport {
  geometry::Mobility mobility;
  std::size_t vertex_loops = 0, hole_cycles = 0;
  double closure_error = 0.0;
};

// The Jacobian as COO arrays; python/foldkit/__init__.py makes a scipy.sparse matrix of them.
py::tuple jacobian_coo(const ClosureSystem& system, const geometry::FoldState& state) {
  Eigen::VectorXd r;
  Eigen::SparseMatrix<double> j;
  {
    py::gil_scoped_release release;
    system.evaluate(state, r, j);
  }
  return sparse_coo(j);
}

void bind_closure_system(py::module_& m) {
  py::class_<ClosureSystem>(m, "ClosureSystem",
                            "The closure equations of a pattern: one rotation loop per interior vertex and one cycle per hole. "
                            "Build it once to evaluate many states; it keeps its pattern alive.")
      .def(py::init<const CreasePattern&, int>(), py::arg("pattern"), py::arg("root") = 0, py::keep_alive<1, 2>(),
           "The closure system of `pattern`, its kinematic tree rooted at actor index `root`.")
      .def_property_readonly("rows", &ClosureSystem::rows, "Number of equations (rows of the Jacobian).")
      .def_property_readonly("cols", &ClosureSystem::cols, "Number of joints (columns of the Jacobian).")
      .def_property_readonly("vertex_loops", &ClosureSystem::vertex_loops, "Interior-vertex loops.")
      .def_property_readonly("hole_cycles", &ClosureSystem::hole_cycles, "Cycles around holes.")
      .def(
          "residual", [](const ClosureSystem& s, const Eigen::VectorXd& state) {
            return s.residual(to_state(s.pattern(), state, "state"));
          },
          py::arg("state"), "The closure residual at `state` (zero on closed states).")
      .def(
          "jacobian_coo", [](const ClosureSystem& s, const Eigen::VectorXd& state) {
            return jacobian_coo(s, to_state(s.pattern(), state, "state"));
          },
          py::arg("state"), "The analytic Jacobian of the residual as (rows, cols, values, shape) COO arrays.")
      .def(
          "max_error", [](const ClosureSystem& s, const Eigen::VectorXd& state) { return s.max_error(to_state(s.pattern(), state, "state")); },
          py::arg("state"), "The largest loop error at `state`, radians (the CLI's closure_error).")
      .def(
          "loop_errors", [](const ClosureSystem& s, const Eigen::VectorXd& state) {
            return py::array(py::cast(s.loop_errors(to_state(s.pattern(), state, "state"))));
          },
          py::arg("state"), "Each loop's error at `state`, radians.");
}

void bind_mobility(py::module_& m) {
  py::class_<DofReport>(m, "Dof", "Mobility at a state: the fields of `foldkit dof --json`.")
      .def_property_readonly("dof", [](const DofReport& d) { return d.mobility.dof; }, "Creases − rank.")
      .def_property_readonly("rank", [](const DofReport& d) { return d.mobility.rank; }, "Numerical rank of the closure Jacobian.")
      .def_property_readonly("creases", [](const DofReport& d) { return d.mobility.creases; }, "Number of joints.")
      .def_property_readonly("tolerance", [](const DofReport& d) { return d.mobility.tolerance; },
                             "Absolute: singular values at or below it count as zero.")
      .def_property_readonly("method", [](const DofReport& d) { return d.mobility.method; },
                             "'dense-svd', 'sparse-qr', 'inverse-subspace' or 'none' (no loop)."
                             " sparse-qr: largest_zero_singular_value is an upper bound and"
                             " smallest_kept_singular_value an estimate (a lower bound once its iteration converged).")
      .def_property_readonly("largest_zero_singular_value", [](const DofReport& d) { return d.mobility.decision.largest_zero; },
                             "Largest singular value counted as zero.")
      .def_property_readonly("smallest_kept_singular_value", [](const DofReport& d) { return d.mobility.decision.smallest_kept; },
                             "Smallest singular value counted as non-zero.")
      .def_property_readonly("rank_gap", [](const DofReport& d) { return d.mobility.decision.gap(); },
                             "smallest_kept / largest_zero: how clear the decision is.")
      .def_readonly("vertex_loops", &DofReport::vertex_loops, "Interior-vertex loops.")
      .def_readonly("hole_cycles", &DofReport::hole_cycles, "Cycles around holes.")
      .def_readonly("closure_error", &DofReport::closure_error, "Largest loop error at the state, radians.")
      .def("__repr__", [](const DofReport& d) {
        return "Dof(dof=" + std::to_string(d.mobility.dof) + ", rank=" + std::to_string(d.mobility.rank) +
               ", creases=" + std::to_string(d.mobility.creases) + ")";
      });
  m.def(
      "dof", [](const CreasePattern& p, const py::object& state, double tolerance) {
        require_positive(tolerance, "tolerance");
        const geometry::FoldState s = state_or_flat(p, state, "state");
        py::gil_scoped_release release;
        const ClosureSystem system(p);
        return DofReport{geometry::mobility(system, s, tolerance), system.vertex_loops(), system.hole_cycles(), system.max_error(s)};
      },
      py::arg("pattern"), py::arg("state") = py::none(), py::arg("tolerance") = geometry::kMobilityTolerance,
      "Instantaneous degrees of freedom at `state` (default flat), as `foldkit dof`; `tolerance` is relative to the largest "
      "singular value.");
}

void bind_projection(py::module_& m) {
  py::class_<geometry::ProjectionResult>(m, "ProjectionResult", "The nearest closed state found by projection.")
      .def_property_readonly("state", [](const geometry::ProjectionResult& r) { return r.state.angles; },
                             "The last accepted state, radians.")
      .def_readonly("status", &geometry::ProjectionResult::status, "How it ended.")
      .def_readonly("iterations", &geometry::ProjectionResult::iterations, "Iterations taken.")
      .def_readonly("error", &geometry::ProjectionResult::error, "Largest loop error at `state`, radians.")
      .def("__repr__", [](const geometry::ProjectionResult& r) {
        return "ProjectionResult(" + std::string(geometry::to_string(r.status.code)) + ", iterations=" + std::to_string(r.iterations) +
               ", error=" + py::repr(py::float_(r.error)).cast<std::string>() + ")";
      });
  m.def(
      "project", [](const CreasePattern& p, const Eigen::VectorXd& state, double tolerance, int max_iterations, bool keep_signs) {
        require_positive(tolerance, "tolerance");
        require(max_iterations >= 1, "max_iterations", "at least 1", max_iterations);
        const geometry::FoldState start = to_state(p, state, "state");
        geometry::ProjectionOptions o;
        o.tolerance = tolerance;
        o.max_iterations = max_iterations;
        o.keep_signs = keep_signs;
        py::gil_scoped_release release;
        return geometry::project(ClosureSystem(p), start, o);
      },
      py::arg("pattern"), py::arg("state"), py::arg("tolerance") = geometry::ProjectionOptions{}.tolerance,
      py::arg("max_iterations") = geometry::ProjectionOptions{}.max_iterations, py::arg("keep_signs") = geometry::ProjectionOptions{}.keep_signs,
      "The closed state nearest to `state` (Levenberg–Marquardt), as `foldkit project`; keep_signs=False lets creases "
      "change between mountain and valley.");
  m.def(
      "goal_from_angles", [](const CreasePattern& p, const std::map<int, double>& angles) {
        std::vector<std::pair<int, double>> held;
        for (const auto& [id, angle] : angles) {
          const auto j = p.joint_index(id);
          if (!j) throw py::value_error("the pattern has no joint " + std::to_string(id));
          require(std::isfinite(angle), "every angle", "finite", angle);
          held.emplace_back(*j, angle);
        }
        std::string why;
        std::optional<geometry::FoldState> goal;
        {
          py::gil_scoped_release release;
          goal = geometry::goal_from_angles(ClosureSystem(p), held, why);
        }
        if (!goal) throw std::runtime_error("no closed state with those angles: " + why);
        return goal->angles;
      },
      py::arg("pattern"), py::arg("angles"),
      "The closed state nearest to flat in which the joints named by ID in `angles` ({id: radians}) have those angles "
      "(`foldkit plan --goal-angles`); RuntimeError when the projection does not converge.");
  m.def(
      "facet_poses", [](const CreasePattern& p, const py::object& states) -> py::array {
        const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(states);
        if (a && a.ndim() == 2) return poses_array(p, states_from_array(p, states, "states"));
        return poses_array(p, {state_or_flat(p, states, "state")})[py::int_(0)].cast<py::array>();
      },
      py::arg("pattern"), py::arg("states"),
      "Each actor's pose (4×4 homogeneous matrix, pattern units; actor 0 fixed) at a state: shape (actors, 4, 4); for a "
      "(states, joints) array, shape (states, actors, 4, 4).");
}

}  // namespace

void bind_kinematics(py::module_& m) {
  bind_closure_system(m);
  bind_mobility(m);
  bind_projection(m);
}

}  // namespace foldkit::python
