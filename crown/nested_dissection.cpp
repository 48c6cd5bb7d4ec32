#include "crown/nested_dissection.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace fspm::crown {
namespace {

// Width of a separator band: the stencil of eq. 4.2 reaches 2 pixels along each direction.
constexpr std::int64_t kBandPixels = 2;

// Coordinate of a pixel along one of the four cut directions: column, row, x + y, x - y.
std::int64_t coordinate(std::size_t pixel, int width, int direction) {
  const auto x = static_cast<std::int64_t>(pixel % static_cast<std::size_t>(width));
  const auto y = static_cast<std::int64_t>(pixel / static_cast<std::size_t>(width));
  switch (direction) {
    case 0:
      return x;
    case 1:
      return y;
    case 2:
      return x + y;
    default:
      return x - y;
  }
}

struct Cut {
  int direction = -1;
  std::int64_t lower = 0;  // the band is lower <= coordinate < lower + kBandPixels
};

// The median cut with the fewest band pixels that leaves pixels on both sides.
Cut smallest_cut(const std::vector<std::size_t>& pixels, int width) {
  Cut best;
  std::size_t best_band = std::numeric_limits<std::size_t>::max();
  std::vector<std::int64_t> c(pixels.size());
  for (int d = 0; d < 4; ++d) {
    for (std::size_t i = 0; i < pixels.size(); ++i) c[i] = coordinate(pixels[i], width, d);
    const auto median = c.begin() + static_cast<std::ptrdiff_t>(c.size() / 2);
    std::nth_element(c.begin(), median, c.end());
    const std::int64_t lower = *median;
    std::size_t below = 0, band = 0;
    for (const std::int64_t v : c) {
      below += v < lower;
      band += v >= lower && v < lower + kBandPixels;
    }
    if (below == 0 || below + band == c.size() || band >= best_band) continue;
    best_band = band;
    best = {d, lower};
  }
  return best;
}

void dissect(std::vector<std::size_t>& pixels, int width, std::size_t leaf_pixels,
             std::vector<std::size_t>& order) {
  const Cut cut = pixels.size() > leaf_pixels ? smallest_cut(pixels, width) : Cut{};
  if (cut.direction < 0) {
    order.insert(order.end(), pixels.begin(), pixels.end());
    return;
  }
  std::vector<std::size_t> below, above, band;
  for (const std::size_t p : pixels) {
    const std::int64_t v = coordinate(p, width, cut.direction);
    (v < cut.lower ? below : v >= cut.lower + kBandPixels ? above : band).push_back(p);
  }
  pixels.clear();
  pixels.shrink_to_fit();
  dissect(below, width, leaf_pixels, order);
  dissect(above, width, leaf_pixels, order);
  order.insert(order.end(), band.begin(), band.end());
}

}  // namespace

std::vector<std::size_t> nested_dissection_order(std::vector<std::size_t> pixels, int width,
                                                 std::size_t leaf_pixels) {
  std::vector<std::size_t> order;
  order.reserve(pixels.size());
  dissect(pixels, width, std::max<std::size_t>(leaf_pixels, 1), order);
  return order;
}

}  // namespace fspm::crown
