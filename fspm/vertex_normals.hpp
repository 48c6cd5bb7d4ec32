#pragma once
// Vertex normals of a triangle mesh from its faces, for meshes whose file or builder gives none.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace fspm {

// Area-weighted vertex normals: each vertex gets the normalized sum of the cross products
// (b - a) x (c - a) of its triangles, whose length is twice the triangle's area, so a large face
// counts more than a sliver. Triangles are
// counter-clockwise seen from outside. A vertex that no triangle with an area touches gets +z.
// Every index of `triangles` must be below positions.size().
std::vector<Eigen::Vector3f> area_weighted_vertex_normals(
    std::span<const Eigen::Vector3f> positions,
    std::span<const std::array<std::uint32_t, 3>> triangles);

}  // namespace fspm
