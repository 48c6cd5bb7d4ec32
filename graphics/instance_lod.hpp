#pragma once
// Level of detail per plant instance for scenes of many plants (Argudo 2014, chapter 6): each
// frame, every placed plant is culled when its bounding sphere lies outside the view frustum,
// given a resolution of its mesh from its distance and size (Reynolds et al. 2011, expression 2,
// tessellation_level) and a share of its leaves (stochastic pruning, Cook et al. 2007: a prefix
// of the randomly ordered leaf buffer). Each plant's switch distances are scaled by a jitter
// hashed from its instance index (Argudo 6), so plants in a row do not change level together.
// Everything is deterministic: the same scene, camera and options give the same choice.
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "graphics/frustum_culling.hpp"
#include "graphics/instanced_mesh.hpp"
#include "graphics/triangle_mesh.hpp"

namespace fspm::graphics {

struct LodOptions {
  // D_max of expression 2: a plant as large as the largest of the scene takes the finest of R
  // resolutions up to max_distance_m / R, the next one up to 2 max_distance_m / R, ..., and the
  // coarsest from (R - 1) max_distance_m / R on (Reynolds' level 0 culls; here the coarsest mesh
  // is kept and only the frustum culls).
  double max_distance_m = 100.0;
  // Every leaf is drawn up to this distance; beyond it the share (reference / d)^2
  // (pruning_fraction), rounded up to the next of leaf_fractions.
  double prune_distance_m = 20.0;
  // Switch distances of instance i are those of the plant at distance d (1 + jitter h(i)), h(i)
  // in [-0.5, 0.5) hashed from i (lod_jitter).
  double jitter = 0.25;
  // Shares of the leaves prebuilt per resolution, from 1 down (strictly decreasing, in (0, 1]).
  std::vector<double> leaf_fractions = {1.0, 0.5, 0.25, 0.125};
  // Impostors (impostor.hpp): a plant as large as the largest of the scene is drawn as one
  // textured quad beyond this distance, a smaller one from proportionally nearer (the same
  // projected size); jittered as the switch distances. 0: never (renders without impostors).
  double impostor_distance_m = 0.0;

  // Throws ValueError for non-positive distances, a jitter outside [0, 1) or bad leaf fractions.
  void validate() const;
};

// One plant at a few resolutions (finest first), each with its leaves pruned to every share of
// LodOptions::leaf_fractions: variants[r][k] is resolution r with leaf share k.
struct LodPlant {
  std::vector<std::vector<TriangleMesh>> variants;
  BoundingSphere sphere;  // of the finest mesh, in the plant's frame
};

// The resolutions of one plant (the same leaves at every resolution, finest first); the leaves
// are ordered once by a generator seeded with `seed`, the same order at every resolution.
// Throws ValueError for no resolutions or bad options.
LodPlant make_lod_plant(const std::vector<TriangleMesh>& resolutions, const LodOptions& options,
                        std::uint64_t seed);

struct LodScene {
  std::vector<LodPlant> plants;
  std::vector<PartPlacement> placements;  // part = index into plants
  InstancedMesh fixed;                    // drawn as is every frame (obstacles)

  // The meshes of every variant, plant by plant (resolution-major), then those of `fixed`:
  // the mesh indices of lod_instances.
  std::vector<const TriangleMesh*> meshes() const;
  std::uint32_t mesh_index(std::size_t plant, std::size_t resolution, std::size_t share) const;
};

// The bounding sphere of a plant placed by `placement`: its centre placed, its radius scaled by
// the largest stretch of the placement's linear part.
BoundingSphere placed_sphere(const LodPlant& plant, const PartPlacement& placement);

// h(i) in [-0.5, 0.5): a hash of the instance index (splitmix64), no generator state.
double lod_jitter(std::size_t instance);

struct InstanceLod {
  bool visible = false;
  bool impostor = false;       // visible, drawn as an impostor (not among lod_instances)
  std::size_t resolution = 0;  // 0 finest
  std::size_t share = 0;       // index into leaf_fractions
  double distance_m = 0.0;     // eye to the placed bounding sphere's centre
};

// The choice for every placement seen from `eye_m` through `view_projection` (OpenGL clip
// space). Throws ValueError for bad options or a placement naming a missing plant.
std::vector<InstanceLod> select_lod(const LodScene& scene, const Eigen::Vector3d& eye_m,
                                    const Eigen::Matrix4d& view_projection,
                                    const LodOptions& options);

// The meshes to draw for a choice: a visible placement's chosen variant (impostors left out:
// they are quads, impostor.hpp), then the fixed instances, mesh indices as LodScene::meshes.
std::vector<MeshInstance> lod_instances(const LodScene& scene,
                                        const std::vector<InstanceLod>& choice);

// The scene drawn for a choice as an instanced mesh (every variant mesh, the chosen instances).
InstancedMesh lod_instanced(const LodScene& scene, const std::vector<InstanceLod>& choice);

// Triangles drawn for a choice (each instance counted).
std::size_t lod_triangle_count(const LodScene& scene, const std::vector<MeshInstance>& instances);

}  // namespace fspm::graphics
