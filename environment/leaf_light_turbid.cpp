// Leaf light model "turbid": CanopyLight (canopy_light.hpp), Beer-Lambert along every sky
// direction through the clusters' spheres, or through 0.1 m voxels (LeafAreaGrid) in crowns of
// more than kLeafLightVoxelsFrom clusters.
#include <algorithm>
#include <memory>
#include <vector>

#include "environment/canopy_light.hpp"
#include "environment/leaf_light.hpp"
#include "environment/leaf_light_model.hpp"

namespace fspm::environment {
namespace {

class TurbidLeafLight final : public LeafLightModel {
 public:
  explicit TurbidLeafLight(const Sky& sky) { scene_.sky = sky; }

  void evaluate(std::span<const Sphere> clusters,
                std::span<const std::span<const float>> visibility,
                std::span<LightSample> out) override {
    const double voxel_m = clusters.size() > kLeafLightVoxelsFrom ? kLeafLightVoxel_m : 0.0;
    const CanopyLight light(scene_, clusters, voxel_m);
    const HemisphereDirections& dirs = light.directions();
    const std::vector<double> weight = sky_weights(scene_.sky, dirs);  // Pirk eq. 4.3 or real
    double weight_sum = 0.0;
    for (double w : weight) weight_sum += w;
    std::vector<double> t;
    for (std::size_t k = 0; k < clusters.size(); ++k) {
      const bool open = visibility.empty() || visibility[k].empty();
      if (open) {
        out[k] = light.evaluate(clusters[k].center);
        continue;
      }
      light.transmission(clusters[k].center, kNoSphere, t);
      double sum = 0.0;
      Eigen::Vector3d moment = Eigen::Vector3d::Zero();
      for (int i = 0; i < dirs.size(); ++i) {
        const auto at = static_cast<std::size_t>(i);
        const double w = weight[at] * t[at] * visibility[k][at];
        sum += w;
        moment += w * dirs.direction(i);
      }
      out[k].light = weight_sum > 0.0 ? std::clamp(sum / weight_sum, 0.0, 1.0) : 0.0;
      out[k].direction = moment.norm() > 1e-300 ? Eigen::Vector3d(moment.normalized())
                                                : light.evaluate(clusters[k].center).direction;
    }
  }

 private:
  Scene scene_;
};

}  // namespace

std::unique_ptr<LeafLightModel> make_turbid_leaf_light(const Sky& sky) {
  return std::make_unique<TurbidLeafLight>(sky);
}

}  // namespace fspm::environment
