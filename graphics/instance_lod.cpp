// Level of detail per plant instance: frustum culling, resolution from expression 2, stochastic
// pruning, jittered switch distances (Argudo 2014, chapter 6).
#include "graphics/instance_lod.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "fspm/error.hpp"
#include "graphics/stochastic_pruning.hpp"
#include "graphics/tessellation_level.hpp"

namespace fspm::graphics {
namespace {

constexpr double kPi = 3.141592653589793;

// The index of the smallest share not below `fraction` (shares strictly decreasing from 1).
std::size_t share_for(const std::vector<double>& shares, double fraction) {
  std::size_t k = 0;
  while (k + 1 < shares.size() && shares[k + 1] >= fraction) ++k;
  return k;
}

}  // namespace

void LodOptions::validate() const {
  if (!(max_distance_m > 0.0) || !std::isfinite(max_distance_m) || !(prune_distance_m > 0.0) ||
      !std::isfinite(prune_distance_m) || !(impostor_distance_m >= 0.0) ||
      !std::isfinite(impostor_distance_m)) {
    throw ValueError(
        "level of detail: max_distance_m and prune_distance_m must be positive and finite, "
        "impostor_distance_m finite and >= 0");
  }
  if (!(jitter >= 0.0 && jitter < 1.0)) {
    throw ValueError("level of detail: jitter must lie in [0, 1)");
  }
  if (leaf_fractions.empty() || leaf_fractions.front() != 1.0) {
    throw ValueError("level of detail: leaf_fractions must start at 1");
  }
  for (std::size_t k = 1; k < leaf_fractions.size(); ++k) {
    if (!(leaf_fractions[k] > 0.0 && leaf_fractions[k] < leaf_fractions[k - 1])) {
      throw ValueError("level of detail: leaf_fractions must decrease strictly and stay above 0");
    }
  }
}

LodPlant make_lod_plant(const std::vector<TriangleMesh>& resolutions, const LodOptions& options,
                        std::uint64_t seed) {
  options.validate();
  if (resolutions.empty()) throw ValueError("a plant needs at least one resolution");
  LodPlant plant;
  plant.sphere = bounding_sphere(resolutions.front());
  for (const TriangleMesh& mesh : resolutions) {
    // The same seed at every resolution: the leaves are the same, so is their order.
    std::mt19937_64 rng(seed);
    const LeafBuffer buffer = make_leaf_buffer(mesh, rng);
    auto& shares = plant.variants.emplace_back();
    for (double f : options.leaf_fractions) {
      shares.push_back(pruned_mesh(buffer, pruned_leaf_count(buffer.leaf_count(), f)));
    }
  }
  return plant;
}

std::vector<const TriangleMesh*> LodScene::meshes() const {
  std::vector<const TriangleMesh*> out;
  for (const LodPlant& p : plants) {
    for (const auto& shares : p.variants) {
      for (const TriangleMesh& m : shares) out.push_back(&m);
    }
  }
  for (const TriangleMesh& m : fixed.meshes) out.push_back(&m);
  return out;
}

std::uint32_t LodScene::mesh_index(std::size_t plant, std::size_t resolution,
                                   std::size_t share) const {
  std::size_t index = 0;
  for (std::size_t p = 0; p < plant; ++p) {
    for (const auto& shares : plants[p].variants) index += shares.size();
  }
  for (std::size_t r = 0; r < resolution; ++r) index += plants[plant].variants[r].size();
  return static_cast<std::uint32_t>(index + share);
}

BoundingSphere placed_sphere(const LodPlant& plant, const PartPlacement& p) {
  const Eigen::Matrix3d linear = p.linear.cast<double>();
  BoundingSphere s;
  s.center = linear * plant.sphere.center + p.translation.cast<double>();
  s.radius = plant.sphere.radius * linear.colwise().norm().maxCoeff();
  return s;
}

double lod_jitter(std::size_t instance) {
  // splitmix64's finaliser (Steele, Lea and Flood 2014) of the index.
  std::uint64_t z = static_cast<std::uint64_t>(instance) + 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) / 9007199254740992.0 - 0.5;  // 53 bits in [0, 1)
}

std::vector<InstanceLod> select_lod(const LodScene& scene, const Eigen::Vector3d& eye_m,
                                    const Eigen::Matrix4d& view_projection,
                                    const LodOptions& options) {
  options.validate();
  const Frustum frustum = frustum_from_matrix(view_projection);
  std::vector<BoundingSphere> spheres;
  double largest_area = 0.0;
  for (const PartPlacement& p : scene.placements) {
    if (p.part >= scene.plants.size()) {
      throw ValueError("placement refers to plant " + std::to_string(p.part) + " of " +
                       std::to_string(scene.plants.size()));
    }
    spheres.push_back(placed_sphere(scene.plants[p.part], p));
    largest_area = std::max(largest_area, kPi * spheres.back().radius * spheres.back().radius);
  }
  const double largest_radius = std::sqrt(largest_area / kPi);
  std::vector<InstanceLod> out(spheres.size());
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const BoundingSphere& s = spheres[i];
    const LodPlant& plant = scene.plants[scene.placements[i].part];
    InstanceLod& lod = out[i];
    lod.distance_m = (s.center - eye_m).norm();
    lod.visible = !plant.variants.empty() && !sphere_outside(frustum, s.center, s.radius);
    if (!lod.visible) continue;
    const double d = lod.distance_m * (1.0 + options.jitter * lod_jitter(i));
    // Impostors from the distance at which the plant looks as large as the largest one at
    // impostor_distance_m (the same projected size, so the same texture resolution suffices).
    lod.impostor = options.impostor_distance_m > 0.0 && largest_radius > 0.0 &&
                   d > options.impostor_distance_m * s.radius / largest_radius;
    const auto resolutions = static_cast<double>(plant.variants.size());
    // Expression 2 with the projected size of the plant (its bounding disc) as the face area
    // and L_max the number of resolutions: level k and above selects resolution R - 1 - k.
    const TessellationLimits limits{options.max_distance_m, largest_area > 0.0 ? largest_area : 1.0,
                                    resolutions};
    const double level = tessellation_level(d, kPi * s.radius * s.radius, limits);
    const auto k = std::min(static_cast<std::size_t>(std::floor(level)), plant.variants.size() - 1);
    lod.resolution = plant.variants.size() - 1 - k;
    lod.share = share_for(options.leaf_fractions, pruning_fraction(d, options.prune_distance_m));
    lod.share = std::min(lod.share, plant.variants[lod.resolution].size() - 1);
  }
  return out;
}

std::vector<MeshInstance> lod_instances(const LodScene& scene,
                                        const std::vector<InstanceLod>& choice) {
  std::vector<MeshInstance> out;
  for (std::size_t i = 0; i < choice.size() && i < scene.placements.size(); ++i) {
    if (!choice[i].visible || choice[i].impostor) continue;
    const PartPlacement& p = scene.placements[i];
    MeshInstance inst;
    inst.mesh = scene.mesh_index(p.part, choice[i].resolution, choice[i].share);
    inst.linear = p.linear;
    inst.translation = p.translation;
    out.push_back(inst);
  }
  const auto first_fixed =
      static_cast<std::uint32_t>(scene.meshes().size() - scene.fixed.meshes.size());
  for (MeshInstance inst : scene.fixed.instances) {
    inst.mesh += first_fixed;
    out.push_back(inst);
  }
  return out;
}

InstancedMesh lod_instanced(const LodScene& scene, const std::vector<InstanceLod>& choice) {
  InstancedMesh out;
  for (const TriangleMesh* m : scene.meshes()) out.meshes.push_back(*m);
  out.instances = lod_instances(scene, choice);
  return out;
}

std::size_t lod_triangle_count(const LodScene& scene, const std::vector<MeshInstance>& instances) {
  const std::vector<const TriangleMesh*> meshes = scene.meshes();
  std::size_t n = 0;
  for (const MeshInstance& inst : instances) n += meshes[inst.mesh]->triangle_count();
  return n;
}

}  // namespace fspm::graphics
