#include "graphics/foliage.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <string>

#include "fspm/error.hpp"
#include "fspm/name_table.hpp"

namespace fspm::graphics {
namespace {

// Farthest point of a leaf quad from its base, as a fraction of the cluster radius.
double leaf_reach_ratio(const FoliageOptions& o) {
  const double half_width = 0.5 * o.leaf_width_ratio;
  return o.leaf_length_ratio * std::sqrt(1.0 + half_width * half_width);
}

Eigen::Vector3d random_direction(std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  for (;;) {
    const Eigen::Vector3d d(normal(rng), normal(rng), normal(rng));
    const double n = d.norm();
    if (n > 1e-12) return d / n;
  }
}

void write_leaf_cloud(const Eigen::Vector3d& center, double radius_m, const FoliageOptions& o,
                      std::mt19937_64& rng, TriangleMesh& mesh, std::uint32_t& v, std::size_t& t) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double length = o.leaf_length_ratio * radius_m;
  const double half_width = 0.5 * o.leaf_width_ratio * length;
  // Bases uniform in the ball the whole quad stays inside: radius R cbrt(u).
  const double base_ball = radius_m * (1.0 - leaf_reach_ratio(o));
  for (int k = 0; k < o.leaves_per_cluster; ++k) {
    const Eigen::Vector3d base = center + base_ball * std::cbrt(unit(rng)) * random_direction(rng);
    const Eigen::Vector3d dir = random_direction(rng);
    Eigen::Vector3d side = dir.cross(random_direction(rng));
    if (side.norm() < 1e-9) side = dir.cross(Eigen::Vector3d::UnitX());
    if (side.norm() < 1e-9) side = dir.cross(Eigen::Vector3d::UnitY());
    side.normalize();
    // The normal of the counter-clockwise quad below (as the mesher's leaves): renderers light
    // the side the normal points to and flip it for the other, so a normal against the winding
    // leaves every leaf unlit.
    const Eigen::Vector3f normal = side.cross(dir).normalized().cast<float>();
    const Eigen::Vector3d corners[4] = {base - half_width * side, base + half_width * side,
                                        base + length * dir - half_width * side,
                                        base + length * dir + half_width * side};
    for (int c = 0; c < 4; ++c) {
      mesh.positions[v + c] = corners[c].cast<float>();
      mesh.normals[v + c] = normal;
      mesh.uvs[v + c] = {static_cast<float>(c % 2), static_cast<float>(c / 2)};
    }
    mesh.triangles[t] = {v, v + 1, v + 3};
    mesh.triangles[t + 1] = {v, v + 3, v + 2};
    mesh.materials[t] = mesh.materials[t + 1] = Material::kLeaf;
    v += 4;
    t += 2;
  }
}

// Latitude-longitude sphere: rows from the north pole (theta = 0) down, triangles
// counter-clockwise seen from outside (theta-hat x phi-hat = r-hat).
void write_volume(const Eigen::Vector3d& center, double radius_m, const FoliageOptions& o,
                  TriangleMesh& mesh, std::uint32_t& v, std::size_t& t) {
  const int stacks = o.sphere_stacks, slices = o.sphere_slices;
  const std::uint32_t first = v;
  for (int i = 0; i <= stacks; ++i) {
    const double theta = std::numbers::pi * i / stacks;
    for (int j = 0; j <= slices; ++j) {
      const double phi = 2.0 * std::numbers::pi * (j == slices ? 0 : j) / slices;
      const Eigen::Vector3d n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                              std::cos(theta));
      mesh.positions[v] = (center + radius_m * n).cast<float>();
      mesh.normals[v] = n.cast<float>();
      mesh.uvs[v] = {static_cast<float>(j) / slices, static_cast<float>(i) / stacks};
      ++v;
    }
  }
  const auto row = static_cast<std::uint32_t>(slices + 1);
  for (int i = 0; i < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      const std::uint32_t a = first + i * row + j, b = a + 1, c = a + row, d = c + 1;
      if (i != 0) {
        mesh.triangles[t] = {a, c, b};
        mesh.materials[t++] = Material::kCrown;
      }
      if (i != stacks - 1) {
        mesh.triangles[t] = {b, c, d};
        mesh.materials[t++] = Material::kCrown;
      }
    }
  }
}

}  // namespace

FoliageMode foliage_mode_from_name(std::string_view name) {
  return kFoliageModeNames.from_name(name);
}

void FoliageOptions::validate() const {
  if (leaves_per_cluster < 1) throw ValueError("foliage: leaves_per_cluster must be >= 1");
  if (!(leaf_length_ratio > 0.0) || !(leaf_width_ratio > 0.0)) {
    throw ValueError("foliage: leaf_length_ratio and leaf_width_ratio must be > 0");
  }
  if (leaf_reach_ratio(*this) > 1.0) {
    throw ValueError(
        "foliage: leaf_length_ratio too large: leaves longer than their cluster's radius do "
        "not fit inside it");
  }
  if (sphere_slices < 3 || sphere_stacks < 2) {
    throw ValueError("foliage: sphere_slices must be >= 3 and sphere_stacks >= 2");
  }
}

FoliageCounts cluster_counts(const FoliageOptions& o) {
  if (o.mode == FoliageMode::kLeaves) {
    const auto n = static_cast<std::size_t>(o.leaves_per_cluster);
    return {4 * n, 2 * n};
  }
  const auto stacks = static_cast<std::size_t>(o.sphere_stacks);
  const auto slices = static_cast<std::size_t>(o.sphere_slices);
  return {(stacks + 1) * (slices + 1), 2 * slices * (stacks - 1)};
}

void write_cluster(const Eigen::Vector3d& center, double radius_m, const FoliageOptions& options,
                   std::mt19937_64& rng, TriangleMesh& mesh, std::uint32_t& v, std::size_t& t) {
  if (options.mode == FoliageMode::kLeaves) {
    write_leaf_cloud(center, radius_m, options, rng, mesh, v, t);
  } else {
    write_volume(center, radius_m, options, mesh, v, t);
  }
}

}  // namespace fspm::graphics
