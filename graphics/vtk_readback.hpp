#pragma once
// Reading a .vtp back through VTK's own vtkXMLPolyDataReader, so exports are checked by the
// reader ParaView uses rather than by our writer's twin. Only available when built with VTK.
#include <map>
#include <string>
#include <vector>

#include "graphics/triangle_mesh.hpp"

namespace fspm::graphics {

struct PolyDataInfo {
  std::size_t points = 0;
  std::size_t polys = 0;
  std::size_t triangles = 0;                             // polys with exactly three points
  std::vector<float> points_xyz;                         // 3 per point
  std::map<std::string, std::vector<float>> point_data;  // first component of each array
  std::map<std::string, int> point_components;
  std::map<std::string, std::vector<float>> cell_data;
};

// True when fspm was built with VTK (FSPM_WITH_VTK).
bool vtk_available();

// Throws IoError when VTK cannot read the file, ValueError when built without VTK.
PolyDataInfo read_vtp_with_vtk(const std::string& path);

// A .vtp back as a TriangleMesh for the viewer: points, the Normals and TCoords arrays (normals
// recomputed per polygon when absent), the "material" cell array, and every other one-component
// point array as a vertex attribute; polygons of more than three points are fanned. Throws
// IoError when VTK cannot read it, ValueError when built without VTK.
TriangleMesh read_vtp_mesh(const std::string& path);

// A ParaView .pvd collection: its data sets (paths resolved against the .pvd's directory) with
// their time steps, sorted by time. Throws IoError when unreadable, ParseError when malformed.
struct PvdStep {
  double time = 0.0;
  std::string path;
};
std::vector<PvdStep> read_pvd_file(const std::string& path);

}  // namespace fspm::graphics
