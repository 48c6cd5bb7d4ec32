// Python bindings (pybind11): the module fspm._fspm. Long computations release the GIL; tree
// columns are exposed as numpy arrays that view the C++ memory and keep the Tree alive. Each
// bind_*() (python/*_bindings.cpp) adds one family of classes and functions.
#include <pybind11/pybind11.h>

#include "python/bindings.hpp"

PYBIND11_MODULE(_fspm, m) {
  m.doc() = "fspm core bindings";
  // The version of project(fspm VERSION ...), the one `fspm --version` prints.
  m.attr("__version__") = FSPM_VERSION;
  namespace python = fspm::python;
  python::bind_errors(m);
  python::bind_calibration(m);
  python::bind_tree(m);
  python::bind_mtg(m);
  python::bind_distance(m);
  python::bind_greenlab(m);
  python::bind_experiments(m);
  python::bind_lsystem(m);
  python::bind_statistics(m);
  python::bind_environment(m);
  python::bind_graphics(m);
  python::bind_stages(m);
  python::bind_scans(m);
  python::bind_io(m);
  python::bind_crown(m);
}
