// fspm crown: a tree crown from one photograph (Argudo 2014, chapters 4-5), written as a mesh and
// cubemaps. Needs OpenImageIO, so it lives in fspm-full.
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/crown_cubemaps_file.hpp"
#include "cli/full_command_list.hpp"
#include "cli/output.hpp"
#include "crown/auto_mask.hpp"
#include "crown/crown_from_photo.hpp"
#include "crown/crown_memory.hpp"
#include "crown/cubemap.hpp"
#include "crown/image_io.hpp"
#include "crown/preview.hpp"
#include "crown/side_view.hpp"
#include "fspm/atomic_file.hpp"
#include "fspm/error.hpp"
#include "fspm/signal_cleanup.hpp"
#include "graphics/mesh_writers.hpp"

namespace fspm::cli {
namespace {

struct CrownCommand {
  std::string photo;
  std::string mask;
  std::string out;
  // The options bound straight into the crown's options, whose defaults are the options'.
  crown::CrownOptions options;
  bool height_given = false;  // --height-m on the command line
  double image_height_m = 0.0;
  int connectivity = options.inflation.connectivity == crown::Connectivity::kFour ? 4 : 8;
  std::string side_mask;
  std::string preview;
  bool keep_gaps = false;
  std::uint64_t seed = 1;
  bool json = false;
};

// Where each output goes: OUT is a mesh file (.glb, .obj, .ply; the cubemaps beside it, named
// after its stem) or a directory (crown.glb and the rest inside).
struct OutputPaths {
  std::string mesh, color, radius, cubemaps, relief, mask, billboards;
  std::string created_dir;  // the output directory when this run created it
  int cleanup = -1;         // its handle of fspm/signal_cleanup.hpp
};

OutputPaths output_paths(const std::string& out) {
  namespace fs = std::filesystem;
  // "crown/" names the directory crown (its parent_path would be crown itself).
  const fs::path p = fs::path(out).has_filename() ? fs::path(out) : fs::path(out).parent_path();
  const std::string ext = p.extension().string();
  const bool directory = ext.empty() || fs::is_directory(p);
  const fs::path dir = directory ? p : p.parent_path();
  // Before any work: a missing parent directory is a mistake (a directory OUT itself is created).
  const fs::path must_exist = directory ? p.parent_path() : dir;
  if (!must_exist.empty() && !fs::is_directory(must_exist)) {
    throw IoError("cannot write: directory '" + must_exist.string() + "' does not exist", out);
  }
  std::error_code ec;
  const bool created = directory && fs::create_directories(p, ec);
  if (directory && !created && !fs::is_directory(p)) {
    throw IoError("cannot create the output directory: " +
                      (ec ? ec.message() : std::string("a file of that name exists")),
                  out);
  }
  const std::string stem = directory ? "crown" : p.stem().string();
  auto beside = [&](const std::string& suffix) { return (dir / (stem + suffix)).string(); };
  OutputPaths o;
  o.mesh = directory ? beside(".glb") : out;
  // .obj, .ply, .vtp or .glb (fspm/file_kind.hpp), else ValueError.
  if (graphics::mesh_format_for(o.mesh) == MeshFormat::kPvd)
    throw ValueError("a crown is one mesh, not a .pvd sequence", out);
  o.color = beside("_color_cubemap.png");
  o.radius = beside("_radius_cubemap.exr");
  o.cubemaps = crown_cubemaps_path(o.mesh);
  o.relief = beside("_relief.png");
  o.mask = beside("_mask.png");
  o.billboards = beside("_billboards.csv");
  if (created) {
    o.created_dir = p.string();
    o.cleanup = register_signal_cleanup(o.created_dir);  // removed, when empty, by a signal
  }
  return o;
}

graphics::TriangleMesh to_triangle_mesh(const crown::CrownMesh& m) {
  graphics::TriangleMesh out;
  out.positions = m.positions;
  out.normals = crown::vertex_normals(m);
  out.uvs.assign(m.positions.size(), Eigen::Vector2f::Zero());
  out.triangles = m.triangles;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    out.materials.push_back(t < m.crown_triangles ? graphics::Material::kLeaf
                                                  : graphics::Material::kBark);
  }
  auto& red = out.add_attribute("red");
  auto& green = out.add_attribute("green");
  auto& blue = out.add_attribute("blue");
  for (std::size_t v = 0; v < m.colors.size(); ++v) {
    red[v] = m.colors[v].x(), green[v] = m.colors[v].y(), blue[v] = m.colors[v].z();
  }
  return out;
}

// Relief in [0, 1] for viewing: 0.5 is the silhouette plane.
crown::Raster relief_picture(const crown::Raster& relief) {
  float largest = 1e-6f;
  for (float v : relief.values) largest = std::max(largest, std::abs(v));
  crown::Raster out = relief;
  for (float& v : out.values) v = 0.5f + 0.5f * v / largest;
  return out;
}

void write_billboards(const std::vector<Eigen::Vector3f>& points, const std::string& path) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "x_m,y_m,z_m\n";
    for (const auto& p : points) out << p.x() << ',' << p.y() << ',' << p.z() << '\n';
  });
}

crown::CrownOptions crown_options(const CrownCommand& c, const crown::Mask& mask) {
  crown::CrownOptions o = c.options;
  if (c.height_given && c.image_height_m > 0.0) {
    throw ValueError("give --height-m (the crown's height) or --image-height-m, not both");
  }
  if (c.image_height_m > 0.0) {  // the whole picture's height: scale the crown's rows by it
    int top = mask.height, bottom = -1;
    for (int y = 0; y < mask.height; ++y) {
      for (int x = 0; x < mask.width; ++x) {
        if (mask.at(x, y)) top = std::min(top, y), bottom = std::max(bottom, y);
      }
    }
    o.height_m = c.image_height_m * (bottom - top + 1) / mask.height;
  }
  o.inflation.connectivity =
      c.connectivity == 4 ? crown::Connectivity::kFour : crown::Connectivity::kEight;
  return o;
}

}  // namespace

namespace {

int lowest_row(const crown::Mask& mask) {
  for (int y = mask.height - 1; y >= 0; --y) {
    for (int x = 0; x < mask.width; ++x) {
      if (mask.at(x, y)) return y;
    }
  }
  return mask.height - 1;
}

void write_outputs(const CrownCommand& c, const OutputPaths& paths, const crown::CrownModel& model,
                   const crown::Mask& mask) {
  graphics::write_mesh(to_triangle_mesh(model.mesh), paths.mesh);
  crown::write_raster(crown::cubemap_strip(model.color), paths.color);
  crown::write_raster(crown::cubemap_strip(model.radius), paths.radius);
  write_crown_cubemaps(paths.cubemaps, model.centre, model.radius.size, paths.color, paths.radius);
  crown::write_raster(relief_picture(model.relief), paths.relief);
  if (c.options.billboards) write_billboards(model.billboards, paths.billboards);
  const double ground_row = lowest_row(mask) + c.options.trunk_height_m / model.metres_per_pixel;
  if (!c.side_mask.empty()) {
    crown::write_mask(crown::side_silhouette(model.mesh, mask.width, mask.height,
                                             model.metres_per_pixel, ground_row),
                      c.side_mask);
  }
  if (!c.preview.empty()) {  // front, side and top side by side
    const crown::PreviewView views[3] = {crown::PreviewView::kFront, crown::PreviewView::kSide,
                                         crown::PreviewView::kTop};
    crown::Raster panels(3 * mask.width, mask.height, 3);
    for (int v = 0; v < 3; ++v) {
      const crown::Raster one = crown::preview(model.mesh, views[v], mask.width, mask.height,
                                               model.metres_per_pixel, ground_row);
      for (int y = 0; y < mask.height; ++y) {
        for (int x = 0; x < mask.width; ++x) {
          for (int k = 0; k < 3; ++k) panels.at(v * mask.width + x, y, k) = one.at(x, y, k);
        }
      }
    }
    crown::write_raster(panels, c.preview);
  }
}

void make_crown(const CrownCommand& c, const OutputPaths& paths);

// Every output or none (OutputTransaction): a failure on the way (a full disk, a photograph too
// large, a report that cannot be printed) leaves no file, and no output directory this run
// created.
void run_crown(const CrownCommand& c) {
  refuse_overwriting_input(c.out, {c.photo, c.mask});
  refuse_overwriting_input(c.side_mask, {c.photo, c.mask});
  refuse_overwriting_input(c.preview, {c.photo, c.mask});
  if (!c.side_mask.empty()) crown::check_image_output(c.side_mask);
  if (!c.preview.empty()) crown::check_image_output(c.preview);
  const OutputPaths paths = output_paths(c.out);
  try {
    make_crown(c, paths);
  } catch (...) {
    std::error_code ec;
    if (!paths.created_dir.empty()) std::filesystem::remove(paths.created_dir, ec);  // if empty
    unregister_signal_cleanup(paths.cleanup);
    throw;
  }
  unregister_signal_cleanup(paths.cleanup);
}

void make_crown(const CrownCommand& c, const OutputPaths& paths) {
  OutputTransaction outputs;
  auto t0 = std::chrono::steady_clock::now();
  nlohmann::json seconds = nlohmann::json::object();
  // The whole reconstruction's memory from the photograph's header, before a pixel is decoded.
  crown::CrownMemoryRequest need;
  need.cubemap_size = c.options.cubemap_size;
  need.working_pixels = c.options.working_pixels;
  need.preview = !c.preview.empty();
  need.side_mask = !c.side_mask.empty();
  crown::check_crown_memory(c.photo, need, c.mask);
  const crown::Raster photo = crown::read_rgb(c.photo);
  crown::Mask mask;
  if (c.mask.empty()) {
    mask = crown::auto_mask(photo, {}, c.photo);
    crown::write_mask(mask, paths.mask);
  } else {
    mask = crown::read_mask(c.mask);
  }
  // Sky seen through the foliage is no crown texture (crown/gap_fill.hpp): the gaps are filled
  // at the working resolution.
  crown::Mask foliage;
  if (!c.keep_gaps) foliage = crown::foreground(photo, crown::AutoMaskOptions{}.threshold);
  seconds["mask"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::mt19937_64 rng(c.seed);
  const crown::CrownModel model = crown::reconstruct_crown(photo, mask, crown_options(c, mask), rng,
                                                           c.keep_gaps ? nullptr : &foliage);
  for (const auto& [stage, s] : model.seconds) seconds[stage] = s;
  t0 = std::chrono::steady_clock::now();
  write_outputs(c, paths, model, mask);
  seconds["writing"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  nlohmann::json files = {{"mesh", paths.mesh},
                          {"color_cubemap", paths.color},
                          {"radius_cubemap", paths.radius},
                          {"cubemaps", paths.cubemaps},
                          {"relief", paths.relief}};
  if (c.mask.empty()) files["mask"] = paths.mask;
  if (c.options.billboards) files["billboards"] = paths.billboards;
  if (!c.side_mask.empty()) files["side_mask"] = c.side_mask;
  if (!c.preview.empty()) files["preview"] = c.preview;
  if (c.json) {
    print_json({{"photo", c.photo},
                {"crown_pixels", model.crown_pixels},
                {"silhouette_pixels", model.silhouette_pixels},
                {"metres_per_pixel", model.metres_per_pixel},
                {"working_factor", model.working_factor},
                {"vertices", model.mesh.vertex_count()},
                {"triangles", model.mesh.triangle_count()},
                {"volume_m3", model.volume_m3},
                {"cubemap_size", model.color.size},
                {"billboards", model.billboards.size()},
                {"files", files},
                {"seconds", seconds}});
  } else if (verbosity() > 0) {
    std::cerr << "wrote " << paths.mesh << " (" << model.mesh.vertex_count() << " vertices, "
              << model.mesh.triangle_count() << " triangles, crown " << model.volume_m3
              << " m3) and its cubemaps\n";
  }
  // The files go into place once the report is out: a report that cannot be written leaves none.
  finish_standard_output();
  outputs.commit();
}

}  // namespace

void add_crown_commands(CLI::App& app) {
  auto cmd = std::make_shared<CrownCommand>();
  CLI::App* c = app.add_subcommand(kCrownCommand.name, kCrownCommand.description);
  c->add_option("PHOTO", cmd->photo, "Photograph of one tree (any format OpenImageIO reads)")
      ->required();
  c->add_option("--mask", cmd->mask,
                "Crown mask, same size, white crown on black (default: found against the sky "
                "and ground beside the tree, written as OUT's _mask.png to check)");
  c->add_option("-o,--output", cmd->out, "Mesh (.glb, .obj, .ply, .vtp) or a directory")
      ->required();
  CLI::Option* height =
      c->add_option("--height-m", cmd->options.height_m, "Height of the crown in metres")
          ->check(positive_number(1e4))
          ->capture_default_str();
  c->add_option("--image-height-m", cmd->image_height_m,
                "Height the whole picture spans in metres (a picture at a known scale)")
      ->check(positive_number(1e5));
  c->add_option("--depth-ratio", cmd->options.depth_ratio, "Crown depth over width")
      ->check(positive_number(10.0))
      ->capture_default_str();
  c->add_option("--relief", cmd->options.relief_weight,
                "Relief weight rho (Argudo 4.6), 0 for none")
      ->check(number_in(0.0, 1.0))
      ->capture_default_str();
  c->add_option("--k", cmd->options.inflation.k,
                "Depth of the outer silhouette in the inflation, pixels")
      ->check(positive_number(100.0))
      ->capture_default_str();
  c->add_option("--connectivity", cmd->connectivity, "Silhouette connectivity, 8 or 4")
      ->check(CLI::IsMember({4, 8}))
      ->capture_default_str();
  c->add_option("--cubemap-size", cmd->options.cubemap_size,
                "Cubemap face side (default: from the crown)")
      ->check(CLI::Range(8, 2048));
  c->add_option("--trunk-m", cmd->options.trunk_height_m,
                "Trunk height below the crown in metres (default none)")
      ->check(number_in(0.0, 1e4));
  c->add_option("--trunk-radius-m", cmd->options.trunk_radius_m,
                "Trunk radius in metres (default 2 % of the crown height)")
      ->check(positive_number(1e3));
  c->add_flag("--billboards", cmd->options.billboards,
              "Also write about 300 blue-noise billboard centres inside the crown (Argudo 5.2)");
  c->add_option("--side-mask", cmd->side_mask,
                "Also write the crown seen from the side (+x) as a mask at the photograph's scale");
  c->add_option(
      "--preview", cmd->preview,
      "Also write a picture of the crown from the front, from the side (+x) and from above");
  c->add_flag("--keep-gaps", cmd->keep_gaps,
              "Keep sky seen through the foliage as crown texture (default: filled from the "
              "foliage around it)");
  c->add_option("--seed", cmd->seed, "Seed of the texture synthesis")
      ->check(number_in(0, kMaxSeed))
      ->capture_default_str();
  c->add_flag("--json", cmd->json, "Machine-readable JSON on stdout");
  c->callback([cmd, height] {
    cmd->height_given = height->count() > 0;
    run_crown(*cmd);
  });
}

}  // namespace fspm::cli
