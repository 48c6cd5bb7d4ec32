// Bindings of the environment module: scenes (JSON), sky light at points (Pirk eq. 4.3), the
// self-organizing growth model (Palubicki et al. 2009) and plastic adaptation (Pirk 4.3-4.4).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "environment/canopy_summary.hpp"
#include "environment/growth_model.hpp"
#include "environment/growth_params.hpp"
#include "environment/leaf_light.hpp"
#include "environment/light_model.hpp"
#include "environment/plastic_adaptation.hpp"
#include "environment/scene_file.hpp"
#include "environment/site_sky.hpp"
#include "environment/sky_distribution.hpp"
#include "environment/tree_analysis.hpp"
#include "fspm/number_text.hpp"
#include "python/bindings.hpp"

namespace fspm::python {
namespace {

namespace env = fspm::environment;

// GrowthParams(preset=..., light_model=..., preset_tropisms=...): the preset fitted for the light
// model and with the tropism pairing given, as `preset` in a parameter file.
env::GrowthParams growth_base(py::dict& values) {
  if (!values.contains("preset")) {
    if (values.contains("preset_tropisms")) {
      throw ValueError("preset_tropisms: chooses the tropisms of a preset; expected a preset too");
    }
    return {};
  }
  const std::string name = py::str(values["preset"]);
  PyDict_DelItemString(values.ptr(), "preset");
  env::BudLightModel model = env::GrowthParams{}.light_model;
  if (values.contains("light_model")) {
    model = env::bud_light_model_from_name(std::string(py::str(values["light_model"])));
  }
  env::TropismPairing pairing = env::kDefaultTropismPairing;
  if (values.contains("preset_tropisms")) {
    const std::string t = py::str(values["preset_tropisms"]);
    PyDict_DelItemString(values.ptr(), "preset_tropisms");
    pairing = env::tropism_pairing_from_name(t);
  }
  return env::growth_preset(name, model, pairing);
}

// Light samples as two numpy arrays viewing one C++ buffer: light (N,) and directions (N, 3).
py::tuple light_arrays(std::vector<env::LightSample>&& samples) {
  auto* owned = new std::vector<env::LightSample>(std::move(samples));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<env::LightSample>*>(p); });
  const auto n = static_cast<py::ssize_t>(owned->size());
  const py::ssize_t row = sizeof(env::LightSample);
  if (n == 0) {
    return py::make_tuple(py::array_t<double>(std::vector<py::ssize_t>{0}),
                          py::array_t<double>(std::vector<py::ssize_t>{0, 3}));
  }
  const env::LightSample& s = owned->front();
  py::array_t<double> light({n}, {row}, &s.light, owner);
  py::array_t<double> dirs({n, py::ssize_t{3}}, {row, py::ssize_t{sizeof(double)}},
                           s.direction.data(), owner);
  return py::make_tuple(light, dirs);
}

py::tuple evaluate(const env::LightModel& model, const PointArray& points) {
  const std::span<const Eigen::Vector3d> p = as_points(points, "points");
  std::vector<env::LightSample> samples(p.size());
  {
    py::gil_scoped_release release;
    model.evaluate(p, samples);
  }
  return light_arrays(std::move(samples));
}

// Sets one field of a scene's sky through the library's check, leaving the sky as it was when
// the value is refused.
template <typename Set>
void set_checked_sky(env::Scene& scene, const Set& set) {
  env::Sky sky = scene.sky;
  set(sky);
  sky.validate();
  scene.sky = sky;
}

env::Scene scene_from(py::handle scene) {
  if (scene.is_none()) return {};
  if (py::isinstance<py::dict>(scene)) {
    const std::string text = py::module_::import("json").attr("dumps")(scene).cast<std::string>();
    return env::parse_scene_json(text, "<dict>");
  }
  if (!py::isinstance<env::Scene>(scene)) {
    throw py::type_error(
        "scene: expected an fspm.Scene, a dict of the scene file's structure or "
        "None, got " +
        py::repr(py::type::of(scene)).cast<std::string>());
  }
  return scene.cast<env::Scene>();
}

py::array sphere_array(const std::vector<env::Sphere>& spheres) {
  // One row per sphere: centre x, y, z, radius, translucency.
  py::array_t<double> a({static_cast<py::ssize_t>(spheres.size()), py::ssize_t{5}});
  auto r = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const auto k = static_cast<py::ssize_t>(i);
    for (py::ssize_t c = 0; c < 3; ++c) r(k, c) = spheres[i].center[c];
    r(k, 3) = spheres[i].radius_m;
    r(k, 4) = spheres[i].translucency;
  }
  return a;
}

py::array cluster_array(const std::vector<env::LeafCluster>& clusters) {
  // One row per cluster: centre x, y, z, radius, translucency.
  py::array_t<double> a({static_cast<py::ssize_t>(clusters.size()), py::ssize_t{5}});
  auto r = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < clusters.size(); ++i) {
    const auto k = static_cast<py::ssize_t>(i);
    for (py::ssize_t c = 0; c < 3; ++c) r(k, c) = clusters[i].center[c];
    r(k, 3) = clusters[i].radius_m;
    r(k, 4) = clusters[i].translucency;
  }
  return a;
}

void bind_scene_obstacles(py::class_<env::Scene>& scene) {
  scene
      .def(
          "add_sphere",
          [](env::Scene& s, const Eigen::Vector3d& center, double radius, double translucency,
             bool solid) {
            const env::Sphere sphere{center, radius, translucency, solid};
            sphere.validate();
            s.spheres.push_back(sphere);
          },
          py::arg("center"), py::arg("radius"), py::arg("translucency") = 0.0,
          py::arg("solid") = false,
          "Adds a sphere: centre (m), radius (m, > 0), translucency in [0, 1] (0: opaque); a leaf "
          "cluster unless solid")
      .def(
          "add_box",
          [](env::Scene& s, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
             double translucency, bool solid) {
            env::Box b = env::Box::from_min_max(lo, hi);
            b.translucency = translucency;
            b.solid = solid;
            b.validate();
            s.boxes.push_back(b);
          },
          py::arg("min"), py::arg("max"), py::arg("translucency") = 0.0, py::arg("solid") = true,
          "Adds an axis-aligned box from its min to its max corner (m; min < max on every axis), "
          "translucency in [0, 1]")
      .def(
          "add_wall",
          [](env::Scene& s, const Eigen::Vector2d& from, const Eigen::Vector2d& to, double height,
             double thickness, double base, double translucency) {
            env::Box b = env::Box::wall(from, to, base, height, thickness);
            b.translucency = translucency;
            b.validate();
            s.boxes.push_back(b);
          },
          py::arg("from_xy"), py::arg("to_xy"), py::arg("height"), py::arg("thickness") = 0.2,
          py::arg("base") = 0.0, py::arg("translucency") = 0.0,
          "Adds a solid vertical wall from (x0, y0) to (x1, y1) (m): height (m, > 0), thickness "
          "(m, > 0), "
          "base z (m)")
      .def(
          "set_ground",
          [](env::Scene& s, double height, double translucency, bool solid) {
            const env::Ground ground{height, translucency, solid};
            ground.validate();
            s.ground = ground;
          },
          py::arg("height") = 0.0, py::arg("translucency") = 0.0, py::arg("solid") = true,
          "Adds (or replaces) the ground plane z = height (m)")
      .def("inside_solid", &env::Scene::inside_solid, py::arg("point"),
           "True when the point (x, y, z in m) lies inside a solid box or sphere, or below a solid "
           "ground")
      .def("__repr__", [](const env::Scene& s) {
        return "<fspm.Scene with " + std::to_string(s.spheres.size()) + " spheres, " +
               std::to_string(s.boxes.size()) + " boxes, " + std::to_string(s.meshes.size()) +
               " meshes" + (s.ground ? ", ground" : "") + ">";
      });
}

void bind_scene(py::module_& m) {
  py::class_<env::Scene> scene(m, "Scene",
                               "The sky and the occluders (spheres, boxes, meshes, ground), z up");
  scene.def(py::init<>(), "An open scene: no occluders, brightest sky point at the zenith")
      .def_property(
          "brightest", [](const env::Scene& s) { return s.sky.brightest; },
          [](env::Scene& s, const Eigen::Vector3d& d) {
            set_checked_sky(s, [&](env::Sky& sky) { sky.brightest = d.normalized(); });
          },
          "Unit direction of the brightest sky point")
      .def_property(
          "directions", [](const env::Scene& s) { return s.sky.directions; },
          [](env::Scene& s, int n) {
            set_checked_sky(s, [&](env::Sky& sky) { sky.directions = n; });
          },
          "Stratified sky directions of the light integral (integer >= 1)")
      .def_property(
          "significance", [](const env::Scene& s) { return s.sky.significance; },
          [](env::Scene& s, double v) {
            set_checked_sky(s, [&](env::Sky& sky) { sky.significance = v; });
          },
          "Shadow-volume cutoff: largest share of light an ignored occluder may remove")
      .def_property(
          "analytic", [](const env::Scene& s) { return s.sky.analytic; },
          [](env::Scene& s, bool v) { s.sky.analytic = v; },
          "Exact sphere-cap integrals where they apply")
      .def_property_readonly(
          "spheres", [](const env::Scene& s) { return sphere_array(s.spheres); },
          "Spheres as rows x, y, z, radius (m), translucency in [0, 1] (a copy)")
      .def_property_readonly(
          "boxes", [](const env::Scene& s) { return s.boxes.size(); }, "Number of boxes and walls")
      .def_property_readonly(
          "meshes", [](const env::Scene& s) { return s.meshes.size(); }, "Number of meshes")
      .def_property_readonly(
          "ground",
          [](const env::Scene& s) -> py::object {
            if (!s.ground) return py::none();
            return py::cast(s.ground->height_m);
          },
          "Height z of the ground plane (m), or None");
  bind_scene_obstacles(scene);

  m.def(
      "read_scene_file",
      [](const std::string& path) {
        py::gil_scoped_release release;
        return env::read_scene_file(path);
      },
      py::arg("path"),
      "Read the sky and obstacles of a scene file (JSON, docs/formats.md; plants are ignored)");
  m.def(
      "parse_scene_json",
      [](py::handle text) {
        if (py::isinstance<py::dict>(text)) return scene_from(text);
        return env::parse_scene_json(text.cast<std::string>());
      },
      py::arg("text"), "A scene from JSON text or from a dict of the same structure");
}

void bind_light(py::module_& m) {
  py::class_<env::LightModel>(m, "LightModel",
                              "Sky light at points through a scene's occluders (Pirk eq. 4.3)")
      .def(py::init([](py::handle scene) {
             const env::Scene s = scene_from(scene);
             py::gil_scoped_release release;
             return std::make_unique<env::LightModel>(s);
           }),
           py::arg("scene"), "Builds the shadow-volume index of a Scene (or scene dict)")
      .def("evaluate", &evaluate, py::arg("points"),
           "Light in [0, 1] and unit mean light direction at points (N, 3): arrays (N,) and "
           "(N, 3)")
      .def(
          "evaluate_brute_force",
          [](const env::LightModel& model, const Eigen::Vector3d& p) {
            py::gil_scoped_release release;
            const env::LightSample s = model.evaluate_brute_force(p);
            return std::make_pair(s.light, s.direction);
          },
          py::arg("point"), "Reference: every direction ray-cast against every occluder")
      .def_property_readonly("scene", &env::LightModel::scene,
                             "The Scene the model was built from");

  m.def(
      "light",
      [](py::handle scene, const PointArray& points, std::optional<int> directions) {
        env::Scene s = scene_from(scene);
        if (directions) {
          set_checked_sky(s, [&](env::Sky& sky) { sky.directions = *directions; });
        }
        std::unique_ptr<env::LightModel> model;
        {
          py::gil_scoped_release release;
          model = std::make_unique<env::LightModel>(s);
        }
        return evaluate(*model, points);
      },
      py::arg("scene"), py::arg("points"), py::arg("directions") = py::none(),
      "Light and mean light direction at points (N, 3) of a scene, as `fspm light`: returns "
      "(light (N,), directions (N, 3))");
}

// A field of a nested parameter struct, bound flat under its parameter-file name.
template <typename Outer, typename Inner, typename T>
void nested_field(py::class_<Outer>& cls, const char* name, Inner Outer::*inner, T Inner::*field,
                  const char* doc) {
  cls.def_property(
      name, [inner, field](const Outer& o) { return o.*inner.*field; },
      [inner, field](Outer& o, T v) { o.*inner.*field = v; }, doc);
}

void bind_growth_light(py::class_<env::GrowthParams>& gp) {
  gp.def_property(
      "light_model",
      [](const env::GrowthParams& p) {
        return std::string(env::bud_light_model_name(p.light_model));
      },
      [](env::GrowthParams& p, const std::string& name) {
        p.light_model = env::bud_light_model_from_name(name);
      },
      ("Where buds get light: " + env::kBudLightModelNames.help()).c_str());
  using GP = env::GrowthParams;
  using SG = env::ShadowGridParams;
  using SC = env::SpaceColonizationParams;
  nested_field(gp, "voxel_size_m", &GP::shadow_grid, &SG::voxel_size_m,
               "shadow_grid: edge of a shadow voxel (m, > 0; 0.15)");
  nested_field(gp, "shadow_a", &GP::shadow_grid, &SG::shade_a,
               "shadow_grid: shade a a bud casts into its own voxel (> 0; 1)");
  nested_field(gp, "shadow_b", &GP::shadow_grid, &SG::shade_b,
               "shadow_grid: each voxel layer further down gets 1/b of the shade above (> 1; 2)");
  nested_field(gp, "shadow_depth_voxels", &GP::shadow_grid, &SG::depth_voxels,
               "shadow_grid: q_max, voxel layers a bud shades below it (integer in [0, 64]; 8)");
  nested_field(gp, "full_light", &GP::shadow_grid, &SG::full_light,
               "shadow_grid: C, the light of an unshaded voxel in units of shadow_a (> 0; 3)");
  nested_field(gp, "obstacle_shade", &GP::shadow_grid, &SG::obstacle_shade,
               "shadow_grid: shade of a voxel filled by an opaque obstacle, in units of full_light "
               "(>= 0; 0.1)");
  nested_field(gp, "marker_density_per_m3", &GP::space_colonization, &SC::marker_density_per_m3,
               "space_colonization: markers per cubic metre (m^-3, > 0; 30)");
  nested_field(gp, "perception_radius_m", &GP::space_colonization, &SC::perception_radius_m,
               "space_colonization: distance within which a bud perceives markers (m, > 0; 0.9)");
  nested_field(gp, "perception_angle_deg", &GP::space_colonization, &SC::perception_angle_deg,
               "space_colonization: full opening angle of a bud's perception cone (degrees, in (0, "
               "360]; 90)");
  nested_field(
      gp, "occupancy_radius_m", &GP::space_colonization, &SC::occupancy_radius_m,
      "space_colonization: markers this close to the tree's nodes are removed (m, > 0; 0.3)");
  nested_field(gp, "marker_region_radius_m", &GP::space_colonization, &SC::region_radius_m,
               "space_colonization: radius of the marker cylinder on the tree's base (m, > 0; 8)");
  nested_field(gp, "marker_region_height_m", &GP::space_colonization, &SC::region_height_m,
               "space_colonization: height of the marker cylinder on the tree's base (m, > 0; 14)");
}

void bind_growth_params(py::module_& m) {
  py::class_<env::GrowthParams> gp(
      m, "GrowthParams",
      "Parameters of the self-organizing growth model (docs/environment.md). "
      "GrowthParams(preset='A', years=10) starts from Pirk's tree type A");
  bind_growth_light(gp);
  Fields<env::GrowthParams>(gp)
      .add("years", &env::GrowthParams::years,
           "Growth cycles (years) to simulate (integer in [0, 1000]; 20)")
      .add("seed", &env::GrowthParams::seed,
           "Seed of the generator of the small heading perturbations (non-negative integer; 1)")
      .add("alpha", &env::GrowthParams::alpha,
           "Borchert-Honda vigour: v_base = alpha * Q_base at the root (> 0; 3, presets fit it)")
      .add("apical_control", &env::GrowthParams::apical_control,
           "Borchert-Honda apical control lambda: weight of the main axis' light against the "
           "lateral's when vigour is shared ([0, 1]; 0.47)")
      .add("internode_length_m", &env::GrowthParams::internode_length_m,
           "Length of one metamer; a shoot of vigour v is v times this long (m, > 0; 0.15)")
      .add("max_shoot_metamers", &env::GrowthParams::max_shoot_metamers,
           "Most metamers in one shoot, n = round(v) (integer >= 1; 5)")
      .add("min_shoot_vigour", &env::GrowthParams::min_shoot_vigour,
           "Buds with less vigour do not grow a shoot (>= 0; 0.5)")
      .add("max_internodes", &env::GrowthParams::max_internodes,
           "Growth stops with an error naming the parameters when the tree has more internodes "
           "(integer >= 1; 1000000)")
      .add("max_height_m", &env::GrowthParams::max_height_m,
           "Growth stops with an error naming the parameters when the tree is taller (m, > 0 or "
           "inf; 150)")
      .add("sky_light_fraction", &env::GrowthParams::sky_light_fraction,
           "Share of the open sky's light reaching the stand, scales every bud's Q ([0, 1], 1 = "
           "open site; 1)")
      .add("light_half_saturation", &env::GrowthParams::light_half_saturation,
           "K of the light response P(Q) = Q (1 + K) / (Q + K), in units of full light (> 0, inf = "
           "linear; 0.2)")
      .add("branching_angle_deg", &env::GrowthParams::branching_angle_deg,
           "Angle between a lateral bud and its parent axis (degrees, finite; 40)")
      .add("phyllotaxy_deg", &env::GrowthParams::phyllotaxy_deg,
           "Divergence angle between successive lateral buds around the axis (degrees, finite; "
           "137.5)")
      .add("perturbation_deg", &env::GrowthParams::perturbation_deg,
           "Heading noise: a random vector of length sin(perturbation_deg) is added to each "
           "metamer's unit heading (degrees, [0, 90]; 4)")
      .add("lateral_bud_lifetime_years", &env::GrowthParams::lateral_bud_lifetime_years,
           "Dormant lateral buds die after this many cycles (years, integer >= 1; 4)")
      .add("phototropism", &env::GrowthParams::phototropism,
           "Weight of the bud's mean light direction in the heading (Pirk eq. 4.6-4.7; >= 0, with "
           "gravitropism < 1; 0.25)")
      .add("gravitropism", &env::GrowthParams::gravitropism,
           "Weight of gravity_direction in the heading (Pirk eq. 4.6-4.7; >= 0, with phototropism "
           "< 1; 0.12)")
      .add("gravity_direction", &env::GrowthParams::gravity_direction,
           "Direction gravitropism bends towards (non-zero vector; (0, 0, -1): down, so branches "
           "droop)")
      .add("pruning_factor", &env::GrowthParams::pruning_factor,
           "Shedding: a lateral branch with less light per supported internode is removed (>= 0; "
           "0.1)")
      .add("leaf_years", &env::GrowthParams::leaf_years,
           "Shoots younger than this carry a leaf cluster (years, integer >= 1; 2)")
      .add("cluster_radius_m", &env::GrowthParams::cluster_radius_m,
           "Smallest leaf-cluster radius; at least half the shoot length (m, > 0; 0.3)")
      .add("gamma0", &env::GrowthParams::gamma0,
           "Leaf-cluster translucency gamma0^r for a radius r in m (Pirk eq. 4.4; [0, 1]; 0.5)")
      .add("light_directions", &env::GrowthParams::light_directions,
           "light_model 'sky': sky directions of the light integral (integer >= 1; 64)")
      .add(
          "light_significance", &env::GrowthParams::light_significance,
          "light_model 'sky': largest share of light an ignored occluder may remove ([0, 1); 0.01)")
      .add("tip_radius_m", &env::GrowthParams::tip_radius_m,
           "Radius of a shoot tip, the start of the pipe model (m, > 0; 0.004)")
      .add("pipe_exponent", &env::GrowthParams::pipe_exponent,
           "Pipe model exponent n in r^n = sum r_child^n ([1, 4]; 2.5)")
      .add("keep_shed_pipes", &env::GrowthParams::keep_shed_pipes,
           "Radii keep the pipes of shed branches, as wood keeps disused pipes (bool; False)")
      .existing("light_model")
      .existing("voxel_size_m")
      .existing("shadow_a")
      .existing("shadow_b")
      .existing("shadow_depth_voxels")
      .existing("full_light")
      .existing("obstacle_shade")
      .existing("marker_density_per_m3")
      .existing("perception_radius_m")
      .existing("perception_angle_deg")
      .existing("occupancy_radius_m")
      .existing("marker_region_radius_m")
      .existing("marker_region_height_m")
      .finish(&growth_base);
  gp.def(
      "validate", [](const env::GrowthParams& p) { p.validate(); },
      "Raises ParameterError naming the first parameter out of range");
}

void bind_growth_functions(py::module_& m) {
  m.def(
      "growth_preset",
      [](const std::string& name, const std::string& light_model, const std::string& tropisms) {
        return env::growth_preset(name, env::bud_light_model_from_name(light_model),
                                  env::tropism_pairing_from_name(tropisms));
      },
      py::arg("name"), py::arg("light_model") = "shadow_grid", py::arg("preset_tropisms") = "text",
      "Pirk's tree type 'A', 'B' or 'C', with vigour fitted for the light model and the tropism "
      "weights of Pirk's text ('text') or of his appendix captions ('appendix')");
  m.def(
      "read_growth_params",
      [](const std::string& path) {
        py::gil_scoped_release release;
        return env::read_growth_params(path);
      },
      py::arg("path"), "Growth parameters from a TOML file");
  m.def(
      "parse_growth_params", [](const std::string& text) { return env::parse_growth_params(text); },
      py::arg("text"), "Growth parameters from TOML text");

  py::class_<env::GrowthResult>(m, "GrowthResult", "A grown tree and its counts")
      .def_readonly("tree", &env::GrowthResult::tree,
                    "Internodes (birth_time = year, attribute 'light'), then the leaf clusters as "
                    "leaf nodes (radius = cluster radius, attribute 'translucency')")
      .def_readonly("internodes", &env::GrowthResult::internodes, "Internodes in the final tree")
      .def_readonly("clusters", &env::GrowthResult::clusters, "Leaf clusters in the final tree")
      .def_readonly("shed", &env::GrowthResult::shed,
                    "Internodes removed by shedding over the whole run")
      .def_readonly("grown", &env::GrowthResult::grown,
                    "Internodes created over the whole run, shed ones included")
      .def_readonly("height_m", &env::GrowthResult::height_m,
                    "Highest internode end above the base (m)")
      .def_property_readonly(
          "cluster_spheres",
          [](const env::GrowthResult& r) { return sphere_array(r.cluster_spheres); },
          "Final leaf clusters as rows x, y, z, radius, translucency")
      .def("__repr__", [](const env::GrowthResult& r) {
        return "<fspm.GrowthResult: " + std::to_string(r.internodes) + " internodes, " +
               std::to_string(r.clusters) + " clusters, height " + format_significant(r.height_m) +
               " m>";
      });

  m.def(
      "grow_tree",
      [](py::handle params, py::handle scene, const Eigen::Vector3d& base) {
        // A dict goes through the keyword constructor: GrowthParams(**params).
        const env::GrowthParams p =
            py::isinstance<py::dict>(params)
                ? py::type::of<env::GrowthParams>()(**params.cast<py::dict>())
                      .cast<env::GrowthParams>()
                : params.cast<env::GrowthParams>();
        const env::Scene s = scene_from(scene);
        py::gil_scoped_release release;
        return env::grow_tree(p, s, base);
      },
      py::arg("params"), py::arg("scene") = py::none(),
      py::arg("base") = Eigen::Vector3d::Zero().eval(),
      "Grow a tree (GrowthParams, or a dict of them with an optional 'preset') in a scene from "
      "base (x, y, z in m)");
}

// The light of a tree's leaf clusters in its crown (environment/canopy_summary), as fspm tree
// info --json gives it under "canopy_light": totals and one array per quantity, per cluster.
py::dict canopy_light(const TreeGraph& tree, const std::string& sky_file, int directions) {
  std::vector<std::uint32_t> sphere_of;
  const std::vector<env::Sphere> clusters = env::leaf_spheres(tree, sphere_of);
  env::Sky sky;
  sky.directions = directions;
  sky.validate();
  if (!sky_file.empty()) {
    env::apply_sky_distribution(sky, std::make_shared<const env::SkyDistribution>(
                                         env::sky_distribution(env::read_site_sky_file(sky_file))));
  }
  env::CanopyLightSummary c;
  {
    py::gil_scoped_release release;
    c = env::summarize_canopy_light(clusters, sky);
  }
  py::dict out;
  out["sky"] = c.real_sky ? "site" : "cos2";
  out["clusters"] = c.clusters;
  out["leaf_area_m2"] = c.leaf_area_m2;
  out["sunlit_leaf_area_m2"] = c.sunlit_leaf_area_m2;
  out["shaded_leaf_area_m2"] = c.shaded_leaf_area_m2;
  out["lie"] = c.lie;
  out["star"] = c.star;
  if (c.real_sky) out["absorbed_par_mol_day"] = c.absorbed_par_mol_day;
  std::vector<std::int64_t> nodes;
  for (NodeId i = 0; i < tree.size(); ++i) {
    if (sphere_of[i] != env::kNoSphere) nodes.push_back(static_cast<std::int64_t>(i));
  }
  const auto column = [&](double env::ClusterCanopyLight::*field) {
    py::array_t<double> a(static_cast<py::ssize_t>(nodes.size()));
    auto v = a.mutable_unchecked<1>();
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      v(static_cast<py::ssize_t>(k)) = c.per_cluster[sphere_of[nodes[k]]].*field;
    }
    return a;
  };
  py::dict per;
  per["node"] = py::array_t<std::int64_t>(static_cast<py::ssize_t>(nodes.size()), nodes.data());
  per["leaf_area_m2"] = column(&env::ClusterCanopyLight::leaf_area_m2);
  per["sunlit_leaf_area_m2"] = column(&env::ClusterCanopyLight::sunlit_leaf_area_m2);
  per["shaded_leaf_area_m2"] = column(&env::ClusterCanopyLight::shaded_leaf_area_m2);
  per["lie"] = column(&env::ClusterCanopyLight::lie);
  per["star"] = column(&env::ClusterCanopyLight::star);
  if (c.real_sky)
    per["absorbed_par_mol_day"] = column(&env::ClusterCanopyLight::absorbed_par_mol_day);
  out["per_cluster"] = per;
  return out;
}

void bind_growth(py::module_& m) {
  bind_growth_params(m);
  bind_growth_functions(m);
  m.def("canopy_light", &canopy_light, py::arg("tree"), py::arg("sky_file") = std::string(),
        py::arg("directions") = 64,
        "Light of a tree's leaf clusters in its crown, per cluster and for the tree: sunlit and "
        "shaded leaf area (m2), light interception efficiency (lie), STAR and, under a real sky "
        "(sky_file: TOML with sky = { site, date, hours | days }), absorbed PAR (mol/day); "
        "as `fspm tree info --json` gives it under canopy_light");
}

void bind_analysis_params(py::module_& m) {
  py::class_<env::AnalysisParams> ap(
      m, "AnalysisParams", "Parameters of the open-sky analysis for plastic adaptation (Pirk 4.3)");
  ap.def_property(
      "light_model",
      [](const env::AnalysisParams& p) {
        return std::string(env::cluster_light_model_name(p.light_model));
      },
      [](env::AnalysisParams& p, const std::string& name) {
        p.light_model = env::cluster_light_model_from_name(name);
      },
      ("Light of the leaf clusters (default canopy): " + env::kClusterLightModelNames.help())
          .c_str());
  Fields<env::AnalysisParams>(ap)
      .existing("light_model")
      .add("skeleton_radius_m", &env::AnalysisParams::skeleton_radius_m,
           "Internodes at least this thick form the skeleton; <= 0 picks 2.5 times the thinnest "
           "internode radius (m; 0)")
      .add("min_cluster_radius_m", &env::AnalysisParams::min_cluster_radius_m,
           "Smallest leaf-cluster radius (m, > 0; 0.3)")
      .add("gamma0", &env::AnalysisParams::gamma0,
           "Leaf-cluster translucency gamma0^r for a radius r in m (Pirk eq. 4.4; (0, 1]; 0.5)")
      .add("pruning_strength", &env::AnalysisParams::pruning_strength,
           "c_psi of Pirk eq. 4.12: a skeleton segment is pruned below psi_min = c_psi * "
           "min(psi_ref, its analysis pruning factor) (>= 0; 0.8)")
      .add("reference_percentile", &env::AnalysisParams::reference_percentile,
           "psi_ref is this percentile (a fraction: 0.05 = 5 %) of the skeleton's pruning factors "
           "(Pirk 4.3.4; [0, 1]; 0.05)")
      .add("temporal_pruning", &env::AnalysisParams::temporal_pruning,
           "Pruning factor over every earlier stage (eq. 4.5 cluster propagation) instead of the "
           "final one (False)")
      .add("relative_pruning", &env::AnalysisParams::relative_pruning,
           "Pruning thresholds follow the whole tree's resources per length, so a branch is pruned "
           "when it falls behind the crown (True)")
      .add("phototropism", &env::AnalysisParams::phototropism,
           "Tropism weight towards the light direction (Pirk eq. 4.6-4.7; >= 0, with gravitropism "
           "< 1; 0.25)")
      .add("gravitropism", &env::AnalysisParams::gravitropism,
           "Tropism weight towards gravity_direction (Pirk eq. 4.6-4.7; >= 0, with phototropism < "
           "1; 0.12)")
      .add("gravity_direction", &env::AnalysisParams::gravity_direction,
           "Direction gravitropism bends towards (vector; (0, 0, -1): down)")
      .add("light_directions", &env::AnalysisParams::light_directions,
           "light_model 'sky': sky directions of the light integral (integer >= 1; 64)")
      .add("light_significance", &env::AnalysisParams::light_significance,
           "light_model 'sky': largest share of light an ignored occluder may remove (> 0; 0.01)")
      .finish();
}

using TA = env::TreeAnalysis;

void bind_tree_analysis(py::module_& m) {
  py::class_<TA>(m, "TreeAnalysis", "A tree analysed as grown in the open (analyze_tree)")
      .def_property_readonly(
          "params", [](const TA& a) { return a.params; }, "The AnalysisParams used (a copy)")
      .def_readonly("skeleton_radius_m", &TA::skeleton_radius_m,
                    "Radius from which internodes belong to the skeleton, as chosen (m)")
      .def_readonly("internode_length_m", &TA::internode_length_m,
                    "l_i, the mode of the internode lengths (mean shift; m)")
      .def_readonly("height_path_m", &TA::height_path_m,
                    "d_r, path length from the root to the furthest tip (m)")
      .def_readonly("max_age", &TA::max_age, "Largest segment age (seasons, Pirk eq. 4.2)")
      .def_readonly("reference_pruning_factor", &TA::reference_pruning_factor,
                    "psi_ref, the reference_percentile of the skeleton's pruning factors")
      .def_property_readonly(
          "skeleton",
          [](py::object self) {
            return column(std::span<const std::uint8_t>(self.cast<const TA&>().skeleton), self);
          },
          "Per node: 1 main skeleton, 0 fine part")
      .def_property_readonly(
          "cluster_of",
          [](py::object self) {
            return column(std::span<const std::uint32_t>(self.cast<const TA&>().cluster_of), self);
          },
          "Per node: index of its leaf cluster, or 2**32 - 1")
      .def_property_readonly(
          "growth_rate",
          [](py::object self) {
            return column(std::span<const double>(self.cast<const TA&>().growth_rate), self);
          },
          "Absolute growth rate nu_s (Pirk eq. 4.1)")
      .def_property_readonly(
          "age",
          [](py::object self) {
            return column(std::span<const int>(self.cast<const TA&>().age), self);
          },
          "Season each segment was created, 0 = oldest (Pirk eq. 4.2)")
      .def_property_readonly(
          "pruning_factor",
          [](py::object self) {
            return column(std::span<const double>(self.cast<const TA&>().pruning_factor), self);
          },
          "psi_s at analysis time (0 for fine nodes)")
      .def_property_readonly(
          "min_pruning_factor",
          [](py::object self) {
            return column(std::span<const double>(self.cast<const TA&>().min_pruning_factor), self);
          },
          "psi_s_min (Pirk eq. 4.12)")
      .def_property_readonly(
          "tropism_weight",
          [](py::object self) {
            return column(std::span<const double>(self.cast<const TA&>().tropism_weight), self);
          },
          "w_s (Pirk eq. 4.7)")
      .def_property_readonly(
          "clusters", [](const TA& a) { return cluster_array(a.clusters); },
          "Leaf clusters as rows x, y, z, radius, translucency")
      .def("__repr__", [](const TA& a) {
        return "<fspm.TreeAnalysis: " + std::to_string(a.skeleton.size()) + " nodes, " +
               std::to_string(a.clusters.size()) + " clusters>";
      });
}

void bind_adaptation_result(py::module_& m) {
  using AR = env::AdaptationResult;
  py::class_<AR>(m, "AdaptationResult", "An adapted tree (attributes displacement and pruned)")
      .def_readonly("tree", &AR::tree,
                    "The input tree with moved nodes and the attributes 'displacement' (m) and "
                    "'pruned' (1 for pruned nodes, kept at their adapted position)")
      .def_readonly("pruned_nodes", &AR::pruned_nodes, "Nodes flagged 'pruned'")
      .def_readonly("bent_segments", &AR::bent_segments,
                    "Skeleton segments rotated by more than 1e-4 rad")
      .def_readonly("tips", &AR::tips, "Internode tips that survived (no internode child)")
      .def_readonly("mean_tip_displacement_m", &AR::mean_tip_displacement_m,
                    "Mean distance the surviving tips moved (m)")
      .def_property_readonly(
          "mean_tip_shift", [](const AR& r) { return r.mean_tip_shift; },
          "Mean displacement vector (x, y, z) of the surviving tips (m)")
      .def_property_readonly(
          "pruned_centroid", [](const AR& r) { return r.pruned_centroid; },
          "Centroid of the pruned internodes in the input tree (m; zero when none)")
      .def_property_readonly(
          "internode_centroid", [](const AR& r) { return r.internode_centroid; },
          "Centroid of the input tree's internodes (m)")
      .def_property_readonly(
          "clusters", [](const AR& r) { return cluster_array(r.clusters); },
          "Adapted leaf clusters as rows x, y, z, radius, translucency")
      .def("__repr__", [](const AR& r) {
        return "<fspm.AdaptationResult: " + std::to_string(r.tree.size()) + " nodes, " +
               std::to_string(r.pruned_nodes) + " pruned>";
      });
}

void bind_adaptation(py::module_& m) {
  bind_analysis_params(m);
  bind_tree_analysis(m);
  bind_adaptation_result(m);
  m.def(
      "analyze_tree",
      [](const TreeGraph& tree, py::handle params, const Eigen::Vector3d& brightest) {
        // None: defaults; a dict goes through the keyword constructor AnalysisParams(**params).
        env::AnalysisParams p;
        if (py::isinstance<py::dict>(params)) {
          p = py::type::of<env::AnalysisParams>()(**params.cast<py::dict>())
                  .cast<env::AnalysisParams>();
        } else if (!params.is_none()) {
          p = params.cast<env::AnalysisParams>();
        }
        py::gil_scoped_release release;
        return env::analyze_tree(tree, p, brightest);
      },
      py::arg("tree"), py::arg("params") = py::none(),
      py::arg("brightest") = Eigen::Vector3d::UnitZ().eval(),
      "Analyse a tree as grown in the open under the sky's brightest point");
  m.def(
      "adapt_tree",
      [](const TreeGraph& tree, const TA& analysis, py::handle scene) {
        const env::Scene s = scene_from(scene);
        py::gil_scoped_release release;
        return env::adapt_tree(tree, analysis, s);
      },
      py::arg("tree"), py::arg("analysis"), py::arg("scene"),
      "Bend and prune a tree for a scene (Pirk 4.4)");
  m.def(
      "adapt_trees",
      [](const std::vector<const TreeGraph*>& trees, const std::vector<const TA*>& analyses,
         py::handle scene) {
        const env::Scene s = scene_from(scene);
        py::gil_scoped_release release;
        return env::adapt_trees(trees, analyses, s);
      },
      py::arg("trees"), py::arg("analyses"), py::arg("scene"),
      "Adapt trees together: each is shaded by the others' leaf clusters");
  m.def(
      "remove_pruned",
      [](const TreeGraph& adapted) {
        py::gil_scoped_release release;
        return env::remove_pruned(adapted);
      },
      py::arg("tree"), "The adapted tree without its nodes flagged 'pruned'");
}

}  // namespace

void bind_environment(py::module_& m) {
  bind_scene(m);
  bind_light(m);
  bind_growth(m);
  bind_adaptation(m);
}

}  // namespace fspm::python
