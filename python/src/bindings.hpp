// What the binding files share: one bind_* function per file, called by module.cpp, and the
// conversions every file needs (states, statuses, patterns kept alive by what refers to them).
#pragma once
#include <string>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "foldkit/analysis/equilibrium.hpp"
#include "foldkit/geometry/crease_pattern.hpp"
#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/geometry/fold_state.hpp"
#include "foldkit/geometry/status.hpp"

namespace foldkit::python {

namespace py = pybind11;

void bind_pattern(py::module_& m);
void bind_io(py::module_& m);
void bind_kinematics(py::module_& m);
void bind_simulate(py::module_& m);
void bind_plan(py::module_& m);
void bind_algorithms(py::module_& m);
void bind_equilibrium(py::module_& m);

/// Checks that `angles` has one finite angle per joint of `pattern` (ValueError otherwise) and
/// wraps it. `what` names the argument in the message ("state", "goal", …).
geometry::FoldState to_state(const geometry::CreasePattern& pattern, const Eigen::VectorXd& angles, const char* what);

/// The flat state when `angles` is None, else to_state().
geometry::FoldState state_or_flat(const geometry::CreasePattern& pattern, const py::object& angles, const char* what);

/// States as a (len(states), joints) float array, radians; `joints` gives the width when there are
/// none (−1: the first state's size, 0 when there is none).
py::array_t<double> states_array(const std::vector<geometry::FoldState>& states, Eigen::Index joints = -1);

/// Rows of a 2-D float array as states of `pattern` (checked by to_state()).
std::vector<geometry::FoldState> states_from_array(const geometry::CreasePattern& pattern, const py::object& rows,
                                                   const char* what);

/// Each actor's 4×4 pose at each state: shape (states, actors, 4, 4), pattern units.
py::array_t<double> poses_array(const geometry::CreasePattern& pattern, const std::vector<geometry::FoldState>& states);

/// Raises ValueError("NAME must be WHAT (got VALUE)") unless `ok`.
void require(bool ok, const char* name, const char* what, double value);

/// require() that `x` is positive and finite.
void require_positive(double x, const char* name);

/// Issues a DeprecationWarning saying `what` (an error when warnings are errors).
void deprecated(const std::string& what);

/// A keyword renamed by issue 37 (one word, one meaning): `value`, the new keyword's, unless the
/// caller gave the old one (`old` not None): then that, with a DeprecationWarning. TypeError when
/// both were given (the new one differing from its default `default_value`) or `old` is no number.
double renamed(double value, double default_value, const py::object& old, const char* old_name, const char* new_name);

/// The result class `cls`'s `seconds` (wall-clock seconds it ran), and `time`, its name before
/// issue 37, which still reads it with a DeprecationWarning.
template <class Result>
py::class_<Result> def_seconds(py::class_<Result> cls, const char* doc) {
  const std::string warning = std::string(py::str(cls.attr("__name__"))) + ".time is deprecated: use seconds";
  cls.def_readonly("seconds", &Result::seconds, doc);
  cls.def_property_readonly(
      "time",
      [warning](const Result& r) {
        deprecated(warning);
        return r.seconds;
      },
      "Deprecated name of `seconds`.");
  return cls;
}

/// The file a FoldSequence object was read from (its `source`), or "<sequence>".
std::string source_of(const py::object& sequence);

/// Raises io::ParseError at `source`'s line for the first error geometry::check_sequence finds
/// (a joint the pattern lacks, a joint twice in one event), as the CLI does for a CMML.
void require_valid(const geometry::CreasePattern& pattern, const geometry::FoldSequence& sequence, const std::string& source);

/// The end state of `sequence` after require_valid(): what the CLI takes from a --goal, --start or
/// --state CMML.
geometry::FoldState checked_end_state(const geometry::CreasePattern& pattern, const geometry::FoldSequence& sequence,
                                      const std::string& source);

/// A sparse matrix as COO arrays (rows, cols, values, shape); python/foldkit/__init__.py makes a
/// scipy.sparse matrix of them.
py::tuple sparse_coo(const Eigen::SparseMatrix<double>& m);

/// The stiffness problem of the folded `pattern` at `state` (None: flat) under `load_case` (a
/// path or a LoadCase), contacts found to `detect_tolerance`; built with the GIL released.
analysis::Problem stiffness_problem(const geometry::CreasePattern& pattern, const py::object& load_case, const py::object& state,
                                    double detect_tolerance);

}  // namespace foldkit::python
