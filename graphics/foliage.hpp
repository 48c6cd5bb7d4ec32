#pragma once
// Foliage of leaf clusters. Grown and adapted trees keep their leaves as clusters (Pirk 4.2: a
// sphere of leaves at the end of each young shoot, drawn in his figures as leaf billboards): leaf
// nodes of length 0 whose radius is the cluster's radius. A cluster is drawn either as
//   kLeaves:  a cloud of small quads, bases uniform in the sphere, orientations uniform, every
//             vertex inside the sphere;
//   kVolumes: the sphere itself, a latitude-longitude mesh in the translucent crown material.
// Random placement draws from a generator the caller seeds: same seed, same picture.
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <random>
#include <string_view>

#include "fspm/name_table.hpp"
#include "graphics/triangle_mesh.hpp"

namespace fspm::graphics {

enum class FoliageMode : std::uint8_t { kLeaves, kVolumes };

inline constexpr NameTable<FoliageMode, 2> kFoliageModeNames{
    "foliage",
    {{FoliageMode::kLeaves, "leaves", "leaf quads in each cluster"},
     {FoliageMode::kVolumes, "volumes", "one translucent sphere per cluster"}}};

// "leaves" or "volumes"; throws ValueError naming both.
FoliageMode foliage_mode_from_name(std::string_view name);

struct FoliageOptions {
  FoliageMode mode = FoliageMode::kLeaves;
  int leaves_per_cluster = 32;
  double leaf_length_ratio = 0.35;  // leaf length / cluster radius
  double leaf_width_ratio = 0.5;    // leaf width / leaf length
  int sphere_slices = 12;           // meridians of a crown volume
  int sphere_stacks = 8;            // bands between its poles

  // Throws ValueError for counts below 1 leaf, 3 slices, 2 stacks or ratios <= 0.
  void validate() const;
};

struct FoliageCounts {
  std::size_t vertices = 0;
  std::size_t triangles = 0;
};

// Vertices and triangles of one cluster: kLeaves 4 n and 2 n (n leaves), kVolumes
// (stacks + 1)(slices + 1) and 2 slices (stacks - 1) (one triangle per cell at the poles).
FoliageCounts cluster_counts(const FoliageOptions& options);

// Writes one cluster at vertex `v` and triangle `t` of `mesh` (already sized; advances both):
// positions, normals, uvs, triangles and materials (leaf or crown). Attributes are the caller's.
void write_cluster(const Eigen::Vector3d& center, double radius_m, const FoliageOptions& options,
                   std::mt19937_64& rng, TriangleMesh& mesh, std::uint32_t& v, std::size_t& t);

}  // namespace fspm::graphics
