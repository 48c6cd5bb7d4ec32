#pragma once
// Example-based synthesis of crown texture (Argudo 4.5) by image quilting (Efros and Freeman
// 2001): square patches cut from inside the photographed crown are laid in raster order with an
// overlap; among random candidate patches the one that best matches what is already laid is
// taken, and the seam through each overlap is the minimum-error boundary cut found by dynamic
// programming. Argudo seeds Wei and Levoy's per-pixel synthesis with such quilted patches joined
// by graph cuts; quilting alone keeps the photograph's structures (leaf clumps, gaps) at their
// size and runs in a fraction of a second instead of minutes (Argudo Table 7.1: 40-45 min).
#include <random>

#include "crown/raster.hpp"

namespace fspm::crown {

struct QuiltOptions {
  int patch_px = 24;    // side of a square patch; halved until a patch fits inside the crown
  int candidates = 48;  // random source patches tried per slot
};

// A width x height RGB texture from the crown pixels of `rgb` (only patches entirely inside
// `mask` are used). Throws ValueError when no 4 x 4 patch fits inside the crown.
Raster quilt_texture(const Raster& rgb, const Mask& mask, int width, int height,
                     const QuiltOptions& options, std::mt19937_64& rng);

// Minimum-error boundary cut through an overlap of `rows` x `cols` squared differences
// (row-major): for each row the first column taken from the new patch, the path moving at most
// one column between rows.
std::vector<int> min_error_cut(const std::vector<float>& errors, int rows, int cols);

}  // namespace fspm::crown
