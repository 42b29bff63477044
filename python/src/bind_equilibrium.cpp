// The stiffness problem's equilibrium equations (analysis::EquilibriumSystem) for scripts that
// solve or study them with tools of their own, e.g. SciPy (microbench/stiffness_scipy.py):
// residual, tangent, retraction, in the solver's scaled units.
#include "bindings.hpp"
#include "foldkit/analysis/load_case.hpp"
#include "foldkit/analysis/solver.hpp"
#include "foldkit/analysis/structure.hpp"

namespace foldkit::python {
namespace {

using analysis::EquilibriumSystem;

void require_size(const EquilibriumSystem& sys, const Eigen::VectorXd& v, const char* name) {
  require(v.size() == sys.size(), name, "of length `size` (6 per free module); its length", static_cast<double>(v.size()));
}

py::tuple tangent_coo(const EquilibriumSystem& sys, const Eigen::VectorXd& x, double load_factor, bool geometric) {
  require_size(sys, x, "x");
  Eigen::SparseMatrix<double> h;
  {
    py::gil_scoped_release release;
    h = sys.tangent(x, load_factor, geometric);
  }
  return sparse_coo(h);
}

}  // namespace

void bind_equilibrium(py::module_& m) {
  py::class_<EquilibriumSystem>(
      m, "EquilibriumSystem",
      "The equilibrium equations that `stiffness` solves, in scaled units (lengths in length_unit, forces in "
      "force_unit): unknowns x hold, per free module, its centroid's displacement and its rotation vector (6 "
      "entries, free_modules order); residual(x) is the gradient of the potential with respect to a left "
      "perturbation of each module and vanishes at equilibrium; tangent(x) is its derivative; retract(x, dx) "
      "applies a perturbation. docs/STIFFNESS.md.")
      .def_property_readonly("size", &EquilibriumSystem::size, "Number of unknowns: 6 per free module.")
      .def_property_readonly("length_unit", &EquilibriumSystem::length_unit, "L, the length unit (the tile size), pattern units.")
      .def_property_readonly("force_unit", &EquilibriumSystem::force_unit, "F0, the force unit (the largest load), N.")
      .def_property_readonly("free_modules", &EquilibriumSystem::free_modules, "Free modules (indices) in unknown order.")
      .def(
          "residual",
          [](const EquilibriumSystem& sys, const Eigen::VectorXd& x, double load_factor) {
            require_size(sys, x, "x");
            py::gil_scoped_release release;
            return Eigen::VectorXd(sys.residual(x, load_factor));
          },
          py::arg("x"), py::arg("load_factor") = 1.0, "The residual at x, the loads scaled by load_factor; zero at equilibrium.")
      .def("tangent_coo", &tangent_coo, py::arg("x"), py::arg("load_factor") = 1.0, py::arg("geometric") = true,
           "The tangent at x as COO arrays (rows, cols, values, shape); tangent() gives a scipy.sparse matrix.")
      .def(
          "retract",
          [](const EquilibriumSystem& sys, const Eigen::VectorXd& x, const Eigen::VectorXd& dx) {
            require_size(sys, x, "x");
            require_size(sys, dx, "dx");
            return Eigen::VectorXd(sys.retract(x, dx));
          },
          py::arg("x"), py::arg("dx"), "x after the left perturbation dx (a screw motion per module).")
      .def(
          "residual_floor", [](const EquilibriumSystem& sys, const Eigen::VectorXd& x) {
            require_size(sys, x, "x");
            return sys.residual_floor(x);
          },
          py::arg("x"), "The round-off level of the residual's entries at x: below it, a residual is as good as zero.");
  m.def(
      "equilibrium_system",
      [](const geometry::CreasePattern& p, const py::object& load_case, const py::object& state, double detect_tolerance) {
        const analysis::Problem problem = stiffness_problem(p, load_case, state, detect_tolerance);
        py::gil_scoped_release release;
        return EquilibriumSystem(problem);
      },
      py::arg("pattern"), py::arg("load_case"), py::arg("state") = py::none(), py::arg("detect_tolerance") = analysis::DetectOptions{}.tolerance,
      "The equilibrium equations of the folded `pattern` at `state` (default flat) under `load_case` (a path or a "
      "LoadCase): the system `stiffness` solves, for solving or studying it with other tools.");
}

analysis::Problem stiffness_problem(const geometry::CreasePattern& pattern, const py::object& load_case, const py::object& state,
                                    double detect_tolerance) {
  require_positive(detect_tolerance, "detect_tolerance");
  const bool from_file = py::isinstance<py::str>(load_case);
  const std::string name = from_file ? load_case.cast<std::string>() : std::string("<load case>");
  const analysis::LoadCase lc = from_file ? analysis::read_load_case(name) : load_case.cast<analysis::LoadCase>();
  const geometry::FoldState s = state_or_flat(pattern, state, "state");
  analysis::DetectOptions detect;
  detect.tolerance = detect_tolerance;
  py::gil_scoped_release release;
  return analysis::make_problem(analysis::build_structure(pattern, s, detect), lc, name);
}

}  // namespace foldkit::python
