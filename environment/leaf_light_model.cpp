#include "environment/leaf_light_model.hpp"

#include <cmath>

#include "environment/occluders.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {

// The models, each defined in its own file.
std::unique_ptr<LeafLightModel> make_turbid_leaf_light(const Sky& sky);  // leaf_light_turbid.cpp
std::unique_ptr<LeafLightModel> make_sweep_leaf_light(const Sky& sky);   // leaf_light_sweep.cpp

namespace {

constexpr LeafLightModelEntry kModels[] = {
    {"turbid",
     "turbid medium along every sky direction through the clusters' spheres (0.1 m voxels above "
     "1 000 clusters)",
     &make_turbid_leaf_light},
    {"sweep", "turbid medium swept once per sky direction through 0.4 m voxels",
     &make_sweep_leaf_light},
};

}  // namespace

std::span<const LeafLightModelEntry> leaf_light_models() { return kModels; }

std::string leaf_light_model_names() {
  std::string out;
  for (const LeafLightModelEntry& e : kModels)
    out += (out.empty() ? "" : ", ") + std::string(e.name);
  return out;
}

std::unique_ptr<LeafLightModel> make_leaf_light_model(const std::string& name, const Sky& sky) {
  for (const LeafLightModelEntry& e : kModels) {
    if (name == e.name) return e.make(sky);
  }
  throw ValueError("unknown leaf light model '" + name.substr(0, 40) + "' (expected one of " +
                   leaf_light_model_names() + ")");
}

double obstacle_transmission(const Scene& scene, const Eigen::Vector3d& p,
                             const Eigen::Vector3d& d) {
  double t = 1.0;
  if (scene.ground && p.z() < scene.ground->height_m) t *= scene.ground->translucency;
  for (const Sphere& o : scene.spheres) {
    if (ray_hits_sphere(p, d, o.center, o.radius_m)) t *= o.translucency;
  }
  for (const Box& b : scene.boxes) {
    if (b.ray_entry(p, d) >= 0.0) t *= b.translucency;
  }
  for (const TriangleMesh& m : scene.meshes) {
    const int n = m.crossings(p, d);
    if (n > 0) t *= std::pow(m.translucency, n);
  }
  return t;
}

std::vector<float> obstacle_visibility(const Scene& scene, const HemisphereDirections& dirs,
                                       const Eigen::Vector3d& p) {
  const bool any = !scene.spheres.empty() || !scene.boxes.empty() || !scene.meshes.empty() ||
                   scene.ground.has_value();
  if (!any) return {};
  std::vector<float> vis(static_cast<std::size_t>(dirs.size()), 1.0f);
  bool shaded = false;
  for (int i = 0; i < dirs.size(); ++i) {
    const double t = obstacle_transmission(scene, p, dirs.direction(i));
    vis[static_cast<std::size_t>(i)] = static_cast<float>(t);
    shaded = shaded || t < 1.0;
  }
  if (!shaded) vis.clear();
  return vis;
}

}  // namespace fspm::environment
