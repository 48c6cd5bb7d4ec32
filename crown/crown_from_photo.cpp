#include "crown/crown_from_photo.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "crown/base_mesh.hpp"
#include "crown/billboard_cloud.hpp"
#include "crown/color_cubemap.hpp"
#include "crown/gap_fill.hpp"
#include "crown/radius_cubemap.hpp"
#include "crown/trunk.hpp"
#include "fspm/error.hpp"

namespace fspm::crown {

void CrownOptions::validate() const {
  if (!(height_m > 0.0) || !std::isfinite(height_m)) {
    throw ValueError("crown: height_m must be > 0");
  }
  if (!(depth_ratio > 0.0) || !std::isfinite(depth_ratio)) {
    throw ValueError("crown: depth_ratio must be > 0");
  }
  if (!(relief_weight >= 0.0 && relief_weight < 2.0)) {
    throw ValueError("crown: relief_weight must be in [0, 2)");
  }
  if (cubemap_size < 0 || cubemap_size > 2048) {
    throw ValueError("crown: cubemap_size must be 0..2048");
  }
  if (working_pixels < 16) throw ValueError("crown: working_pixels must be >= 16");
  if (trunk_height_m < 0.0 || trunk_radius_m < 0.0) {
    throw ValueError("crown: trunk_height_m and trunk_radius_m must be >= 0");
  }
  inflation.validate();
  relief.validate();
}
namespace {

// Pixel to metre frame: x right from the crown's centroid column, z up from the ground.
struct Frame {
  double metres_per_px = 0.0;
  double centre_x_px = 0.0;
  double bottom_px = 0.0;  // the lower edge of the crown's lowest row
  double half_width_px = 0.0;
  double depth_scale = 0.0;   // inflated z to pixels of depth
  double depth_max_px = 0.0;  // the deepest point of the base mesh, pixels
  double base_z_m = 0.0;      // trunk height
  Eigen::Vector3f centre_m = Eigen::Vector3f::Zero();
};

void check(const Raster& photo, const Mask& mask, const CrownOptions& o) {
  if (photo.width != mask.width || photo.height != mask.height) {
    throw ValueError("the photograph is " + std::to_string(photo.width) + "x" +
                     std::to_string(photo.height) + " but the mask " + std::to_string(mask.width) +
                     "x" + std::to_string(mask.height) + ": they must be the same size");
  }
  o.validate();
}

// The crown's extent is the base mesh's: its silhouette vertices lie on the mask's border, so the
// crown spans `height_m` from its lowest to its highest point, as the mask's pixels do.
Frame make_frame(const Mask& mask, const InflatedSheet& sheet, const CrownOptions& o) {
  double sum_x = 0.0, sum_y = 0.0, n = 0.0;
  for (int y = 0; y < mask.height; ++y) {
    for (int x = 0; x < mask.width; ++x) {
      if (mask.at(x, y)) sum_x += x, sum_y += y, n += 1.0;
    }
  }
  Eigen::Vector3d lo = sheet.positions.front(), hi = lo;
  for (const auto& p : sheet.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  Frame f;
  f.metres_per_px = o.height_m / std::max(1.0, hi.y() - lo.y());
  f.centre_x_px = sum_x / n;
  f.bottom_px = hi.y();
  f.half_width_px = std::max(0.5, 0.5 * (hi.x() - lo.x()));
  const double z_max = hi.z();
  f.depth_scale = z_max > 0.0 ? o.depth_ratio * f.half_width_px / z_max : 0.0;
  f.depth_max_px = z_max * f.depth_scale;
  f.base_z_m = o.trunk_height_m;
  f.centre_m = {0.0f, 0.0f,
                static_cast<float>(f.base_z_m + (f.bottom_px - sum_y / n) * f.metres_per_px)};
  return f;
}

// Base mesh in metres with the relief: the photograph's on the front half (0 on the silhouette),
// the height cubemap's on the back half (faded to 0 toward the silhouette).
void compose(BaseMesh& base, const InflatedSheet& sheet, const Frame& f, const Raster& photo,
             const Raster& relief, const Cubemap& color, const Cubemap& height, double rho) {
  // Each vertex takes the photograph's colour and relief at its own pixel: silhouette vertices lie
  // half a pixel out from their centres, where rounding would reach the sky beside the crown.
  std::vector<std::size_t> pixel_of(sheet.positions.size(), 0);
  for (std::size_t p = 0; p < sheet.vertex.size(); ++p) {
    if (sheet.vertex[p] >= 0) pixel_of[static_cast<std::size_t>(sheet.vertex[p])] = p;
  }
  float relief_max = 1e-6f;
  for (float v : relief.values) relief_max = std::max(relief_max, std::abs(v));
  // Argudo 4.6 displaces by rho (h - 1/2); h - mean(h) keeps the back's mean radius, so the relief
  // adds detail without shrinking or swelling the crown (a uniform texture has h = 0 everywhere).
  double height_sum = 0.0, height_count = 0.0;
  for (const Raster& face : height.faces) {
    for (float v : face.values) height_sum += v, height_count += 1.0;
  }
  const double height_mean = height_count > 0.0 ? height_sum / height_count : 0.5;
  CrownMesh& mesh = base.mesh;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    Eigen::Vector3f& p = mesh.positions[v];
    const std::size_t pixel = pixel_of[static_cast<std::size_t>(base.front_of_vertex[v])];
    const int px = static_cast<int>(pixel % static_cast<std::size_t>(photo.width));
    const int py = static_cast<int>(pixel / static_cast<std::size_t>(photo.width));
    double depth_px = std::abs(p.z()) * f.depth_scale;
    const float side = base.is_back[v] ? 1.0f : -1.0f;  // the photograph looks along +y
    const Eigen::Vector3f world(
        static_cast<float>((p.x() - f.centre_x_px) * f.metres_per_px),
        side * static_cast<float>(depth_px * f.metres_per_px),
        static_cast<float>(f.base_z_m + (f.bottom_px - p.y()) * f.metres_per_px));
    if (!base.is_back[v]) {
      depth_px += rho * 0.5 * f.half_width_px * relief.at(px, py) / relief_max;
      mesh.colors[v] = {photo.at(px, py, 0), photo.at(px, py, 1), photo.at(px, py, 2)};
    } else {
      const Eigen::Vector3f dir = world - f.centre_m;
      const float h = sample(height, dir);
      depth_px += rho * f.half_width_px * (h - height_mean) *
                  std::min(1.0, depth_px / std::max(1e-9, f.depth_max_px));
      const CubeTexel t = direction_texel(dir, color.size);
      const Raster& face = color.faces[static_cast<std::size_t>(t.face)];
      mesh.colors[v] = {face.at(t.x, t.y, 0), face.at(t.x, t.y, 1), face.at(t.x, t.y, 2)};
    }
    p = {world.x(), side * static_cast<float>(std::max(0.0, depth_px) * f.metres_per_px),
         world.z()};
  }
}

double seconds_since(std::chrono::steady_clock::time_point& t0) {
  const auto now = std::chrono::steady_clock::now();
  const double s = std::chrono::duration<double>(now - t0).count();
  t0 = now;
  return s;
}

}  // namespace

CrownModel reconstruct_crown(const Raster& photo, const Mask& mask, const CrownOptions& options,
                             std::mt19937_64& rng, const Mask* foliage) {
  check(photo, mask, options);
  CrownModel model;
  auto t0 = std::chrono::steady_clock::now();
  const WorkingImages work = working_images(photo, mask, foliage, options.working_pixels);
  const Raster texture =
      foliage != nullptr ? fill_gaps(work.photo, work.mask, work.foliage) : work.photo;
  model.seconds.emplace_back("resample", seconds_since(t0));
  const InflatedSheet sheet = inflate(work.mask, options.inflation, work.coverage);
  BaseMesh base = mirrored_mesh(sheet);
  model.seconds.emplace_back("base_mesh", seconds_since(t0));
  model.relief = relief(texture, work.mask, options.relief);
  model.seconds.emplace_back("relief", seconds_since(t0));
  const Frame frame = make_frame(work.mask, sheet, options);
  const int size = options.cubemap_size > 0
                       ? options.cubemap_size
                       : std::clamp(static_cast<int>(1.4 * frame.half_width_px), 32, 256);
  model.color = color_cubemap(texture, work.mask, size, options.quilt, rng);
  model.seconds.emplace_back("texture_synthesis", seconds_since(t0));
  const Cubemap height = height_cubemap(model.color, options.relief.levels);
  compose(base, sheet, frame, texture, model.relief, model.color, height, options.relief_weight);
  model.mesh = std::move(base.mesh);
  model.volume_m3 = enclosed_volume(model.mesh, 0, model.mesh.crown_triangles);
  if (model.volume_m3 < 0.0) {  // the image's rows run down: the mirror flips orientation
    flip_triangles(model.mesh, 0, model.mesh.crown_triangles);
    model.volume_m3 = -model.volume_m3;
  }
  model.centre = frame.centre_m;
  model.radius = radius_cubemap(model.mesh, model.centre, size);
  model.seconds.emplace_back("composition", seconds_since(t0));
  const double trunk_radius =
      options.trunk_radius_m > 0.0 ? options.trunk_radius_m : 0.02 * options.height_m;
  append_trunk(model.mesh, Eigen::Vector2f::Zero(),
               options.trunk_height_m + 0.25 * options.height_m * (options.trunk_height_m > 0.0),
               trunk_radius);
  if (options.billboards) model.billboards = billboard_centres(model.radius, model.centre, rng);
  model.crown_pixels = mask.count();
  model.silhouette_pixels = static_cast<std::size_t>(
      std::count(sheet.classes.begin(), sheet.classes.end(), PixelClass::kSilhouette));
  model.metres_per_pixel = frame.metres_per_px / work.factor;
  model.working_factor = work.factor;
  return model;
}

}  // namespace fspm::crown
