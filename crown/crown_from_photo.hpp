#pragma once
// A tree crown from one photograph and its crown mask (Argudo 4.6): base mesh by inflation,
// relief from luminance on the visible half, a colour cubemap synthesized from the crown's
// texture, a height cubemap from it for the hidden half, the radius cubemap of the result.
// Units are metres, z up; the photograph looks along +y, its right is +x.
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "crown/crown_mesh.hpp"
#include "crown/cubemap.hpp"
#include "crown/inflation.hpp"
#include "crown/relief.hpp"
#include "crown/texture_synthesis.hpp"
#include "crown/working_resolution.hpp"

namespace fspm::crown {

struct CrownOptions {
  double height_m = 10.0;  // height of the crown (the mask's top to bottom row)
  // Depth of the crown front to back over its width. 1: as deep as wide, the shape of a crown
  // that grew in the open around a vertical stem; below 1 for crowns flattened against a row.
  double depth_ratio = 1.0;
  InflationOptions inflation;
  ReliefOptions relief;
  double relief_weight = 0.15;  // rho of Argudo 4.6: radius * (1 + rho (h - 0.5))
  int cubemap_size = 0;         // 0: 0.7 of the crown's width in pixels, within [32, 256]
  QuiltOptions quilt;
  double trunk_height_m = 0.0;  // from the ground to the crown's lowest point; 0: no trunk
  double trunk_radius_m = 0.0;  // 0: 2 % of the crown height
  bool billboards = false;
  // The crown's bounding box is reduced to at most this many pixels on its longer side
  // (crown/working_resolution.hpp); its border keeps the photograph's resolution.
  int working_pixels = 512;

  // Throws ValueError naming the first field out of range.
  void validate() const;
};

struct CrownModel {
  CrownMesh mesh;
  Cubemap color;   // RGB
  Cubemap radius;  // metres from `centre`
  Raster relief;   // Poisson-pasted heightfield of the photograph, at the working resolution
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();
  std::vector<Eigen::Vector3f> billboards;
  std::size_t crown_pixels = 0;
  std::size_t silhouette_pixels = 0;
  double metres_per_pixel = 0.0;  // of the photograph
  int working_factor = 1;         // photograph pixels per working pixel along each side
  double volume_m3 = 0.0;
  std::vector<std::pair<std::string, double>> seconds;  // per stage, in order
};

// `foliage` (optional) marks the photograph's pixels that hold crown texture: the gaps between
// them inside the crown are filled from the foliage around them (crown/gap_fill.hpp) at the
// working resolution. Throws ValueError for a photograph and mask of different sizes, an empty
// mask, or options out of range.
CrownModel reconstruct_crown(const Raster& photo, const Mask& mask, const CrownOptions& options,
                             std::mt19937_64& rng, const Mask* foliage = nullptr);

}  // namespace fspm::crown
