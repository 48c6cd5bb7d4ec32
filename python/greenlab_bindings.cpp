// Python bindings: GreenLab plants, their simulation into compressed graphs and reconstruction.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "fspm/compressed_tree_graph.hpp"
#include "fspm/instanced_ctree.hpp"
#include "fspm/line_tree.hpp"
#include "greenlab/expand.hpp"
#include "greenlab/plant_params.hpp"
#include "greenlab/simulation.hpp"
#include "python/bindings.hpp"

namespace fspm::python {

namespace {

void bind_compressed_plant(py::module_& m) {
  py::class_<fspm::CompressedTreeGraph>(
      m, "CompressedPlant",
      "A plant as a compressed tree graph: one record per substructure (GreenLab), or a drawn "
      "L-system with turtle geometry (lsystem_plant)")
      .def("__len__", &fspm::CompressedTreeGraph::size)
      .def_property_readonly("has_geometry", &fspm::CompressedTreeGraph::has_geometry,
                             "Whether the graph carries turtle geometry (a drawn L-system)")
      .def_property_readonly(
          "organs", &fspm::geometry_organ_count,
          "Internodes, leaves and flowers of the explicit plant (records that are not groups; "
          "the metamers of a GreenLab graph)")
      .def_property_readonly("graph_nodes", &fspm::CompressedTreeGraph::size,
                             "Records of the compressed graph (its substructures)")
      .def_property_readonly(
          "metamers", &fspm::CompressedTreeGraph::expanded_size,
          "Metamers of the explicit plant it stands for (sum of the record multiplicities; "
          "with turtle geometry, group records included: see organs)")
      .def(
          "counts",
          [](const fspm::CompressedTreeGraph& g) {
            const fspm::greenlab::OrganCounts c = fspm::greenlab::count_organs(g);
            py::dict d;
            d["metamers"] = c.metamers;
            d["leaves"] = c.leaves;
            d["flowers"] = c.flowers;
            d["buds"] = c.buds;
            d["metamers_by_age"] = c.metamers_by_age;
            return d;
          },
          "Organ counts of the plant the graph stands for")
      .def(
          "save",
          [](const fspm::CompressedTreeGraph& g, const std::string& path) {
            py::gil_scoped_release release;
            fspm::write_ctree_file(g, path);
          },
          py::arg("path"), "Write a .ctree file (atomically)");
}

void bind_greenlab_simulation(py::module_& m) {
  m.def(
      "greenlab_simulate",
      [](const std::string& params_path, std::optional<int> cycles,
         std::optional<std::uint64_t> seed) {
        py::gil_scoped_release release;
        fspm::greenlab::PlantParams params = fspm::greenlab::read_plant_params(params_path);
        std::mt19937_64 rng(seed.value_or(params.seed));
        return fspm::greenlab::simulate_compressed(params, rng, cycles.value_or(-1));
      },
      py::arg("params"), py::arg("cycles") = py::none(), py::arg("seed") = py::none(),
      "Simulate a GreenLab plant (TOML parameters) by substructure factorization");
  m.def(
      "greenlab_simulate",
      [](const fspm::greenlab::PlantParams& params, std::optional<int> cycles,
         std::optional<std::uint64_t> seed) {
        py::gil_scoped_release release;
        std::mt19937_64 rng(seed.value_or(params.seed));
        return fspm::greenlab::simulate_compressed(params, rng, cycles.value_or(-1));
      },
      py::arg("params"), py::arg("cycles") = py::none(), py::arg("seed") = py::none(),
      "Simulate a GreenLab plant from PlantParams");
  m.def(
      "read_plant",
      [](const std::string& path) {
        py::gil_scoped_release release;
        return fspm::read_ctree_file(path);
      },
      py::arg("path"), "Read a .ctree compressed plant");
  m.def(
      "greenlab_reconstruct",
      [](const fspm::CompressedTreeGraph& g, std::optional<double> age, bool leaves) {
        py::gil_scoped_release release;
        fspm::greenlab::ReconstructionOptions o;
        o.age = age.value_or(-1.0);
        o.leaves = leaves;
        return fspm::greenlab::reconstruct(g, o);
      },
      py::arg("plant"), py::arg("age") = py::none(), py::arg("leaves") = true,
      "The explicit tree of a GreenLab plant at any age up to the simulated one, or of a drawn "
      "L-system (lsystem_plant) as its turtle drew it");
}

void bind_line_tree(py::module_& m) {
  py::class_<fspm::LineTree>(m, "LineTree",
                             "Explicit plant geometry in single precision, one record per "
                             "internode, leaf or flower (parents first)")
      .def("__len__", &fspm::LineTree::size)
      .def_property_readonly(
          "parents",
          [](py::object self) {
            return parent_column(self.cast<const fspm::LineTree&>().parents(), self);
          },
          "Parent of every record (int32; -1 for the root), parents first")
      .def_property_readonly(
          "starts",
          [](py::object self) {
            return column(self.cast<const fspm::LineTree&>().starts(), self, 3);
          },
          "Start points (N, 3) float32, m, z up")
      .def_property_readonly(
          "directions",
          [](py::object self) {
            return column(self.cast<const fspm::LineTree&>().directions(), self, 3);
          },
          "Unit headings (N, 3) float32; end = start + direction * length")
      .def_property_readonly(
          "lengths",
          [](py::object self) {
            return column(self.cast<const fspm::LineTree&>().lengths(), self);
          },
          "Lengths (float32, m)")
      .def_property_readonly(
          "radii",
          [](py::object self) { return column(self.cast<const fspm::LineTree&>().radii(), self); },
          "Radii (float32, m)")
      .def_property_readonly(
          "birth_times",
          [](py::object self) {
            return column(self.cast<const fspm::LineTree&>().birth_times(), self);
          },
          "Birth times (float32, growth cycles)")
      .def_property_readonly(
          "orders",
          [](py::object self) { return column(self.cast<const fspm::LineTree&>().orders(), self); },
          "Branching orders (uint16): 0 on the trunk, +1 at each lateral branch")
      .def_property_readonly(
          "physiological_ages",
          [](py::object self) {
            return column(self.cast<const fspm::LineTree&>().physiological_ages(), self);
          },
          "GreenLab physiological ages (uint16, from 1)")
      .def_property_readonly(
          "kinds",
          [](py::object self) {
            const auto k = self.cast<const fspm::LineTree&>().kinds();
            return column(std::span<const std::uint8_t>(
                              reinterpret_cast<const std::uint8_t*>(k.data()), k.size()),
                          self);
          },
          "Organ kinds: 0 internode, 1 leaf, 2 flower")
      .def_property_readonly(
          "dead",
          [](py::object self) { return column(self.cast<const fspm::LineTree&>().dead(), self); },
          "1 for dead organs still on the plant (empty unless the plant has a pruning period)")
      .def("to_tree", &fspm::LineTree::to_tree_graph, "The same plant as a Tree");
  m.def(
      "greenlab_reconstruct_lines",
      [](const fspm::CompressedTreeGraph& g, std::optional<double> age, bool leaves) {
        py::gil_scoped_release release;
        fspm::greenlab::ReconstructionOptions o;
        o.age = age.value_or(-1.0);
        o.leaves = leaves;
        return fspm::greenlab::reconstruct_lines(g, o);
      },
      py::arg("plant"), py::arg("age") = py::none(), py::arg("leaves") = true,
      "The explicit plant as a single-precision LineTree (the same records as "
      "greenlab_reconstruct, several times faster for big plants)");
}

}  // namespace

void bind_greenlab(py::module_& m) {
  bind_compressed_plant(m);
  bind_greenlab_simulation(m);
  bind_line_tree(m);
}

}  // namespace fspm::python
