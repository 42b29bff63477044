// The compiled part of the `foldkit` Python package (foldkit._foldkit); python/foldkit/__init__.py
// re-exports it and adds what is easier in Python (SciPy matrices, summaries).
#include <exception>

#include "bindings.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/simulation/simulate.hpp"

namespace foldkit::python {
namespace {

// A Python exception instance of `type` whose file, line and message are set, so that scripts can
// point at the offending element as the CLI's FILE:LINE: message does.
void raise_located(PyObject* type, const std::string& what, const std::string& file, int line, const std::string& message) {
  py::object error = py::reinterpret_borrow<py::object>(type)(what);
  error.attr("file") = file;
  error.attr("line") = line;
  error.attr("message") = message;
  PyErr_SetObject(type, error.ptr());
}

}  // namespace
}  // namespace foldkit::python

PYBIND11_MODULE(_foldkit, m) {
  namespace py = pybind11;
  using namespace foldkit;
  m.doc() = "foldkit's C++ core: crease patterns, closure kinematics, simulation, planning, folding, stiffness.";

  // Bad input in a file (or a sequence read from one): a ValueError whose text is FILE:LINE: message.
  static py::exception<io::ParseError> parse_error(m, "ParseError", PyExc_ValueError);
  parse_error.doc() =
      "Bad input: a ValueError whose text is 'FILE:LINE: message' (LINE 0 when no line applies), "
      "with attributes file, line and message.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const io::ParseError& e) {
      python::raise_located(parse_error.ptr(), e.what(), e.file(), e.line(), e.message());
    }
  });

  python::bind_pattern(m);
  python::bind_io(m);
  python::bind_kinematics(m);
  python::bind_simulate(m);
  python::bind_plan(m);
  python::bind_algorithms(m);
  python::bind_equilibrium(m);
}
