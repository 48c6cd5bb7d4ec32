#pragma once
// The per-run files of `fspm run` that need graphics ([outputs] keep = ["mesh", "image"]) and the
// tree renders of `fspm report`: the experiments library stays free of graphics, the command line
// installs these writers (experiments/run_files.hpp).
#include <string>

#include "experiments/experiment.hpp"
#include "experiments/run_files.hpp"
#include "fspm/tree_graph.hpp"
#include "graphics/tree_mesher.hpp"
#include "graphics/triangle_mesh.hpp"

namespace fspm::cli {

// Writers for every kind of `keep` that graphics provides: "mesh" (outputs.mesh_format) always,
// "image" (.png, outputs.image_size and image_view) when fspm was built with VTK. Images need an X
// display when they are written.
experiments::RunFileWriters graphics_run_file_writers(const experiments::Experiment& experiment);

// How kept meshes, images and report renders mesh a tree: bark and leaves.
graphics::MeshOptions run_mesh_options();

// The tree meshed as kept meshes, images and report renders show it: bark and leaves.
graphics::TriangleMesh run_tree_mesh(const TreeGraph& tree);

// The tree meshed (bark and leaves) and rendered offscreen with the experiment's image size and
// view, ground included, into a PNG at `png_path` (atomically). Renders are serialized: one VTK
// window at a time, whichever thread asks. Throws ValueError without VTK, IoError without an X
// display.
void render_tree_png(const TreeGraph& tree, const experiments::Experiment& experiment,
                     const std::string& png_path);

}  // namespace fspm::cli
