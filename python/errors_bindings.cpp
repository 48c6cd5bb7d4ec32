// Python bindings: the exception classes. Every fspm error is fspm.Error and the matching
// built-in exception at once.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "fspm/error.hpp"
#include "python/bindings.hpp"

namespace fspm::python {
namespace {

// A new exception class fspm._fspm.NAME deriving from every class in `bases`, added to the module;
// kept alive for the interpreter's lifetime.
PyObject* new_exception(py::module_& m, const char* name, const char* doc,
                        std::initializer_list<PyObject*> bases) {
  py::tuple base_tuple(bases.size());
  std::size_t k = 0;
  for (PyObject* b : bases) base_tuple[k++] = py::reinterpret_borrow<py::object>(b);
  const std::string full = std::string("fspm._fspm.") + name;
  PyObject* type = PyErr_NewExceptionWithDoc(full.c_str(), doc, base_tuple.ptr(), nullptr);
  if (type == nullptr) throw py::error_already_set();
  m.add_object(name, py::reinterpret_borrow<py::object>(type));
  return type;
}
}  // namespace

void bind_errors(py::module_& m) {
  static PyObject* const error = new_exception(
      m, "Error",
      "Base of every error fspm raises for a user mistake (a RuntimeError); the message says where "
      "(file, line, column when known) and what was expected",
      {PyExc_RuntimeError});
  static PyObject* const parse_error =
      new_exception(m, "ParseError",
                    "A malformed input text: tree file, Newick string, grammar, TOML, CSV ... "
                    "(also a ValueError)",
                    {error, PyExc_ValueError});
  static PyObject* const io_error =
      new_exception(m, "IoError", "A file that cannot be opened, read or written (also an OSError)",
                    {error, PyExc_OSError});
  // Named as Python's own exceptions, of which they are subclasses, so that the name in a
  // traceback reads as the built-in one (fspm.FileNotFoundError, fspm.ValueError).
  static PyObject* const file_not_found = new_exception(
      m, "FileNotFoundError",
      "An input file that does not exist (also an IoError, an OSError and the built-in "
      "FileNotFoundError); also named fspm.MissingFileError",
      {io_error, PyExc_FileNotFoundError});
  static PyObject* const value_error = new_exception(
      m, "ValueError",
      "A parameter outside its valid range, an unknown name or an impossible request (also the "
      "built-in ValueError); also named fspm.ParameterError",
      {error, PyExc_ValueError});
  static PyObject* const memory_error = new_exception(
      m, "MemoryLimitError",
      "A computation whose estimated memory is above the limit of set_memory_limit (also a "
      "MemoryError); the message gives the estimate and the limit",
      {error, PyExc_MemoryError});
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const fspm::ParseError& e) {
      PyErr_SetString(parse_error, e.what());
    } catch (const fspm::FileNotFoundError& e) {
      PyErr_SetString(file_not_found, e.what());
    } catch (const fspm::IoError& e) {
      PyErr_SetString(io_error, e.what());
    } catch (const fspm::ValueError& e) {
      PyErr_SetString(value_error, e.what());
    } catch (const fspm::MemoryLimitError& e) {
      PyErr_SetString(memory_error, e.what());
    } catch (const fspm::Error& e) {
      PyErr_SetString(error, e.what());
    }
  });
}

}  // namespace fspm::python
