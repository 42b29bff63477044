#include <cmath>
#include <sstream>

#include "bindings.hpp"
#include "foldkit/geometry/kinematics.hpp"
#include "foldkit/io/parse_error.hpp"

namespace foldkit::python {

py::tuple sparse_coo(const Eigen::SparseMatrix<double>& m) {
  std::vector<int> rows, cols;
  std::vector<double> values;
  rows.reserve(static_cast<std::size_t>(m.nonZeros()));
  cols.reserve(static_cast<std::size_t>(m.nonZeros()));
  values.reserve(static_cast<std::size_t>(m.nonZeros()));
  for (int k = 0; k < m.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(m, k); it; ++it) {
      rows.push_back(static_cast<int>(it.row()));
      cols.push_back(static_cast<int>(it.col()));
      values.push_back(it.value());
    }
  return py::make_tuple(py::array(py::cast(rows)), py::array(py::cast(cols)), py::array(py::cast(values)),
                        py::make_tuple(m.rows(), m.cols()));
}

geometry::FoldState to_state(const geometry::CreasePattern& pattern, const Eigen::VectorXd& angles, const char* what) {
  const auto joints = static_cast<Eigen::Index>(pattern.joints().size());
  if (angles.size() != joints)
    throw py::value_error(std::string(what) + " has " + std::to_string(angles.size()) + " angles; the pattern has " +
                          std::to_string(joints) + " joints (one angle per joint, radians, in joint order)");
  for (Eigen::Index i = 0; i < angles.size(); ++i)
    if (!std::isfinite(angles[i]))
      throw py::value_error(std::string(what) + "[" + std::to_string(i) + "] (joint " +
                            std::to_string(pattern.joints()[static_cast<std::size_t>(i)].id) + ") is not finite");
  return geometry::FoldState{angles};
}

geometry::FoldState state_or_flat(const geometry::CreasePattern& pattern, const py::object& angles, const char* what) {
  if (angles.is_none()) return geometry::FoldState::flat(pattern);
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(angles);
  if (!a || a.ndim() != 1) throw py::value_error(std::string(what) + " must be a 1-D array of angles (radians), or None for flat");
  return to_state(pattern, Eigen::Map<const Eigen::VectorXd>(a.data(), a.shape(0)), what);
}

py::array_t<double> states_array(const std::vector<geometry::FoldState>& states, Eigen::Index joints) {
  if (joints < 0) joints = states.empty() ? 0 : states.front().angles.size();
  py::array_t<double> out({static_cast<py::ssize_t>(states.size()), static_cast<py::ssize_t>(joints)});
  auto a = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < states.size(); ++i)
    for (Eigen::Index j = 0; j < joints; ++j) a(static_cast<py::ssize_t>(i), j) = states[i].angles[j];
  return out;
}

std::vector<geometry::FoldState> states_from_array(const geometry::CreasePattern& pattern, const py::object& rows,
                                                   const char* what) {
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(rows);
  if (!a || a.ndim() != 2) throw py::value_error(std::string(what) + " must be a 2-D array: one state (row) per waypoint");
  std::vector<geometry::FoldState> out;
  const auto view = a.unchecked<2>();
  for (py::ssize_t i = 0; i < view.shape(0); ++i) {
    Eigen::VectorXd angles(view.shape(1));
    for (py::ssize_t j = 0; j < view.shape(1); ++j) angles[j] = view(i, j);
    out.push_back(to_state(pattern, angles, (std::string(what) + "[" + std::to_string(i) + "]").c_str()));
  }
  return out;
}

py::array_t<double> poses_array(const geometry::CreasePattern& pattern, const std::vector<geometry::FoldState>& states) {
  const geometry::KinematicTree tree = geometry::make_tree(pattern);
  py::array_t<double> out({static_cast<py::ssize_t>(states.size()), static_cast<py::ssize_t>(pattern.actors().size()),
                           py::ssize_t{4}, py::ssize_t{4}});
  auto a = out.mutable_unchecked<4>();
  for (std::size_t t = 0; t < states.size(); ++t) {
    const auto poses = geometry::facet_poses(pattern, tree, states[t]);
    for (std::size_t i = 0; i < poses.size(); ++i)
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) a(static_cast<py::ssize_t>(t), static_cast<py::ssize_t>(i), r, c) = poses[i].matrix()(r, c);
  }
  return out;
}

void require(bool ok, const char* name, const char* what, double value) {
  if (ok) return;
  std::ostringstream out;
  out << name << " must be " << what << " (got " << value << ")";
  throw py::value_error(out.str());
}

void require_positive(double x, const char* name) { require(std::isfinite(x) && x > 0.0, name, "positive and finite", x); }

void deprecated(const std::string& what) {
  // Level 1: called from C++ bound code, the frame that warns is the caller's Python line.
  if (PyErr_WarnEx(PyExc_DeprecationWarning, what.c_str(), 1) != 0) throw py::error_already_set();
}

double renamed(double value, double default_value, const py::object& old, const char* old_name, const char* new_name) {
  if (old.is_none()) return value;
  if (value != default_value) throw py::type_error(std::string("give ") + new_name + "= or its old name " + old_name + "=, not both");
  deprecated(std::string(old_name) + "= is deprecated: use " + new_name + "=");
  if (!py::isinstance<py::float_>(old) && !py::isinstance<py::int_>(old))
    throw py::type_error(std::string(old_name) + " must be a number");
  return old.cast<double>();
}

std::string source_of(const py::object& sequence) {
  return py::hasattr(sequence, "source") ? py::str(sequence.attr("source")).cast<std::string>() : std::string("<sequence>");
}

geometry::FoldState checked_end_state(const geometry::CreasePattern& pattern, const geometry::FoldSequence& sequence,
                                      const std::string& source) {
  require_valid(pattern, sequence, source);
  return geometry::end_state(pattern, sequence);
}

void require_valid(const geometry::CreasePattern& pattern, const geometry::FoldSequence& sequence, const std::string& source) {
  for (const auto& d : geometry::check_sequence(pattern, sequence))
    if (d.severity == geometry::Severity::Error) throw io::ParseError(source, d.line, d.message);
}

}  // namespace foldkit::python
