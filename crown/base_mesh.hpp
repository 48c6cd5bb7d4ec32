#pragma once
// The closed base crown (Argudo 4.3.2, Fig. 4.11): the inflated front sheet and its mirror image
// behind the silhouette plane, sharing the silhouette vertices, triangulated on the pixel grid.
#include "crown/crown_mesh.hpp"
#include "crown/inflation.hpp"

namespace fspm::crown {

// Pixel-grid triangles of the crown: two per 2x2 block of crown pixels, one per block with three
// (so every open edge joins two silhouette pixels). Indices are sheet vertex indices.
std::vector<std::array<std::uint32_t, 3>> grid_triangles(const InflatedSheet& sheet);

struct BaseMesh {
  CrownMesh mesh;  // pixel units: x = column, y = row, z = depth (front > 0 > back)
  std::vector<int> front_of_vertex;  // sheet vertex index of each mesh vertex
  std::vector<bool> is_back;         // true for back-sheet copies of inner vertices
};

// Front sheet as inflated, back sheet with z mirrored; inner vertices are duplicated, silhouette
// vertices shared. Triangles are oriented outward.
BaseMesh mirrored_mesh(const InflatedSheet& sheet);

}  // namespace fspm::crown
