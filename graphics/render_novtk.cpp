#include "fspm/error.hpp"
#include "graphics/image.hpp"
#include "graphics/render.hpp"

namespace fspm::graphics {

bool render_available() { return false; }
bool display_available() { return false; }

Image render_mesh(const TriangleMesh& mesh, const RenderOptions& options) {
  if (!options.color_by.empty()) (void)mesh.attribute(options.color_by);
  throw ValueError("fspm was built without VTK (FSPM_WITH_VTK=OFF): rendering is not available");
}

Image render_scene(const InstancedMesh& scene, const RenderOptions& options) {
  if (!options.color_by.empty()) {
    for (const auto& m : scene.meshes) (void)m.attribute(options.color_by);
  }
  throw ValueError("fspm was built without VTK (FSPM_WITH_VTK=OFF): rendering is not available");
}

Image render_lod_scene(const LodScene&, const LodOptions&, const RenderOptions&, std::size_t*) {
  throw ValueError("fspm was built without VTK (FSPM_WITH_VTK=OFF): rendering is not available");
}

void write_image(const Image&, const std::string& path) {
  throw ValueError("fspm was built without OpenImageIO (FSPM_WITH_VTK=OFF)", path);
}

void check_image_path(const std::string& path) {
  throw ValueError("fspm was built without OpenImageIO (FSPM_WITH_VTK=OFF)", path);
}

Image read_image(const std::string& path) {
  throw ValueError("fspm was built without OpenImageIO (FSPM_WITH_VTK=OFF)", path);
}

}  // namespace fspm::graphics
