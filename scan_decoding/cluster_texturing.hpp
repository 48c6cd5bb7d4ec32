#pragma once
// Cluster texturing (Pirk sec. 3.4, Figures 3.6 and 3.7): each leaf cluster is filled from its
// seed point by iterating patch selection and patch fitting. At a docking position d (first the
// seed point on the skeleton, then the docking points of the patches placed so far), the subset
// S_s of patches of similar thickness and orientation is taken from the species library, each is
// rated by eq. 3.3, and the chosen patch is rotated onto the docking direction and scaled so it
// ends where the ray along that direction leaves the cluster hull. Its docking points that lie
// inside the hull are textured next; patches without docking points end the texturing.
#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "scan_decoding/species_library.hpp"
#include "scans/cluster_model.hpp"

namespace fspm::scan_decoding {

struct TextureOptions {
  // S_s: patches whose thickness is within this ratio of the docking position's ...
  double max_thickness_ratio = 2.0;
  // ... and whose orientation is within this angle of its direction.
  double max_angle_deg = 60.0;
  // Patches whose |d - 1| (eq. 3.3) is within this of the best one's are equally good; one of
  // them is drawn with the seeded generator, so clusters of one tree are not textured alike.
  double fit_tolerance = 0.1;
  int max_depth = 8;  // docking generations after the seed's patch
  std::size_t max_patches_per_cluster = 5000;
  // A docking point so near the hull that its patch would shrink below this share of its
  // parent's scale stays empty.
  double min_scale_ratio = 0.25;
  // Patches are scaled to the hull but never beyond this (1: the library's size, the species'
  // own leaves and internodes, species_sizes); a large hull takes more patches, not larger ones.
  double max_scale = 1.0;
  // Texture up to the cluster's branch length (ClusterHull::branch_length_m, the skeleton length
  // the scan showed there): stop there, and once Pirk's texturing has used every docking point
  // short of it, start further branchlets at the seed point. Clusters without one, or false:
  // Pirk's texturing alone.
  bool match_branch_length = true;

  // Throws ValueError naming the first field out of range.
  void validate() const;
};

inline constexpr std::uint32_t kNoPlacement = std::numeric_limits<std::uint32_t>::max();

// A docking position in the world: the seed point of a cluster or a placed patch's docking point.
struct Docking {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // unit
  double thickness = 1.0;                                // relative, as in the library
};

// One patch placed in a cluster: x_world = translation + scale * rotation * x_patch.
struct PlacedPatch {
  std::uint32_t patch = 0;
  std::uint32_t cluster = 0;
  std::uint32_t parent = kNoPlacement;  // placement it docks on; none: the cluster's seed point
  std::uint32_t docking = 0;            // which docking point of the parent's patch
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  double scale = 1.0;
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  double fit = 0.0;  // d of eq. 3.3
  int depth = 0;     // 0 at the seed point

  Eigen::Vector3d to_world(const Eigen::Vector3d& x) const {
    return translation + scale * (rotation * x);
  }
};

// Pirk eq. 3.3: d = max(thickn_r, thickn_d) / min(thickn_r, thickn_d) * (v_r . v_d), r the root
// of the patch, d the docking point. It is 1 for a patch of the docking point's thickness and
// orientation; a thickness mismatch raises it and an angle lowers it.
double patch_fit(double thickness_r, double thickness_d, const Eigen::Vector3d& v_r,
                 const Eigen::Vector3d& v_d);

// S_s: indices of the patches within the thickness ratio and angle of TextureOptions.
std::vector<std::uint32_t> similar_patches(const SpeciesLibrary& library, const Docking& docking,
                                           const TextureOptions& options);

// The patches of `candidates` whose |d - 1| is within options.fit_tolerance of the smallest.
std::vector<std::uint32_t> best_fitting_patches(const SpeciesLibrary& library,
                                                const std::vector<std::uint32_t>& candidates,
                                                const Docking& docking,
                                                const TextureOptions& options);

// The seed point of a cluster: the end of its skeleton node, directed to the hull's centroid
// (the node's direction when they coincide), thickness 1.
Docking seed_docking(const scans::ClusterModel& model, std::size_t cluster);

// Textures one cluster (parents before children). A cluster without hull triangles, or whose
// hull the seed's ray does not reach, gets no patches. At the seed point an empty S_s falls
// back to the whole library; elsewhere it leaves the docking point empty. With
// match_branch_length, texturing stops once the placed internodes (scale x
// Patch::internode_length_m) are as long as the cluster's branch length, and further branchlets
// start at the seed point, each towards a point drawn inside the hull, until they are, the
// cluster has its most patches, or 16 seeds in a row place nothing.
std::vector<PlacedPatch> texture_cluster(const scans::ClusterModel& model, std::size_t cluster,
                                         const SpeciesLibrary& library,
                                         const TextureOptions& options, std::mt19937_64& rng);

// Every cluster in order. Throws ValueError for an empty library, bad options or a cluster whose
// seed node is not in the skeleton.
std::vector<PlacedPatch> texture_clusters(const scans::ClusterModel& model,
                                          const SpeciesLibrary& library,
                                          const TextureOptions& options, std::mt19937_64& rng);

}  // namespace fspm::scan_decoding
