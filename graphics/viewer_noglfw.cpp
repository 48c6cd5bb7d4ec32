#include "fspm/error.hpp"
#include "graphics/viewer.hpp"

namespace fspm::graphics {

bool viewer_available() { return false; }

bool viewer_panel_available() { return false; }

ViewerStats run_viewer(const std::vector<TriangleMesh>&, const std::vector<double>&,
                       const ViewerOptions&, const std::vector<TriangleMesh>&) {
  throw ValueError("fspm was built without the viewer (FSPM_WITH_VIEWER=OFF)");
}

ViewerStats run_instanced_viewer(const std::vector<InstancedMesh>&, const std::vector<double>&,
                                 const ViewerOptions&, const std::vector<InstancedMesh>&) {
  throw ValueError("fspm was built without the viewer (FSPM_WITH_VIEWER=OFF)");
}

ViewerStats run_lod_viewer(const LodScene&, const LodOptions&, const ViewerOptions&) {
  throw ValueError("fspm was built without the viewer (FSPM_WITH_VIEWER=OFF)");
}

}  // namespace fspm::graphics
