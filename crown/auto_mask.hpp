#pragma once
// Automatic crown mask for a photograph without one (Argudo leaves segmentation to the user):
// the background of every row is the colour at the row's left and right ends (sky above, ground
// below, both seen beside the tree). A pixel is crown when its colour is far from its row's
// background; a closing joins the foliage, an opening then removes the thin trunk and branches,
// holes are filled and the pieces of at least a tenth of the largest one's area are kept. Write the
// mask out and check it: a tree touching the image's sides or a background that changes along a row
// defeats it.
#include <string>

#include "crown/raster.hpp"

namespace fspm::crown {

struct AutoMaskOptions {
  float threshold = 0.12f;  // RGB distance (0..sqrt 3) from the row's background
  int open_px = 0;          // 0: 1 % of the image height, at least 1
  int close_px = 0;         // 0: 2 % of the image height, at least 1
};

// Throws ValueError naming `source` (the photograph's file, when given) when nothing differs
// from the background.
Mask auto_mask(const Raster& rgb, const AutoMaskOptions& options, const std::string& source = {});

// The pixels that differ from their row's background (foliage, branches), before any clean-up:
// inside the crown mask the others are sky seen through gaps in the foliage.
Mask foreground(const Raster& rgb, float threshold);

}  // namespace fspm::crown
