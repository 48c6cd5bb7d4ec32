#include "crown/mask_morphology.hpp"

#include <algorithm>
#include <vector>

namespace fspm::crown {
namespace {

// Square-window max (dilation, `any`) or min, separably (rows then columns). Each pass keeps a
// running count of the crown pixels in the window, so the cost is independent of the radius (the
// automatic mask's closing of a 4000 x 3000 photograph has a radius of 60 pixels). Pixels past the
// border count as background for a dilation and as crown for an erosion.
void window_pass(const Mask& in, Mask& out, int radius, bool any, bool along_rows) {
  const int lines = along_rows ? in.height : in.width;
  const int length = along_rows ? in.width : in.height;
  auto value = [&](int line, int i) {
    if (i < 0 || i >= length) return !any;
    return along_rows ? in.at(i, line) : in.at(line, i);
  };
  const int full = 2 * radius + 1;
  for (int line = 0; line < lines; ++line) {
    int count = 0;
    for (int i = -radius; i <= radius; ++i) count += value(line, i);
    for (int i = 0; i < length; ++i) {
      const bool v = any ? count > 0 : count == full;
      if (along_rows) {
        out.set(i, line, v);
      } else {
        out.set(line, i, v);
      }
      count += value(line, i + radius + 1) - value(line, i - radius);
    }
  }
}

Mask window(const Mask& mask, int radius, bool any) {
  Mask rows(mask.width, mask.height), out(mask.width, mask.height);
  window_pass(mask, rows, radius, any, true);
  window_pass(rows, out, radius, any, false);
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
