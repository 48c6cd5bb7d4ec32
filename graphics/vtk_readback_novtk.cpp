#include "fspm/error.hpp"
#include "graphics/vtk_readback.hpp"

namespace fspm::graphics {

bool vtk_available() { return false; }

PolyDataInfo read_vtp_with_vtk(const std::string& path) {
  throw ValueError("fspm was built without VTK (FSPM_WITH_VTK=OFF)", path);
}

TriangleMesh read_vtp_mesh(const std::string& path) {
  throw ValueError("fspm was built without VTK (FSPM_WITH_VTK=OFF): cannot read .vtp", path);
}

}  // namespace fspm::graphics
