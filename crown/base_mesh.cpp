#include "crown/base_mesh.hpp"

namespace fspm::crown {

std::vector<std::array<std::uint32_t, 3>> grid_triangles(const InflatedSheet& sheet) {
  std::vector<std::array<std::uint32_t, 3>> out;
  auto v = [&](int x, int y) {
    return sheet.vertex[static_cast<std::size_t>(y) * sheet.width + x];
  };
  for (int y = 0; y + 1 < sheet.height; ++y) {
    for (int x = 0; x + 1 < sheet.width; ++x) {
      // Corners counter-clockwise in (column, row, toward viewer) coordinates: normal +z.
      const int a = v(x, y), b = v(x, y + 1), c = v(x + 1, y + 1), d = v(x + 1, y);
      const int present = (a >= 0) + (b >= 0) + (c >= 0) + (d >= 0);
      auto tri = [&](int p, int q, int r) {
        out.push_back({static_cast<std::uint32_t>(p), static_cast<std::uint32_t>(q),
                       static_cast<std::uint32_t>(r)});
      };
      if (present == 4) {
        tri(a, d, b);
        tri(d, c, b);
      } else if (present == 3) {
        if (a < 0) tri(d, c, b);
        if (b < 0) tri(a, d, c);
        if (c < 0) tri(a, d, b);
        if (d < 0) tri(a, c, b);
      }
    }
  }
  return out;
}

BaseMesh mirrored_mesh(const InflatedSheet& sheet) {
  BaseMesh base;
  CrownMesh& mesh = base.mesh;
  const std::size_t n = sheet.positions.size();
  std::vector<std::uint32_t> back_of(n);
  for (std::size_t i = 0; i < n; ++i) {
    mesh.positions.push_back(sheet.positions[i].cast<float>());
    base.front_of_vertex.push_back(static_cast<int>(i));
    base.is_back.push_back(false);
  }
  for (std::size_t p = 0; p < sheet.classes.size(); ++p) {
    const int i = sheet.vertex[p];
    if (i < 0) continue;
    if (sheet.classes[p] == PixelClass::kSilhouette) {
      back_of[static_cast<std::size_t>(i)] = static_cast<std::uint32_t>(i);
      continue;
    }
    back_of[static_cast<std::size_t>(i)] = static_cast<std::uint32_t>(mesh.positions.size());
    Eigen::Vector3f mirrored = sheet.positions[static_cast<std::size_t>(i)].cast<float>();
    mirrored.z() = -mirrored.z();
    mesh.positions.push_back(mirrored);
    base.front_of_vertex.push_back(i);
    base.is_back.push_back(true);
  }
  const auto front = grid_triangles(sheet);
  mesh.triangles = front;
  for (const auto& t : front)
    mesh.triangles.push_back({back_of[t[0]], back_of[t[2]], back_of[t[1]]});
  mesh.crown_triangles = mesh.triangles.size();
  mesh.colors.assign(mesh.positions.size(), Eigen::Vector3f(0.2f, 0.4f, 0.15f));
  return base;
}

}  // namespace fspm::crown
