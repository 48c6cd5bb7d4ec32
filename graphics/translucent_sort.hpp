#pragma once
// Back-to-front order of blended triangles (the painter's algorithm). Blending "over" is not
// commutative: a surface of opacity a drawn over what is already in the frame gives
// a c + (1 - a) dst, so translucent surfaces must reach the frame farthest first. Triangles are
// ordered by the distance from the eye to their centroid, which is exact for triangles that do not
// overlap in depth (separate crowns, walls, nets) and an approximation for interpenetrating ones.
#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

namespace fspm::graphics {

// Centroid of each triangle of a flat soup (three positions per triangle, in order).
std::vector<Eigen::Vector3f> soup_centroids(std::span<const Eigen::Vector3f> corners);

// Indices of `centroids` from the farthest from `eye` to the nearest; equal distances keep
// their index order, so the same eye gives the same order.
std::vector<std::uint32_t> back_to_front(std::span<const Eigen::Vector3f> centroids,
                                         const Eigen::Vector3f& eye);

}  // namespace fspm::graphics
