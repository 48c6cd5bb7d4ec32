// Python bindings (pybind11). Long computations release the GIL; tree columns are exposed as
// numpy arrays that view the C++ memory and keep the Tree alive.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "experiments/comparisons.hpp"
#include "experiments/experiment.hpp"
#include "experiments/model_factory.hpp"
#include "experiments/run_plan.hpp"
#include "experiments/runner.hpp"
#include "fspm/compressed_tree_graph.hpp"
#include "fspm/constrained_edit_distance.hpp"
#include "fspm/edit_cost_model.hpp"
#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"
#include "fspm/newick_format.hpp"
#include "fspm/tree_file.hpp"
#include "fspm/tree_summary.hpp"
#include "greenlab/plant_params.hpp"
#include "greenlab/reconstruction.hpp"
#include "greenlab/simulation.hpp"
#include "lsystem/derivation.hpp"
#include "lsystem/lsystem.hpp"
#include "lsystem/parser.hpp"
#include "lsystem/substructure_derivation.hpp"
#include "lsystem/turtle.hpp"
#include "python/bindings.hpp"

namespace py = pybind11;

namespace {

using fspm::TreeGraph;

using fspm::python::column;
using fspm::python::parent_column;

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

fspm::lsystem::LSystem load_lsystem(const std::string& path,
                                    const std::map<std::string, std::string>& defines) {
  return fspm::lsystem::parse_lsystem_file(path, defines);
}

fspm::lsystem::DeriveOptions derive_options(std::optional<int> steps,
                                            std::optional<std::uint64_t> seed) {
  fspm::lsystem::DeriveOptions o;
  o.steps = steps;
  o.seed = seed;
  return o;
}

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
  if (!(unit_cost >= 0.0)) throw fspm::ValueError("unit_cost: expected a value >= 0");
  return fspm::FeatureCostModel(da, std::vector<double>(fa.data(), fa.data() + fa.size()),
                                std::vector<double>(fb.data(), fb.data() + fb.size()), unit_cost);
}

fspm::TreeGraph tree_from_arrays(
    const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& parents,
    const fspm::python::PointArray& starts, const fspm::python::PointArray& ends,
    std::optional<fspm::python::Sample> radii, std::optional<fspm::python::Sample> birth_times,
    std::optional<py::array_t<std::uint16_t, py::array::c_style | py::array::forcecast>> orders,
    std::optional<py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>> kinds,
    const std::map<std::string, fspm::python::Sample>& attributes) {
  const auto n = static_cast<std::size_t>(parents.size());
  const auto s = fspm::python::as_points(starts, "starts");
  const auto e = fspm::python::as_points(ends, "ends");
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

PYBIND11_MODULE(_fspm, m) {
  m.doc() = "fspm core bindings";

  // Errors are fspm.Error and the matching built-in exception at once, so `except ValueError`
  // and `except OSError` catch them as they would catch Python's own.
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
  static PyObject* const value_error = new_exception(
      m, "ValueError_",
      "A parameter outside its valid range, an unknown name or an impossible request (also a "
      "ValueError); fspm.ParameterError",
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

  fspm::python::bind_calibration(m);

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
                  py::arg("attributes") = std::map<std::string, fspm::python::Sample>{},
                  "A tree from columns: parents (-1 for the root, else a smaller id), starts and "
                  "ends (N, 3), optional radii, birth times, orders, kinds and user attributes")
      .def(
          "copy", [](const TreeGraph& t) { return TreeGraph(t); }, "An independent copy");

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
      "the default (half of the physical memory). Requests above it raise MemoryLimitError, a "
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
      "branch lengths 'branch_length' (NaN where missing)");
  m.def(
      "to_newick", [](const TreeGraph& t) { return fspm::to_newick(t); }, py::arg("tree"),
      "The tree as Newick text: topology, the attribute 'label' as node labels and "
      "'branch_length' when present");

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
        return fspm::python::adopt(fspm::main_skeleton_nodes(t, min_radius));
      },
      py::arg("tree"), py::arg("min_radius"),
      "Ids of the nodes thicker than min_radius whose ancestors all are");
  m.def(
      "node_attribute_values",
      [](const TreeGraph& t, const std::string& name) {
        return fspm::python::adopt(fspm::node_attribute_values(t, name));
      },
      py::arg("tree"), py::arg("name"),
      "One value per node: length, radius, birth_time, order, physiological_age or a user "
      "attribute");

  py::class_<fspm::CompressedTreeGraph>(
      m, "CompressedPlant",
      "A GreenLab plant as a compressed tree graph: one record per substructure")
      .def("__len__", &fspm::CompressedTreeGraph::size)
      .def_property_readonly("graph_nodes", &fspm::CompressedTreeGraph::size,
                             "Records of the compressed graph (its substructures)")
      .def_property_readonly(
          "metamers", &fspm::CompressedTreeGraph::expanded_size,
          "Metamers of the explicit plant it stands for (sum of the record multiplicities)")
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
      "The explicit tree of a GreenLab plant at any age up to the simulated one");

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

  m.def(
      "run_experiment",
      [](const std::string& path, const std::string& out, std::size_t jobs, bool resume,
         std::size_t replicates) {
        namespace ex = fspm::experiments;
        ex::RunnerSummary s;
        {
          py::gil_scoped_release release;
          ex::Experiment x = ex::read_experiment(path);
          if (replicates > 0) ex::override_replicates(x, replicates);
          const std::unique_ptr<ex::Model> model = ex::make_model(x);
          const ex::RunPlan plan(x);
          ex::check_experiment(x, *model, plan);
          ex::RunnerOptions r;
          r.out_dir = out;
          r.jobs = jobs;
          r.resume = resume;
          s = ex::run_experiment(x, *model, r);
          // As fspm run: a complete sweep with [[comparison]]s gets its distances and t-tests.
          if (!x.comparisons.empty()) ex::compare_results(out, jobs);
        }
        py::dict d;
        d["database"] = s.database;
        d["total_runs"] = s.total_runs;
        d["ran"] = s.ran;
        d["ok"] = s.ok;
        d["error"] = s.failed;
        d["timeout"] = s.timed_out;
        d["seconds"] = s.seconds;
        return d;
      },
      py::arg("experiment"), py::arg("out"), py::arg("jobs") = 0, py::arg("resume") = false,
      py::arg("replicates") = 0,
      "Run an experiment file (TOML) into the directory `out` (replicates > 0 overrides the "
      "file's); read it with read_results, its comparisons (pairs.csv, ttests.csv) with pandas");

  m.def(
      "compare_results",
      [](const std::string& out, std::size_t jobs) {
        namespace ex = fspm::experiments;
        ex::ComparisonResults c;
        {
          py::gil_scoped_release release;
          c = ex::compare_results(out, jobs);
        }
        py::dict d;
        d["pairs"] = c.pairs.size();
        d["notes"] = c.notes;
        d["seconds"] = c.seconds;
        return d;
      },
      py::arg("out"), py::arg("jobs") = 0,
      "Recompute the [[comparison]] distances and t-tests of a result directory (pairs.csv, "
      "ttests.csv)");

  m.def(
      "lsystem_derive",
      [](const std::string& path, std::optional<int> steps, std::optional<std::uint64_t> seed,
         const std::map<std::string, std::string>& defines, bool compressed) {
        py::dict d;
        std::vector<std::uint64_t> per_symbol;
        int done = 0;
        std::uint64_t modules = 0;
        std::size_t graph_nodes = 0, graph_bytes = 0;
        std::uint64_t explicit_bytes = 0;
        fspm::lsystem::LSystem sys;
        {
          py::gil_scoped_release release;
          sys = load_lsystem(path, defines);
          if (compressed) {
            // Shared substructures (lsystem/substructure_derivation.hpp): counts of strings too
            // large to hold; ValueError when the L-system cannot be factorized.
            const auto g = fspm::lsystem::derive_substructures(sys, derive_options(steps, seed));
            const auto c = fspm::lsystem::count_modules(g, sys.symbols.size());
            done = g.steps;
            modules = c.modules;
            per_symbol = c.per_symbol;
            graph_nodes = g.nodes.size();
            graph_bytes = g.memory_bytes();
            explicit_bytes = c.explicit_bytes;
          } else {
            fspm::lsystem::Derivation der(sys, derive_options(steps, seed));
            der.run();
            done = der.steps_done();
            modules = der.string().size();
            per_symbol.assign(sys.symbols.size(), 0);
            for (auto id : der.string().symbols()) ++per_symbol[id];
          }
        }
        py::dict symbols;
        for (std::size_t i = 0; i < per_symbol.size(); ++i) {
          if (per_symbol[i] != 0) {
            symbols[py::str(sys.symbols.name(static_cast<fspm::lsystem::SymbolId>(i)))] =
                per_symbol[i];
          }
        }
        d["steps"] = done;
        d["modules"] = modules;
        d["symbols"] = symbols;
        if (compressed) {
          d["graph_nodes"] = graph_nodes;
          d["graph_bytes"] = graph_bytes;
          d["explicit_bytes"] = explicit_bytes;
        }
        return d;
      },
      py::arg("path"), py::arg("steps") = py::none(), py::arg("seed") = py::none(),
      py::arg("defines") = std::map<std::string, std::string>{}, py::arg("compressed") = false,
      "Derive an L-system file: steps, modules and the count of each module name; "
      "compressed=True derives into shared substructures (context-free L-systems only, "
      "docs/lsystem-language.md) and adds graph_nodes, graph_bytes and explicit_bytes");

  m.def(
      "lsystem_interpret",
      [](const std::string& path, std::optional<int> steps, std::optional<std::uint64_t> seed,
         const std::map<std::string, std::string>& defines) {
        py::gil_scoped_release release;
        const fspm::lsystem::LSystem sys = load_lsystem(path, defines);
        const fspm::lsystem::TurtleSettings view = fspm::lsystem::view_for_lsystem(path);
        auto options = derive_options(steps, seed);
        options.turtle = &view;
        fspm::lsystem::Derivation der(sys, options);
        der.run();
        return fspm::lsystem::interpret(der.interpretation_string(), sys.symbols, view).tree;
      },
      py::arg("path"), py::arg("steps") = py::none(), py::arg("seed") = py::none(),
      py::arg("defines") = std::map<std::string, std::string>{},
      "Derive an L-system file and draw it into a Tree");

  fspm::python::bind_statistics(m);
  fspm::python::bind_environment(m);
  fspm::python::bind_graphics(m);
  fspm::python::bind_stages(m);
  fspm::python::bind_crown(m);
}
