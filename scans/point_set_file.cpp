#include "scans/point_set_file.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "fspm/error.hpp"
#include "scans/las_reader.hpp"
#include "scans/mesh_file.hpp"
#include "scans/pcd_reader.hpp"
#include "scans/ply_reader.hpp"
#include "scans/xyz_reader.hpp"

namespace fspm::scans {

PointSet read_point_set(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".ply") return read_ply_points(path);
  if (ext == ".xyz" || ext == ".txt" || ext == ".csv") return read_xyz_points(path);
  if (ext == ".pcd") return read_pcd_points(path);
  if (ext == ".las" || ext == ".laz") return read_las_points(path);
  if (is_grouped_mesh_file(path)) return PointSet{read_mesh_file(path).vertices};
  throw ValueError("unknown point-set extension '" + ext +
                       "', expected .ply, .xyz, .txt, .csv, .pcd, .las, .obj, .gltf or .glb",
                   path);
}

}  // namespace fspm::scans
