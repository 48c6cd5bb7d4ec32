// Skinned meshes and wind poses for fspm mesh --skin and fspm render --wind-time.
#include "cli/wind_skin.hpp"

#include <cmath>
#include <numbers>

#include "cli/output.hpp"
#include "fspm/error.hpp"
#include "graphics/mesh_writers.hpp"
#include "graphics/skeleton_skin.hpp"

namespace fspm::cli {
namespace {
constexpr double kDegree = std::numbers::pi / 180.0;
}  // namespace

void add_wind_options(CLI::App* command, WindArguments& wind, bool frames) {
  command
      ->add_option("--wind-amplitude", wind.amplitude_deg,
                   "Sway of the thinnest branch in degrees (thicker ones sway less, with the "
                   "square of their radius)")
      ->check(number_in(0.0, 90.0))
      ->capture_default_str();
  command->add_option("--wind-frequency", wind.options.frequency_hz, "Sway frequency in Hz")
      ->check(positive_number(100.0))
      ->capture_default_str();
  command->add_option("--wind-direction", wind.direction, "Wind direction X,Y (horizontal)")
      ->delimiter(',')
      ->expected(2);
  if (frames) {
    command
        ->add_option("--fps", wind.options.frames_per_second,
                     "Keyframes per second of the wind animation")
        ->check(positive_number(1000.0))
        ->capture_default_str();
  } else {
    command
        ->add_option("--wind-period", wind.options.duration_s,
                     "Length of the looping wind clip the time falls in (as --animate of fspm "
                     "mesh), in s")
        ->check(positive_number(1e5))
        ->capture_default_str();
  }
}

graphics::WindOptions wind_options(const WindArguments& wind, double duration_s,
                                   std::uint64_t seed) {
  graphics::WindOptions o = wind.options;
  o.amplitude_rad = wind.amplitude_deg * kDegree;
  o.duration_s = duration_s;
  if (!wind.direction.empty()) o.direction = {wind.direction.at(0), wind.direction.at(1), 0.0};
  o.seed = seed;
  o.validate();
  return o;
}

graphics::TriangleMesh skinnable_mesh(const TreeGraph& tree, graphics::MeshOptions options) {
  options.junctions = graphics::JunctionMode::kContinuous;
  return graphics::mesh_tree(tree, options);
}

SkinnedOutput write_wind_glb(const TreeGraph& tree, const graphics::MeshOptions& options,
                             const WindArguments& wind, double duration_s, std::uint64_t seed,
                             const std::string& path) {
  const graphics::TriangleMesh mesh = skinnable_mesh(tree, options);
  const graphics::Skin skin = graphics::skin_mesh(tree, mesh);
  SkinnedOutput out{skin.skeleton.size(), mesh.vertex_count(), mesh.triangle_count(), 0};
  if (duration_s <= 0.0) {
    graphics::write_skinned_glb(mesh, skin, nullptr, path);
  } else {
    const graphics::WindAnimation animation =
        graphics::wind_animation(skin.skeleton, wind_options(wind, duration_s, seed));
    out.keyframes = animation.times_s.size();
    graphics::write_skinned_glb(mesh, skin, &animation, path);
  }
  return out;
}

WindFrame posed_in_wind(const TreeGraph& tree, const graphics::MeshOptions& options,
                        const WindArguments& wind, double t_s, std::uint64_t seed) {
  const graphics::TriangleMesh mesh = skinnable_mesh(tree, options);
  const graphics::Skin skin = graphics::skin_mesh(tree, mesh);
  const std::vector<Eigen::Quaternionf> rotations =
      graphics::wind_pose(skin.skeleton, wind_options(wind, wind.options.duration_s, seed), t_s);
  WindFrame out;
  out.mesh =
      graphics::pose_mesh(mesh, skin, graphics::joint_world_matrices(skin.skeleton, rotations));
  const Eigen::Vector3f lo = mesh.bbox_min(), hi = mesh.bbox_max();
  const float margin = 0.1f * (hi.z() - lo.z());
  out.frame = Eigen::AlignedBox3f(lo - Eigen::Vector3f(margin, margin, 0.0f),
                                  hi + Eigen::Vector3f::Constant(margin));
  return out;
}

}  // namespace fspm::cli
