#pragma once
// Reading a .vtp back through VTK's own vtkXMLPolyDataReader, so exports are checked by the
// reader ParaView uses rather than by our writer's twin. Only available when built with VTK.
#include <map>
#include <string>
#include <vector>

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

}  // namespace fspm::graphics
