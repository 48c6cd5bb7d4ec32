#pragma once
// The description `fspm crown` writes beside a crown's mesh, STEM_cubemaps.json, so that the
// crown can be drawn by relief-mapped ray casting of its cubemaps (Argudo 5.1; fspm view
// --ray-cast):
//   {"fspm_crown_cubemaps": 1, "centre_m": [x, y, z], "cubemap_size": N,
//    "color_cubemap": "STEM_color_cubemap.png", "radius_cubemap": "STEM_radius_cubemap.exr"}
// The centre is in the mesh's frame (metres); the cubemap names are relative to the file.
#include <Eigen/Core>
#include <string>

#include "graphics/relief_crown.hpp"

namespace fspm::cli {

// STEM_cubemaps.json beside the mesh `mesh_path` (.glb, .obj, ...).
std::string crown_cubemaps_path(const std::string& mesh_path);

// Writes the description atomically; the cubemap paths are stored relative to its directory.
void write_crown_cubemaps(const std::string& path, const Eigen::Vector3f& centre_m, int size,
                          const std::string& color_path, const std::string& radius_path);

// The crown of the mesh `mesh_path` as a relief crown, placed where the mesh is (identity): its
// description, then both cubemaps, and billboard centres for close views (Argudo 5.2, from the
// radius cubemap with a fixed seed). Throws IoError naming a missing file ("draw it with fspm crown
// first"), ParseError or ValueError naming the description or a cubemap of the wrong size.
graphics::ReliefCrown read_relief_crown(const std::string& mesh_path);

}  // namespace fspm::cli
