#pragma once
// Relief from luminance (Argudo 4.4): under diffuse light a dense crown is darker the deeper a
// point lies, so luminance L = 0.2126 R + 0.7152 G + 0.0722 B, normalized to [0, 1] over the
// crown, estimates height. Noise is removed by a blur pyramid (increasing Gaussian radius at full
// resolution, no downsampling, so no upsampling artefacts) whose levels are summed with weights
// growing with the blur (large structures count most). The heightfield is then pasted onto the
// plane of the silhouette by Poisson image editing (Perez et al. 2003): the 4-neighbour system
// 4 x_p - sum_{q in N_p and C} x_q = 4 H_p - sum_{q in N_p} H_q, with x = 0 outside the crown.
#include "crown/raster.hpp"

namespace fspm::crown {

struct ReliefOptions {
  int levels = 4;             // N, Argudo used 4 and 5
  double first_sigma_px = 1;  // blur of the finest level; each next level doubles it

  // Throws ValueError naming the first field out of range.
  void validate() const;
};

// The weighted sum of the blur pyramid of the crown's normalized luminance, in [0, 1] inside the
// mask, 0 outside. Throws ValueError for levels < 1 or an empty mask.
Raster luminance_heightfield(const Raster& rgb, const Mask& mask, const ReliefOptions& options);

// Poisson pasting of `height` onto the zero plane: same gradients inside the crown, 0 on its
// border. Solved with Eigen's SimplicialLDLT (the system is symmetric positive definite).
Raster paste_on_plane(const Raster& height, const Mask& mask);

// Both steps.
Raster relief(const Raster& rgb, const Mask& mask, const ReliefOptions& options);

}  // namespace fspm::crown
