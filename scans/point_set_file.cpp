#include "scans/point_set_file.hpp"

#include <filesystem>

#include "fspm/error.hpp"
#include "fspm/file_kind.hpp"
#include "scans/gltf_reader.hpp"
#include "scans/las_reader.hpp"
#include "scans/mesh_file.hpp"
#include "scans/obj_reader.hpp"
#include "scans/pcd_reader.hpp"
#include "scans/ply_reader.hpp"
#include "scans/xyz_reader.hpp"

namespace fspm::scans {

namespace {

PointSet read_any_point_set(const std::string& path, FileKind kind, const std::string& ext) {
  if (kind == FileKind::kPly) return read_ply_points(path);
  if (kind == FileKind::kXyz) return read_xyz_points(path);
  if (kind == FileKind::kPcd) return read_pcd_points(path);
  if (kind == FileKind::kLas) return read_las_points(path);
  // The vertices of a mesh, faces or not.
  if (kind == FileKind::kObj) return PointSet{read_obj_mesh(path).vertices};
  if (kind == FileKind::kGltf || kind == FileKind::kGlb) {
    return PointSet{read_gltf_mesh(path).vertices};
  }
  throw ValueError("unknown point-set extension '" + ext +
                       "', expected .ply, .xyz, .txt, .csv, .pcd, .las, .obj, .gltf or .glb",
                   path);
}

}  // namespace

PointSet read_point_set(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  PointSet points = read_any_point_set(path, file_kind(path), ext);
  if (points.points.empty()) {
    throw ParseError("no point in the file (empty, a header only, or no line read as a point)",
                     path);
  }
  return points;
}

}  // namespace fspm::scans
