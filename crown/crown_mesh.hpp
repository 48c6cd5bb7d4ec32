#pragma once
// CrownMesh: the reconstructed crown (and optional trunk) as an indexed triangle mesh with a colour
// per vertex, in metres, z up. A core-level type so this module needs no graphics library; the
// command line converts it to the project's mesh writers.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace fspm::crown {

struct CrownMesh {
  std::vector<Eigen::Vector3f> positions;
  std::vector<Eigen::Vector3f> colors;                  // linear RGB in [0, 1], one per vertex
  std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise seen from outside
  // Triangles [0, crown_triangles) are the crown, the rest the trunk.
  std::size_t crown_triangles = 0;

  std::size_t vertex_count() const { return positions.size(); }
  std::size_t triangle_count() const { return triangles.size(); }
};

// Enclosed volume of triangles [first, last) by the divergence theorem (signed: positive for a
// closed surface oriented outward).
double enclosed_volume(const CrownMesh& mesh, std::size_t first, std::size_t last);

// Area-weighted unit vertex normals.
std::vector<Eigen::Vector3f> vertex_normals(const CrownMesh& mesh);

// Reverses every triangle in [first, last).
void flip_triangles(CrownMesh& mesh, std::size_t first, std::size_t last);

}  // namespace fspm::crown
