#include "crown/mask_morphology.hpp"

#include <algorithm>
#include <vector>

namespace fspm::crown {
namespace {

// Square-window min or max, separably (rows then columns).
Mask window(const Mask& mask, int radius, bool any) {
  Mask rows(mask.width, mask.height), out(mask.width, mask.height);
  for (int y = 0; y < mask.height; ++y) {
    for (int x = 0; x < mask.width; ++x) {
      bool v = !any;
      for (int d = -radius; d <= radius; ++d) {
        const bool s = mask.contains(x + d, y) ? mask.at(x + d, y) : !any;
        v = any ? (v || s) : (v && s);
      }
      rows.set(x, y, v);
    }
  }
  for (int y = 0; y < mask.height; ++y) {
    for (int x = 0; x < mask.width; ++x) {
      bool v = !any;
      for (int d = -radius; d <= radius; ++d) {
        const bool s = rows.contains(x, y + d) ? rows.at(x, y + d) : !any;
        v = any ? (v || s) : (v && s);
      }
      out.set(x, y, v);
    }
  }
  return out;
}

// Labels the piece of pixels equal to `value` containing `seed`, with `label` in `labels`.
std::size_t flood(const Mask& mask, bool value, int seed, bool diagonals, int label,
                  std::vector<int>& labels) {
  std::vector<int> stack{seed};
  labels[static_cast<std::size_t>(seed)] = label;
  std::size_t size = 0;
  while (!stack.empty()) {
    const int p = stack.back();
    stack.pop_back();
    ++size;
    const int x = p % mask.width, y = p / mask.width;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx == 0 && dy == 0) || (!diagonals && dx != 0 && dy != 0)) continue;
        const int qx = x + dx, qy = y + dy;
        if (!mask.contains(qx, qy) || mask.at(qx, qy) != value) continue;
        const int q = qy * mask.width + qx;
        if (labels[static_cast<std::size_t>(q)] != 0) continue;
        labels[static_cast<std::size_t>(q)] = label;
        stack.push_back(q);
      }
    }
  }
  return size;
}

}  // namespace

Mask dilate(const Mask& mask, int radius) { return window(mask, radius, true); }
Mask erode(const Mask& mask, int radius) { return window(mask, radius, false); }

Mask fill_holes(const Mask& mask) {
  std::vector<int> labels(mask.inside.size(), 0);
  for (int y = 0; y < mask.height; ++y) {
    for (int x = 0; x < mask.width; ++x) {
      const bool border = x == 0 || y == 0 || x == mask.width - 1 || y == mask.height - 1;
      const int p = y * mask.width + x;
      if (border && !mask.at(x, y) && labels[static_cast<std::size_t>(p)] == 0) {
        flood(mask, false, p, false, 1, labels);
      }
    }
  }
  Mask out(mask.width, mask.height);
  for (std::size_t p = 0; p < labels.size(); ++p) out.inside[p] = labels[p] == 1 ? 0 : 1;
  return out;
}

Mask large_pieces(const Mask& mask, double fraction) {
  std::vector<int> labels(mask.inside.size(), 0);
  std::vector<std::size_t> sizes{0};  // by label; label 0 is the background
  for (std::size_t p = 0; p < labels.size(); ++p) {
    if (!mask.inside[p] || labels[p] != 0) continue;
    const int label = static_cast<int>(sizes.size());
    sizes.push_back(flood(mask, true, static_cast<int>(p), true, label, labels));
  }
  const std::size_t largest = *std::max_element(sizes.begin(), sizes.end());
  Mask out(mask.width, mask.height);
  for (std::size_t p = 0; p < labels.size(); ++p) {
    const auto size = static_cast<double>(sizes[static_cast<std::size_t>(labels[p])]);
    out.inside[p] = labels[p] != 0 && size >= fraction * static_cast<double>(largest);
  }
  return out;
}

}  // namespace fspm::crown
