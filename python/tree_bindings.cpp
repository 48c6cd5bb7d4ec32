// Python bindings: the Tree class, tree files, Newick text and the memory limit.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "fspm/memory_budget.hpp"
#include "fspm/newick_format.hpp"
#include "fspm/number_text.hpp"
#include "fspm/tree_file.hpp"
#include "fspm/tree_summary.hpp"
#include "python/bindings.hpp"

namespace fspm::python {
namespace {

py::dict summary_dict(const TreeGraph& t) {
  const fspm::TreeSummary s = fspm::summarize(t);
  py::dict d;
  d["nodes"] = s.nodes;
  d["internodes"] = s.internodes;
  d["leaves"] = s.leaves;
  d["flowers"] = s.flowers;
  d["buds"] = s.buds;
  d["tips"] = s.tips;
  d["max_order"] = s.max_order;
  d["max_depth"] = s.max_depth;
  d["height"] = s.height_m;
  d["total_length"] = s.total_length_m;
  return d;
}

fspm::TreeGraph tree_from_arrays(
    const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& parents,
    const PointArray& starts, const PointArray& ends, std::optional<Sample> radii,
    std::optional<Sample> birth_times,
    std::optional<py::array_t<std::uint16_t, py::array::c_style | py::array::forcecast>> orders,
    std::optional<py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>> kinds,
    const std::map<std::string, Sample>& attributes) {
  const auto n = static_cast<std::size_t>(parents.size());
  const auto s = as_points(starts, "starts");
  const auto e = as_points(ends, "ends");
  const auto check = [n](std::size_t size, const std::string& what) {
    if (size != n) {
      throw fspm::ValueError(what + ": expected " + std::to_string(n) + " values (one per node)");
    }
  };
  check(s.size(), "starts");
  check(e.size(), "ends");
  if (radii) check(static_cast<std::size_t>(radii->size()), "radii");
  if (birth_times) check(static_cast<std::size_t>(birth_times->size()), "birth_times");
  if (orders) check(static_cast<std::size_t>(orders->size()), "orders");
  if (kinds) check(static_cast<std::size_t>(kinds->size()), "kinds");
  TreeGraph t;
  t.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::int64_t p = parents.data()[i];
    // The root's parent is -1, or kNoNode as Tree.parents gives it.
    const bool root = p == -1 || p == std::int64_t{fspm::kNoNode};
    if (i == 0 ? !root : (p < 0 || static_cast<std::size_t>(p) >= i)) {
      throw fspm::ValueError("parents[" + std::to_string(i) +
                             "]: expected -1 for the root (node 0) and a smaller node id for "
                             "every other node");
    }
    fspm::NodeData d;
    d.start = s[i];
    d.end = e[i];
    if (radii) d.radius = radii->data()[i];
    if (birth_times) d.birth_time = birth_times->data()[i];
    if (orders) d.order = orders->data()[i];
    if (kinds) {
      if (kinds->data()[i] > 3) throw fspm::ValueError("kinds: expected values 0 to 3");
      d.kind = static_cast<fspm::OrganKind>(kinds->data()[i]);
    }
    t.add_node(i == 0 ? fspm::kNoNode : static_cast<fspm::NodeId>(p), d);
  }
  for (const auto& [name, values] : attributes) {
    check(static_cast<std::size_t>(values.size()), "attribute " + name);
    t.add_attribute(name);
    auto out = t.attribute(name);
    std::copy(values.data(), values.data() + n, out.begin());
  }
  return t;
}

void bind_tree_class(py::module_& m) {
  py::class_<TreeGraph>(m, "Tree", "A plant's tree graph: one node per internode or organ")
      .def(py::init<>(), "An empty tree")
      .def("__len__", &TreeGraph::size)
      .def("__repr__",
           [](const TreeGraph& t) {
             return "<fspm.Tree with " + std::to_string(t.size()) + " nodes>";
           })
      .def_property_readonly(
          "parents",
          [](py::object self) {
            return parent_column(self.cast<const TreeGraph&>().parents(), self);
          },
          "Parent of every node (int32; -1 for the root)")
      .def_property_readonly(
          "starts",
          [](py::object self) { return column(self.cast<const TreeGraph&>().starts(), self, 3); },
          "Segment start points (N, 3): m (model units for L-system trees), z up")
      .def_property_readonly(
          "ends",
          [](py::object self) { return column(self.cast<const TreeGraph&>().ends(), self, 3); },
          "Segment end points (N, 3): m (model units for L-system trees), z up")
      .def_property_readonly(
          "directions",
          [](py::object self) {
            return column(self.cast<const TreeGraph&>().directions(), self, 3);
          },
          "Unit headings (N, 3), also of zero-length organs")
      .def_property_readonly(
          "lengths",
          [](py::object self) { return column(self.cast<const TreeGraph&>().lengths(), self); },
          "Segment lengths: m (model units for L-system trees)")
      .def_property_readonly(
          "radii",
          [](py::object self) { return column(self.cast<const TreeGraph&>().radii(), self); },
          "Radii: m (model units for L-system trees)")
      .def_property_readonly(
          "birth_times",
          [](py::object self) { return column(self.cast<const TreeGraph&>().birth_times(), self); },
          "Birth times: growth cycle or year, may be fractional")
      .def_property_readonly(
          "orders",
          [](py::object self) { return column(self.cast<const TreeGraph&>().orders(), self); },
          "Branching orders (uint16): 0 on the trunk, +1 at each lateral branch")
      .def_property_readonly(
          "physiological_ages",
          [](py::object self) {
            return column(self.cast<const TreeGraph&>().physiological_ages(), self);
          },
          "GreenLab physiological ages (uint16, 1 by default)")
      .def_property_readonly(
          "kinds",
          [](py::object self) {
            const auto k = self.cast<const TreeGraph&>().kinds();
            return column(std::span<const std::uint8_t>(
                              reinterpret_cast<const std::uint8_t*>(k.data()), k.size()),
                          self);
          },
          "Organ kinds: 0 internode, 1 leaf, 2 flower, 3 bud")
      .def("attribute_names", &TreeGraph::attribute_names,
           "Names of the user attribute columns (light, pruned, label ...)")
      .def(
          "attribute",
          [](py::object self, const std::string& name) {
            const auto values = self.cast<const TreeGraph&>().attribute(name);
            return column(values, self);
          },
          py::arg("name"), "A user attribute column (read-only view)")
      .def("summary", &summary_dict, "Node counts, height and total length")
      .def_static("from_arrays", &tree_from_arrays, py::arg("parents"), py::arg("starts"),
                  py::arg("ends"), py::arg("radii") = py::none(),
                  py::arg("birth_times") = py::none(), py::arg("orders") = py::none(),
                  py::arg("kinds") = py::none(),
                  py::arg("attributes") = std::map<std::string, Sample>{},
                  "A tree from columns: parents (-1 for the root, else a smaller id), starts and "
                  "ends (N, 3), optional radii, birth times, orders, kinds and user attributes")
      .def(
          "copy", [](const TreeGraph& t) { return TreeGraph(t); }, "An independent copy");
}

void bind_tree_functions(py::module_& m) {
  m.def("format_significant", &fspm::format_significant, py::arg("value"), py::arg("digits") = 4,
        "A number as people read it, as the command line prints it: `digits` significant digits "
        "(1 to 17), integer parts never cut, magnitudes below 1e-12 (rounding noise) as '0'");
  m.def(
      "set_memory_limit",
      [](std::optional<std::variant<std::uint64_t, std::string>> limit) {
        if (!limit) {
          fspm::set_memory_limit_bytes(0);
        } else if (const auto* bytes = std::get_if<std::uint64_t>(&*limit)) {
          if (*bytes == 0) throw fspm::ValueError("memory limit: expected a positive size, got 0");
          fspm::set_memory_limit_bytes(*bytes);
        } else {
          fspm::set_memory_limit_bytes(
              fspm::parse_memory_size(std::get<std::string>(*limit), "memory limit"));
        }
      },
      py::arg("limit"),
      "Limit the memory fspm may plan to use, in bytes or as text ('512M', '2G'); None restores "
      "the default (half of the physical memory, or of the ulimit or cgroup limit). Requests above "
      "it raise MemoryLimitError, a "
      "MemoryError, before anything is allocated");
  m.def(
      "memory_limit", [] { return fspm::memory_limit_bytes(); },
      "The memory limit in bytes (see set_memory_limit)");
  m.def(
      "read_tree",
      [](const std::string& path, const std::string& format) {
        py::gil_scoped_release release;
        return fspm::read_tree_file(path, format);
      },
      py::arg("path"), py::arg("format") = "", "Read a .tree, .treeb, .nwk or .mtg file");
  m.def(
      "write_tree",
      [](const TreeGraph& t, const std::string& path, const std::string& format) {
        py::gil_scoped_release release;
        fspm::write_tree_file(t, path, format);
      },
      py::arg("tree"), py::arg("path"), py::arg("format") = "",
      "Write a tree (.tree, .treeb, .nwk or .mtg), atomically");
  m.def(
      "parse_newick", [](const std::string& text) { return fspm::parse_newick(text); },
      py::arg("text"),
      "A tree from Newick text ending in ';': numeric node labels become the attribute 'label', "
      "branch lengths 'branch_length' (NaN where missing); names are dropped "
      "(parse_newick_named keeps them)");
  m.def(
      "parse_newick_named",
      [](const std::string& text) {
        fspm::NamedTree t = fspm::parse_newick_named(text);
        return py::make_tuple(std::move(t.tree), std::move(t.names));
      },
      py::arg("text"),
      "(tree, names) from Newick text: the tree as parse_newick gives it and one name per node "
      "(taxon names and quoted labels; '' where a node has none or a numeric label)");
  m.def(
      "to_newick",
      [](const TreeGraph& t, const std::vector<std::string>& names) {
        return fspm::to_newick_named(t, names);
      },
      py::arg("tree"), py::arg("names") = std::vector<std::string>{},
      "The tree as Newick text: topology, the attribute 'label' as node labels and "
      "'branch_length' when present; with names (one per node), a node's name, quoted where "
      "needed, in place of its label");
}

}  // namespace

void bind_tree(py::module_& m) {
  bind_tree_class(m);
  bind_tree_functions(m);
}

}  // namespace fspm::python
