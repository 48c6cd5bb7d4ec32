// Python bindings: trees from laser scans (Pirk 2012, 3.3; docs/scans.md): point-set files, the
// cluster-based representation (skeleton with allometric radii, leaf-cluster hulls), .clusters
// files and the scan simulator used to validate it.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <random>
#include <string>
#include <vector>

#include "python/bindings.hpp"
#include "scan_decoding/decoding.hpp"
#include "scans/clusters_file.hpp"
#include "scans/encoder.hpp"
#include "scans/point_set_file.hpp"
#include "scans/scan_simulator.hpp"
#include "scans/scanned_tree.hpp"
#include "scans/species.hpp"
#include "scans/tree_measurements.hpp"

namespace fspm::python {
namespace {

py::array_t<std::uint32_t> triangle_rows(const std::vector<std::array<std::uint32_t, 3>>& tris) {
  py::array_t<std::uint32_t> out({static_cast<py::ssize_t>(tris.size()), py::ssize_t{3}});
  auto a = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < tris.size(); ++i) {
    for (int k = 0; k < 3; ++k)
      a(static_cast<py::ssize_t>(i), k) = tris[i][static_cast<std::size_t>(k)];
  }
  return out;
}

scans::EncodeResult encode(const PointArray& points, const std::string& species,
                           std::optional<double> beta, std::optional<double> gamma,
                           std::optional<double> f_s, std::optional<double> root_diameter,
                           int neighbours, double voxel, bool pirk_split) {
  scans::EncodeOptions o;
  o.species = scans::species_by_name(species);
  if (beta) o.species.beta = *beta;
  if (gamma) o.species.gamma = *gamma;
  if (f_s) o.species.f_s = *f_s;
  o.root_diameter_m = root_diameter;
  o.neighbours = neighbours;
  o.voxel_m = voxel;
  o.follow_main_axes = !pirk_split;
  scans::PointSet set;
  const auto span = as_points(points, "points");
  set.points.assign(span.begin(), span.end());
  py::gil_scoped_release release;
  return scans::encode_point_set(set, o);
}

void bind_cluster_model(py::module_& m) {
  using scans::ClusterModel;
  py::class_<ClusterModel>(m, "ClusterModel",
                           "The cluster-based representation of a scanned tree (Pirk 3.3): the "
                           "main skeleton with radii of eq. 3.1 and the leaf clusters' hulls")
      .def_readonly("species", &ClusterModel::species, "Species preset whose parameters were used")
      .def_readonly("beta", &ClusterModel::beta, "Edge-weight exponent of the neighbour graph")
      .def_readonly("gamma", &ClusterModel::gamma, "Allometric exponent of eq. 3.1")
      .def_readonly("f_s", &ClusterModel::f_s, "Diameter factor of eq. 3.2")
      .def_readonly("root_diameter", &ClusterModel::root_diameter_m, "d_root of eq. 3.1, m")
      .def_readonly("skeleton", &ClusterModel::skeleton, "The main skeleton as a Tree (m)")
      .def_property_readonly(
          "clusters",
          [](const ClusterModel& c) {
            return dict_list(c.clusters, [](py::dict& d, const scans::ClusterHull& h) {
              d["seed_node"] = h.seed_node;
              d["point_count"] = h.point_count;
              d["branch_length"] = h.branch_length_m;
              d["vertices"] = vector_rows(h.vertices);
              d["triangles"] = triangle_rows(h.triangles);
            });
          },
          "One dict per leaf cluster: seed_node (skeleton node id it hangs at), point_count, "
          "branch_length (m of skeleton segments the scan showed in it; 0 from version 1 files), "
          "vertices (N, 3) in m and triangles (M, 3) of its alpha-shape hull");
}

void bind_point_encoding(py::module_& m) {
  m.def(
      "read_points",
      [](const std::string& path) {
        scans::PointSet set;
        {
          py::gil_scoped_release release;
          set = scans::read_point_set(path);
        }
        return vector_rows(set.points);
      },
      py::arg("path"),
      "The points of a point-set file (.ply ASCII or binary, .xyz/.txt/.csv, .pcd, .las), or the "
      "vertices of a mesh (.obj, glTF 2.0 .gltf/.glb with node transforms applied), as an (N, 3) "
      "float64 array in the file's units (metres expected)");
  m.def(
      "species_presets",
      [] {
        return dict_list(scans::species_presets(),
                         [](py::dict& d, const scans::SpeciesParameters& s) {
                           d["name"] = s.name;
                           d["beta"] = s.beta;
                           d["gamma"] = s.gamma;
                           d["f_s"] = s.f_s;
                         });
      },
      "The species parameters of Pirk Table 3.1 (name, beta, gamma, f_s), in its order");
  m.def(
      "encode_points",
      [](const PointArray& points, const std::string& species, std::optional<double> beta,
         std::optional<double> gamma, std::optional<double> f_s,
         std::optional<double> root_diameter, int neighbours, double voxel, bool pirk_split) {
        return encode(points, species, beta, gamma, f_s, root_diameter, neighbours, voxel,
                      pirk_split)
            .model;
      },
      py::arg("points"), py::arg("species") = "default", py::arg("beta") = py::none(),
      py::arg("gamma") = py::none(), py::arg("f_s") = py::none(),
      py::arg("root_diameter") = py::none(), py::arg("neighbours") = 8, py::arg("voxel") = 0.0,
      py::arg("pirk_split") = false,
      "Encode a scanned tree ((N, 3) points in m, z up) into a ClusterModel (Pirk 3.3): "
      "species names a preset of Table 3.1 ('default', 'pine', ...) whose beta, gamma, f_s any "
      "keyword overrides; root_diameter (m) is estimated from the trunk points when None; "
      "voxel: thinning size in m (0: 1/1000 of the extent, negative: none); pirk_split=True "
      "keeps the main skeleton by eq. 3.2 alone, as Pirk and fspm encode --pirk-split (default: "
      "the trunk to the top and the limbs to their tips, eq. 3.2 for the smaller branches)");
}

void bind_cluster_files(py::module_& m) {
  m.def(
      "write_clusters",
      [](const scans::ClusterModel& model, const std::string& path) {
        py::gil_scoped_release release;
        scans::write_clusters_file(model, path);
      },
      py::arg("model"), py::arg("path"), "Write a ClusterModel as a .clusters file, atomically");
  m.def(
      "read_clusters",
      [](const std::string& path) {
        py::gil_scoped_release release;
        return scans::read_clusters_file(path);
      },
      py::arg("path"), "Read a .clusters file (docs/formats.md)");
  m.def(
      "decode_clusters",
      [](const scans::ClusterModel& model, const std::string& species, int branchlets,
         std::uint64_t seed, bool docking_only) {
        scan_decoding::DecodeOptions o;
        o.species = species;
        o.library.branchlets = branchlets;
        o.seed = seed;
        o.texture.match_branch_length = !docking_only;
        py::gil_scoped_release release;
        return scan_decoding::decoded_tree(model, scan_decoding::decode_clusters(model, o));
      },
      py::arg("model"), py::arg("species") = "", py::arg("branchlets") = 8, py::arg("seed") = 1,
      py::arg("docking_only") = false,
      "Decode a ClusterModel into a full Tree (Pirk 3.4): the skeleton (same node ids) followed "
      "by the patches of L-system branchlets that texture its clusters, chosen by eq. 3.3 and "
      "fitted to the hulls, up to each cluster's scanned branch_length (docking_only=True: until "
      "the docking points are used up, Pirk's rule alone); species '' uses the model's; the same "
      "seed gives the same tree");
  m.def(
      "simulate_scan",
      [](const TreeGraph& tree, std::uint64_t seed, int scanners, double density_per_m2,
         double range_noise) {
        scans::ScanOptions o;
        o.scanners = scanners;
        o.density_per_m2 = density_per_m2;
        o.range_noise_m = range_noise;
        std::mt19937_64 rng(seed);
        scans::PointSet set;
        {
          py::gil_scoped_release release;
          set = scans::simulate_scan(tree, o, rng);
        }
        return vector_rows(set.points);
      },
      py::arg("tree"), py::arg("seed") = 1, py::arg("scanners") = 4,
      py::arg("density_per_m2") = 20000.0, py::arg("range_noise") = 0.003,
      "A simulated terrestrial laser scan of the tree's internodes (cylinders) from `scanners` "
      "positions around it: (N, 3) points in m; density per m^2 at normal incidence, Gaussian "
      "range noise in m; the same seed gives the same points");
}

py::object optional_value(const std::optional<double>& v) {
  return v ? py::object(py::float_(*v)) : py::object(py::none());
}

// The cylinders as an (N, 12) array in the columns of fspm encode --cylinders.
py::array_t<double> cylinder_rows(const std::vector<scans::QsmCylinder>& cylinders) {
  py::array_t<double> out({static_cast<py::ssize_t>(cylinders.size()), py::ssize_t{12}});
  auto a = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < cylinders.size(); ++i) {
    const scans::QsmCylinder& c = cylinders[i];
    const auto r = static_cast<py::ssize_t>(i);
    for (int k = 0; k < 3; ++k) a(r, k) = c.start[k], a(r, 3 + k) = c.axis[k];
    a(r, 6) = c.length_m;
    a(r, 7) = c.radius_m;
    a(r, 8) = static_cast<double>(c.parent + 1);
    a(r, 9) = static_cast<double>(c.branch + 1);
    a(r, 10) = c.order;
    a(r, 11) = c.nested ? 1.0 : 0.0;
  }
  return out;
}

py::dict measurements_dict(const scans::TreeMeasurements& t) {
  py::dict d;
  d["dbh_m"] = optional_value(t.dbh_m);
  d["height_m"] = t.height_m;
  d["crown_width_m"] = t.crown_width_m;
  d["crown_base_m"] = optional_value(t.crown_base_m);
  d["woody_volume_m3"] = t.woody_volume_m3;
  d["branches_per_order"] = t.branches_per_order;
  d["branch_length_per_order_m"] = t.branch_length_per_order_m;
  d["points_explained_fraction"] = t.points_explained_fraction;
  d["breast_height_points"] = t.breast_height_points;
  d["stems"] = t.stems;
  d["breast_height_stems_m"] = t.breast_height_stems_m;
  d["tree_found"] = t.tree_found;
  d["warnings"] = t.warnings;
  d["cylinders"] = cylinder_rows(t.cylinders);
  return d;
}

void bind_measurements(py::module_& m) {
  m.def(
      "measure_points",
      [](const PointArray& points, const std::string& species,
         std::optional<double> root_diameter) {
        scans::PointSet set;
        const auto span = as_points(points, "points");
        set.points.assign(span.begin(), span.end());
        scans::EncodeOptions o;
        o.species = scans::species_by_name(species);
        o.root_diameter_m = root_diameter;
        scans::ScannedTree tree;
        {
          py::gil_scoped_release release;
          tree = scans::encode_and_measure(set, o);
        }
        py::dict d = measurements_dict(tree.measurements);
        d["isolated_points"] = tree.isolated_points;
        return d;
      },
      py::arg("points"), py::arg("species") = "default", py::arg("root_diameter") = py::none(),
      "Measurements of a scanned tree as fspm encode --json reports them (docs/scans.md): "
      "encodes the (N, 3) points (m, z up) and returns a dict with dbh_m (None without a "
      "compact trunk at 1.2-1.4 m), height_m, crown_width_m, crown_base_m (None without a fork), "
      "woody_volume_m3, branches_per_order, branch_length_per_order_m, "
      "points_explained_fraction, breast_height_points, stems, isolated_points (stray returns left "
      "out first), tree_found, warnings and "
      "cylinders, an (N, 12) array: start x y z, axis x y z, length, radius, parent, branch, "
      "order (TreeQSM's columns, numbered from 1) and nested");
}

}  // namespace

void bind_scans(py::module_& m) {
  bind_cluster_model(m);
  bind_point_encoding(m);
  bind_cluster_files(m);
  bind_measurements(m);
}

}  // namespace fspm::python
