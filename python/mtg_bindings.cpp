// Python bindings: measured plants in MTG files as multiscale graphs (fspm.read_mtg, fspm.Mtg).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <optional>

#include "fspm/atomic_file.hpp"
#include "fspm/length_unit.hpp"
#include "fspm/mtg_reader.hpp"
#include "fspm/mtg_tree.hpp"
#include "fspm/mtg_writer.hpp"
#include "fspm/warning.hpp"
#include "python/bindings.hpp"

namespace fspm::python {
namespace {

// The graph and the units its file was read in (used by to_tree).
struct PyMtg {
  Mtg mtg;
  MtgTreeOptions options;
};

MtgTreeOptions tree_options(const std::string& length_unit,
                            const std::optional<std::string>& diameter_unit) {
  MtgTreeOptions o;
  o.length_unit = length_unit_from_name(length_unit, "length_unit");
  if (diameter_unit) o.diameter_unit = length_unit_from_name(*diameter_unit, "diameter_unit");
  return o;
}

const char* edge_text(MtgEdge e) {
  return e == MtgEdge::kSuccessor ? "<" : e == MtgEdge::kBranch ? "+" : "";
}

// One list per column for the entities of a scale: their structure, then every feature (numbers
// as floats, NaN where empty; dates and text as strings).
py::dict columns(const Mtg& g, int scale) {
  if (scale < 0 || scale > g.max_scale()) {
    throw ValueError("scale " + std::to_string(scale) + ": expected 0 to " +
                     std::to_string(g.max_scale()));
  }
  const std::vector<MtgVertex> vs = g.vertices(scale);
  py::list vertex, label, symbol, index, complex, parent, edge;
  for (MtgVertex v : vs) {
    vertex.append(v);
    label.append(g.label(v));
    symbol.append(g.symbol(v));
    index.append(g.index(v) >= 0 ? py::object(py::int_(g.index(v))) : py::object(py::none()));
    complex.append(g.complex(v) == kNoMtgVertex ? py::object(py::none()) : py::int_(g.complex(v)));
    parent.append(g.parent(v) == kNoMtgVertex ? py::object(py::none()) : py::int_(g.parent(v)));
    edge.append(edge_text(g.edge(v)));
  }
  py::dict d;
  d["vertex"] = vertex;
  d["label"] = label;
  d["symbol"] = symbol;
  d["index"] = index;
  d["complex"] = complex;
  d["parent"] = parent;
  d["edge"] = edge;
  for (std::size_t f = 0; f < g.features().size(); ++f) {
    const bool number = mtg_feature_is_number(g.features()[f].type);
    py::list values;
    for (MtgVertex v : vs) {
      if (number) {
        values.append(g.feature_number(v, f).value_or(std::numeric_limits<double>::quiet_NaN()));
      } else {
        values.append(std::string(g.feature_text(v, f)));
      }
    }
    d[py::str(g.features()[f].name)] = values;
  }
  return d;
}

}  // namespace

void bind_mtg(py::module_& m) {
  // Library warnings (centimetres read as metres ...) become Python UserWarnings.
  set_warning_handler([](const std::string& message) {
    py::gil_scoped_acquire gil;
    if (PyErr_WarnEx(PyExc_UserWarning, message.c_str(), 1) != 0) PyErr_Clear();
  });
  py::class_<PyMtg>(m, "Mtg",
                    "A multiscale tree graph (Godin and Caraglio 1998) read from an MTG file")
      .def_property_readonly(
          "max_scale", [](const PyMtg& g) { return g.mtg.max_scale(); },
          "The finest scale (the plants are scale 1)")
      .def("__len__", [](const PyMtg& g) { return g.mtg.size() - 1; })
      .def(
          "scale_counts",
          [](const PyMtg& g) {
            std::map<int, std::size_t> c;
            for (MtgVertex v = 1; v < g.mtg.size(); ++v) ++c[g.mtg.scale(v)];
            return c;
          },
          "Entities per scale: {scale: count}")
      .def_property_readonly(
          "features",
          [](const PyMtg& g) {
            std::vector<std::pair<std::string, std::string>> f;
            for (const MtgFeature& x : g.mtg.features()) {
              f.emplace_back(x.name, std::string(mtg_feature_type_name(x.type)));
            }
            return f;
          },
          "The features: (name, type) in file order")
      .def(
          "columns", [](const PyMtg& g, int scale) { return columns(g.mtg, scale); },
          py::arg("scale"),
          "The entities of one scale as a dict of lists (vertex, label, symbol, index, complex, "
          "parent, edge, then one per feature); to_dataframe makes a pandas DataFrame of it")
      .def(
          "to_tree",
          [](const PyMtg& g, int scale, const std::string& plant) {
            MtgTreeOptions o = g.options;
            o.scale = scale;
            o.plant = plant;
            return mtg_to_tree(g.mtg, o);
          },
          py::arg("scale") = -1, py::arg("plant") = "",
          "The Tree of one scale (default: the finest with geometry), in metres; plant keeps one "
          "plant (its label or number)")
      .def(
          "write",
          [](const PyMtg& g, const std::string& path) {
            write_file_atomically(path, [&](std::ostream& out) { write_mtg(g.mtg, out, path); });
          },
          py::arg("path"), "Write the graph as an MTG file (scales and features kept)");
  m.def(
      "read_mtg",
      [](const std::string& path, const std::string& length_unit,
         const std::optional<std::string>& diameter_unit) {
        PyMtg g{Mtg{}, tree_options(length_unit, diameter_unit)};
        std::vector<std::string> warnings;
        {
          py::gil_scoped_release release;
          g.mtg = read_mtg_file(path, &warnings);
        }
        for (const std::string& w : warnings) warn(w);
        return g;
      },
      py::arg("path"), py::arg("length_unit") = "m", py::arg("diameter_unit") = py::none(),
      "Read an MTG file into its multiscale graph; length_unit (m, dm, cm, mm) is the unit of "
      "its coordinates and lengths, diameter_unit (default: length_unit) that of its diameters");
}

}  // namespace fspm::python
