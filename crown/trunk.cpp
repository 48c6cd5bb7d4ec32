#include "crown/trunk.hpp"

#include <cmath>

namespace fspm::crown {

void append_trunk(CrownMesh& mesh, const Eigen::Vector2f& xy, double top_m, double radius_m) {
  if (!(top_m > 0.0) || !(radius_m > 0.0)) return;
  constexpr int kSides = 12;
  const Eigen::Vector3f bark(0.36f, 0.25f, 0.15f);
  const auto base = static_cast<std::uint32_t>(mesh.positions.size());
  for (int i = 0; i < kSides; ++i) {
    const double a = 2.0 * M_PI * i / kSides;
    const float x = xy.x() + static_cast<float>(radius_m * std::cos(a));
    const float y = xy.y() + static_cast<float>(radius_m * std::sin(a));
    mesh.positions.emplace_back(x, y, 0.0f);
    mesh.positions.emplace_back(x, y, static_cast<float>(top_m));
    mesh.colors.push_back(bark);
    mesh.colors.push_back(bark);
  }
  for (std::uint32_t i = 0; i < kSides; ++i) {
    const std::uint32_t j = (i + 1) % kSides;
    const std::uint32_t b0 = base + 2 * i, t0 = b0 + 1, b1 = base + 2 * j, t1 = b1 + 1;
    mesh.triangles.push_back({b0, b1, t1});  // outward: counter-clockwise seen from outside
    mesh.triangles.push_back({b0, t1, t0});
  }
}

}  // namespace fspm::crown
