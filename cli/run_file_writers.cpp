#include "cli/run_file_writers.hpp"

#include <filesystem>
#include <mutex>

#include "graphics/image.hpp"
#include "graphics/mesh_writers.hpp"
#include "graphics/render.hpp"
#include "graphics/tree_mesher.hpp"

namespace fspm::cli {
namespace {

namespace fs = std::filesystem;

}  // namespace

graphics::MeshOptions run_mesh_options() {
  graphics::MeshOptions options;
  options.leaves = true;
  return options;
}

graphics::TriangleMesh run_tree_mesh(const TreeGraph& tree) {
  return graphics::mesh_tree(tree, run_mesh_options());
}

void render_tree_png(const TreeGraph& tree, const experiments::Experiment& experiment,
                     const std::string& png_path) {
  const graphics::TriangleMesh mesh = graphics::mesh_tree(tree, run_mesh_options());
  graphics::RenderOptions options;
  options.width = experiment.image_width;
  options.height = experiment.image_height;
  options.view = experiment.image_view;
  // VTK's render windows and X connections are not meant to be driven from several threads at
  // once; meshing and writing run in parallel, the rendering itself one at a time.
  static std::mutex render_mutex;
  graphics::Image image;
  {
    const std::lock_guard lock(render_mutex);
    image = graphics::render_mesh(mesh, options);
  }
  graphics::write_image(image, png_path);
}

experiments::RunFileWriters graphics_run_file_writers(const experiments::Experiment& experiment) {
  experiments::RunFileWriters writers;
  const std::string extension(mesh_format_name(experiment.mesh_format));
  writers[experiments::KeptFile::kMesh] = [extension](const TreeGraph& tree, std::size_t run,
                                                      const std::string& out_dir) {
    const std::string rel = experiments::run_file_path(run, extension);
    // By extension: .glb, .ply or .vtp, each written atomically.
    graphics::write_mesh(graphics::mesh_tree(tree, run_mesh_options()),
                         (fs::path(out_dir) / rel).string());
    return rel;
  };
  if (graphics::render_available()) {
    // The runner keeps the experiment alive for the whole sweep.
    writers[experiments::KeptFile::kImage] = [&experiment](const TreeGraph& tree, std::size_t run,
                                                           const std::string& out_dir) {
      const std::string rel = experiments::run_file_path(run, "png");
      render_tree_png(tree, experiment, (fs::path(out_dir) / rel).string());
      return rel;
    };
  }
  return writers;
}

}  // namespace fspm::cli
