#include "graphics/viewer_wind.hpp"

#include <algorithm>

namespace fspm::graphics {

void ViewerWind::pose(double t_s, double strength, std::vector<Eigen::Vector3f>& positions,
                      std::vector<Eigen::Vector3f>& normals) const {
  WindOptions scaled = wind;
  // The sway angle of every joint is proportional to the amplitude (wind_animation.hpp), so this
  // scales the whole pose.
  scaled.amplitude_rad *= std::max(strength, 0.0);
  const std::vector<Eigen::Quaternionf> rotations = wind_pose(skin.skeleton, scaled, t_s);
  const TriangleMesh posed = pose_mesh(mesh, skin, joint_world_matrices(skin.skeleton, rotations));
  positions = posed.positions;
  normals = posed.normals;
}

}  // namespace fspm::graphics
