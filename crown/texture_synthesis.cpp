#include "crown/texture_synthesis.hpp"

#include <algorithm>
#include <limits>
#include <vector>

#include "fspm/error.hpp"

namespace fspm::crown {
namespace {

struct Source {
  const Raster& rgb;
  std::vector<std::pair<int, int>> corners;  // top-left corners of patches inside the crown
  int patch = 0;
};

// Every corner whose patch lies entirely in the mask (summed-area table of the mask).
std::vector<std::pair<int, int>> patch_corners(const Mask& mask, int patch) {
  const int w = mask.width, h = mask.height;
  std::vector<int> sat(static_cast<std::size_t>(w + 1) * (h + 1), 0);
  auto s = [&](int x, int y) -> int& { return sat[static_cast<std::size_t>(y) * (w + 1) + x]; };
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x)
      s(x + 1, y + 1) = mask.at(x, y) + s(x, y + 1) + s(x + 1, y) - s(x, y);
  }
  std::vector<std::pair<int, int>> out;
  for (int y = 0; y + patch <= h; ++y) {
    for (int x = 0; x + patch <= w; ++x) {
      if (s(x + patch, y + patch) - s(x, y + patch) - s(x + patch, y) + s(x, y) == patch * patch) {
        out.emplace_back(x, y);
      }
    }
  }
  return out;
}

float squared_difference(const Raster& a, int ax, int ay, const Raster& b, int bx, int by) {
  float d = 0.0f;
  for (int c = 0; c < 3; ++c) {
    const float e = a.at(ax, ay, c) - b.at(bx, by, c);
    d += e * e;
  }
  return d;
}

// Squared error of candidate (sx, sy) over the overlaps of the slot at (ox, oy) already laid.
float overlap_error(const Source& src, int sx, int sy, const Raster& out, int ox, int oy,
                    int overlap) {
  float error = 0.0f;
  for (int i = 0; i < src.patch && oy + i < out.height; ++i) {
    for (int j = 0; j < src.patch && ox + j < out.width; ++j) {
      const bool in_overlap = (ox > 0 && j < overlap) || (oy > 0 && i < overlap);
      if (in_overlap) error += squared_difference(src.rgb, sx + j, sy + i, out, ox + j, oy + i);
    }
  }
  return error;
}

// Lays the chosen patch, cutting along the minimum-error seams of the left and top overlaps.
void lay_patch(const Source& src, int sx, int sy, Raster& out, int ox, int oy, int overlap) {
  const int rows = std::min(src.patch, out.height - oy), cols = std::min(src.patch, out.width - ox);
  std::vector<int> left_cut(static_cast<std::size_t>(rows), 0),
      top_cut(static_cast<std::size_t>(cols), 0);
  if (ox > 0) {
    std::vector<float> e(static_cast<std::size_t>(rows) * overlap);
    for (int i = 0; i < rows; ++i) {
      for (int j = 0; j < overlap; ++j)
        e[static_cast<std::size_t>(i) * overlap + j] =
            squared_difference(src.rgb, sx + j, sy + i, out, ox + j, oy + i);
    }
    left_cut = min_error_cut(e, rows, overlap);
  }
  if (oy > 0) {  // the top seam is a cut of the transposed overlap
    std::vector<float> e(static_cast<std::size_t>(cols) * overlap);
    for (int j = 0; j < cols; ++j) {
      for (int i = 0; i < overlap; ++i)
        e[static_cast<std::size_t>(j) * overlap + i] =
            squared_difference(src.rgb, sx + j, sy + i, out, ox + j, oy + i);
    }
    top_cut = min_error_cut(e, cols, overlap);
  }
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < cols; ++j) {
      if (j < left_cut[static_cast<std::size_t>(i)] || i < top_cut[static_cast<std::size_t>(j)])
        continue;
      for (int c = 0; c < 3; ++c) out.at(ox + j, oy + i, c) = src.rgb.at(sx + j, sy + i, c);
    }
  }
}

}  // namespace

std::vector<int> min_error_cut(const std::vector<float>& errors, int rows, int cols) {
  std::vector<float> cost(errors);
  for (int i = 1; i < rows; ++i) {
    for (int j = 0; j < cols; ++j) {
      float best = cost[static_cast<std::size_t>(i - 1) * cols + j];
      if (j > 0) best = std::min(best, cost[static_cast<std::size_t>(i - 1) * cols + j - 1]);
      if (j + 1 < cols) best = std::min(best, cost[static_cast<std::size_t>(i - 1) * cols + j + 1]);
      cost[static_cast<std::size_t>(i) * cols + j] += best;
    }
  }
  std::vector<int> cut(static_cast<std::size_t>(rows));
  const auto last = cost.begin() + static_cast<std::ptrdiff_t>(rows - 1) * cols;
  int j = static_cast<int>(std::min_element(last, last + cols) - last);
  for (int i = rows - 1; i >= 0; --i) {
    cut[static_cast<std::size_t>(i)] = j;
    if (i == 0) break;
    int best = j;
    for (int k = std::max(0, j - 1); k <= std::min(cols - 1, j + 1); ++k) {
      if (cost[static_cast<std::size_t>(i - 1) * cols + k] <
          cost[static_cast<std::size_t>(i - 1) * cols + best])
        best = k;
    }
    j = best;
  }
  return cut;
}

Raster quilt_texture(const Raster& rgb, const Mask& mask, int width, int height,
                     const QuiltOptions& options, std::mt19937_64& rng) {
  Source src{rgb, {}, std::max(4, options.patch_px)};
  for (; src.patch >= 4; src.patch /= 2) {
    src.corners = patch_corners(mask, src.patch);
    if (!src.corners.empty()) break;
  }
  if (src.corners.empty()) throw ValueError("the crown is too small to take texture patches from");
  const int overlap = std::max(2, src.patch / 4), step = src.patch - overlap;
  Raster out(width, height, 3);
  std::uniform_int_distribution<std::size_t> pick(0, src.corners.size() - 1);
  for (int oy = 0; oy < height; oy += step) {
    for (int ox = 0; ox < width; ox += step) {
      std::pair<int, int> best = src.corners[pick(rng)];
      float best_error = std::numeric_limits<float>::max();
      for (int k = 0; k < options.candidates && (ox > 0 || oy > 0); ++k) {
        const auto c = src.corners[pick(rng)];
        const float e = overlap_error(src, c.first, c.second, out, ox, oy, overlap);
        if (e < best_error) best_error = e, best = c;
      }
      lay_patch(src, best.first, best.second, out, ox, oy, overlap);
    }
  }
  return out;
}

}  // namespace fspm::crown
