// Python bindings: the constrained edit distance and the node selections it uses.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "fspm/constrained_edit_distance.hpp"
#include "fspm/edit_cost_model.hpp"
#include "fspm/error.hpp"
#include "python/bindings.hpp"

namespace fspm::python {
namespace {

// The Manhattan cost model on per-node feature rows given from Python as (Fa, Fb).
fspm::FeatureCostModel feature_model(const TreeGraph& a, const TreeGraph& b,
                                     const py::tuple& features, double unit_cost) {
  using Rows = py::array_t<double, py::array::c_style | py::array::forcecast>;
  if (features.size() != 2) throw fspm::ValueError("features: expected a pair (Fa, Fb)");
  const Rows fa = features[0].cast<Rows>();
  const Rows fb = features[1].cast<Rows>();
  const auto dims = [](const Rows& f, const TreeGraph& t, const char* which) {
    if (f.ndim() > 2 || f.shape(0) != static_cast<py::ssize_t>(t.size())) {
      throw fspm::ValueError(std::string("features: ") + which + " needs one row per node (" +
                             std::to_string(t.size()) + " rows)");
    }
    return f.ndim() == 1 ? std::size_t{1} : static_cast<std::size_t>(f.shape(1));
  };
  const std::size_t da = dims(fa, a, "Fa");
  if (dims(fb, b, "Fb") != da) {
    throw fspm::ValueError("features: Fa and Fb need the same number of columns");
  }
  return fspm::FeatureCostModel(da, std::vector<double>(fa.data(), fa.data() + fa.size()),
                                std::vector<double>(fb.data(), fb.data() + fb.size()), unit_cost);
}

}  // namespace

void bind_distance(py::module_& m) {
  m.def(
      "distance",
      [](const TreeGraph& a, const TreeGraph& b, const std::string& cost,
         const std::vector<std::string>& attributes, std::optional<double> main_skeleton,
         bool mapping, const std::string& solver, std::optional<py::tuple> features,
         double unit_cost) {
        fspm::EditDistanceOptions o;
        o.cost = fspm::edit_cost_kind_from_name(cost);
        o.attributes = attributes;
        o.main_skeleton_radius_m = main_skeleton;
        o.with_mapping = mapping;
        o.solver = fspm::assignment_solver_from_name(solver);
        std::optional<fspm::FeatureCostModel> model;
        if (features) model = feature_model(a, b, *features, unit_cost);
        fspm::EditDistanceResult r;
        {
          py::gil_scoped_release release;
          r = model ? fspm::constrained_edit_distance(a, b, *model, o)
                    : fspm::constrained_edit_distance(a, b, o);
        }
        py::dict d;
        d["distance"] = r.distance;
        d["normalized_distance"] = r.normalized;
        d["deletion_cost_a"] = r.deletion_cost_a;
        d["insertion_cost_b"] = r.insertion_cost_b;
        d["nodes_a"] = r.nodes_a;
        d["nodes_b"] = r.nodes_b;
        if (mapping) d["mapping"] = r.mapping;
        return d;
      },
      py::arg("a"), py::arg("b"), py::arg("cost") = "topological",
      py::arg("attributes") = std::vector<std::string>{}, py::arg("main_skeleton") = py::none(),
      py::arg("mapping") = false, py::arg("solver") = "hungarian", py::arg("features") = py::none(),
      py::arg("unit_cost") = 1.0,
      "Constrained edit distance (Zhang; Ferraro and Godin; Pirk eq. 4.15-4.22). cost: "
      "topological, absolute or standardized over `attributes`; main_skeleton: compare only "
      "nodes thicker than this radius (and their ancestors); features=(Fa, Fb), arrays of one "
      "row per node, gives the Manhattan cost model instead (delete/insert = unit_cost + |f|); "
      "solver: hungarian or min-cost-flow; mapping: also return the matched (a, b) node pairs");
  m.def(
      "main_skeleton_nodes",
      [](const TreeGraph& t, double min_radius) {
        return adopt(fspm::main_skeleton_nodes(t, min_radius));
      },
      py::arg("tree"), py::arg("min_radius"),
      "Ids of the nodes thicker than min_radius whose ancestors all are");
  m.def(
      "node_attribute_values",
      [](const TreeGraph& t, const std::string& name) {
        return adopt(fspm::node_attribute_values(t, name));
      },
      py::arg("tree"), py::arg("name"),
      "One value per node: length, radius, birth_time, order, physiological_age or a user "
      "attribute");
}

}  // namespace fspm::python
