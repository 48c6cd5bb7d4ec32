#include "environment/canopy_summary.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "environment/canopy_light.hpp"
#include "environment/canopy_sweep.hpp"
#include "environment/hemisphere.hpp"
#include "environment/leaf_light_model.hpp"
#include "environment/sky_distribution.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {

CanopySummary summarize_canopy(std::span<const Sphere> clusters, const Eigen::Vector3d& sun,
                               double pixel_m) {
  if (!(pixel_m > 0.0))
    throw ValueError("pixel size must be > 0 m, got " + std::to_string(pixel_m));
  CanopySummary out;
  out.clusters = clusters.size();
  if (clusters.empty()) return out;
  const Eigen::Vector3d d = sun.normalized();
  const Eigen::Vector3d e1 = d.unitOrthogonal(), e2 = d.cross(e1);
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  double far = -1e300;  // the start of the lines, beyond every cluster away from the sun
  for (const Sphere& c : clusters) {
    out.leaf_area_m2 += cluster_leaf_area_m2(c);
    const Eigen::Vector2d q(c.center.dot(e1), c.center.dot(e2));
    lo = lo.cwiseMin(q - Eigen::Vector2d::Constant(c.radius_m));
    hi = hi.cwiseMax(q + Eigen::Vector2d::Constant(c.radius_m));
    far = std::max(far, -c.center.dot(d) + c.radius_m);
  }
  // Pixel centres on the plane, each the start of a line toward the sun through the crown.
  const int nu = static_cast<int>(std::ceil((hi.x() - lo.x()) / pixel_m));
  const int nv = static_cast<int>(std::ceil((hi.y() - lo.y()) / pixel_m));
  std::vector<Eigen::Vector3d> starts;
  starts.reserve(static_cast<std::size_t>(nu) * nv);
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const double u = lo.x() + (i + 0.5) * pixel_m, v = lo.y() + (j + 0.5) * pixel_m;
      starts.push_back(u * e1 + v * e2 - (far + 1.0) * d);
    }
  }
  const CanopyLight light(Scene{}, clusters);
  std::vector<double> t(starts.size());
  light.transmission_along(starts, d, {}, t);
  for (const double v : t) out.silhouette_area_m2 += (1.0 - v) * pixel_m * pixel_m;
  out.sunlit_leaf_area_m2 =
      std::min(out.silhouette_area_m2 / kSphericalLeafProjection, out.leaf_area_m2);
  out.shaded_leaf_area_m2 = out.leaf_area_m2 - out.sunlit_leaf_area_m2;
  out.star = out.leaf_area_m2 > 0.0 ? out.silhouette_area_m2 / out.leaf_area_m2 : 0.0;
  return out;
}

namespace {

// The directions the crown is lit from, each with its light on a plane normal to it (F_d), and
// the sun's positions with their direct light (for the sunlit fraction).
struct LitDirections {
  std::vector<Eigen::Vector3d> dirs;
  std::vector<double> normal_flux;  // F_d: mol m-2 per day (real sky) or eq. 4.3's I(d)
  std::vector<double> beam;         // direct light of each direction (0 for the diffuse sky)
  std::vector<int> cell;            // the direction's cell of the sky, -1 for the sun
  double per_day = 1.0;             // a real sky's period / its days: F in mol m-2 per day
};

LitDirections lit_directions(const Sky& sky) {
  LitDirections out;
  const HemisphereDirections cells(sky.directions);
  std::vector<double> w;
  if (sky.distribution) {
    SkyDistribution diffuse = *sky.distribution;
    std::fill(diffuse.direct_mol_m2.begin(), diffuse.direct_mol_m2.end(), 0.0);
    w = diffuse.cell_mol_m2(cells);
    out.per_day = 1.0 / std::max(sky.distribution->days, 1);
  } else {
    w = sky_weights(sky, cells);  // eq. 4.3's intensity: already per unit normal area
  }
  for (int i = 0; i < cells.size(); ++i) {
    const Eigen::Vector3d& d = cells.direction(i);
    const double v = w[static_cast<std::size_t>(i)];
    if (v <= 0.0) continue;
    out.dirs.push_back(d);
    out.normal_flux.push_back(sky.distribution ? v / d.z() : v);
    out.beam.push_back(0.0);
    out.cell.push_back(i);
  }
  if (!sky.distribution) {
    out.dirs.push_back(Eigen::Vector3d::UnitZ());  // the beam of the sunlit leaf area
    out.normal_flux.push_back(0.0);
    out.beam.push_back(1.0);
    out.cell.push_back(-1);
    return out;
  }
  const SkyDistribution& d = *sky.distribution;
  for (std::size_t k = 0; k < d.suns.size(); ++k) {
    if (d.direct_mol_m2[k] <= 0.0 || d.suns[k].z() <= 0.0) continue;
    out.dirs.push_back(d.suns[k]);
    out.normal_flux.push_back(d.direct_mol_m2[k] / d.suns[k].z());
    out.beam.push_back(d.direct_mol_m2[k]);
    out.cell.push_back(-1);
  }
  return out;
}

}  // namespace

CanopyLightSummary summarize_canopy_light(std::span<const Sphere> clusters, const Sky& sky) {
  Scene open;
  open.sky = sky;
  return summarize_canopy_light(clusters, open);
}

CanopyLightSummary summarize_canopy_light(std::span<const Sphere> clusters, const Scene& scene) {
  const Sky& sky = scene.sky;
  CanopyLightSummary out;
  out.clusters = clusters.size();
  out.real_sky = sky.distribution != nullptr;
  if (clusters.empty()) return out;
  const LitDirections lit = lit_directions(sky);
  const std::size_t n = clusters.size();
  std::vector<Eigen::Vector3d> centres(n);
  for (std::size_t k = 0; k < n; ++k) centres[k] = clusters[k].center;
  std::vector<float> t(lit.dirs.size() * n);
  CanopySweep sweep(1, Eigen::Vector3d::UnitZ(), kCanopySweepVoxel_m);
  sweep.transmissions(clusters, centres, lit.dirs, t);
  // The obstacles by their translucency along each direction (eq. 4.3).
  const bool obstacles = !scene.spheres.empty() || !scene.boxes.empty() || !scene.meshes.empty() ||
                         scene.ground.has_value();
  if (obstacles) {
    const HemisphereDirections cells(sky.directions);
    for (std::size_t k = 0; k < n; ++k) {
      const std::vector<float> vis = obstacle_visibility(scene, cells, centres[k]);
      for (std::size_t i = 0; i < lit.dirs.size(); ++i) {
        const int c = lit.cell[i];
        const double o = c >= 0 ? (vis.empty() ? 1.0 : vis[static_cast<std::size_t>(c)])
                                : obstacle_transmission(scene, centres[k], lit.dirs[i]);
        t[i * n + k] *= static_cast<float>(o);
      }
    }
  }
  double flux = 0.0, beam = 0.0;
  for (std::size_t i = 0; i < lit.dirs.size(); ++i) flux += lit.normal_flux[i], beam += lit.beam[i];
  out.per_cluster.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    double lit_flux = 0.0, lit_beam = 0.0;
    for (std::size_t i = 0; i < lit.dirs.size(); ++i) {
      const double tk = t[i * n + k];
      lit_flux += lit.normal_flux[i] * tk;
      lit_beam += lit.beam[i] * tk;
    }
    ClusterCanopyLight& c = out.per_cluster[k];
    c.leaf_area_m2 = cluster_leaf_area_m2(clusters[k]);
    c.sunlit_fraction = beam > 0.0 ? lit_beam / beam : 0.0;
    c.sunlit_leaf_area_m2 = c.sunlit_fraction * c.leaf_area_m2;
    c.shaded_leaf_area_m2 = c.leaf_area_m2 - c.sunlit_leaf_area_m2;
    c.lie = flux > 0.0 ? lit_flux / flux : 0.0;
    c.star = kSphericalLeafProjection * c.lie;
    if (out.real_sky) {
      c.absorbed_par_mol_day =
          kLeafParAbsorptance * kSphericalLeafProjection * c.leaf_area_m2 * lit_flux * lit.per_day;
    }
    out.leaf_area_m2 += c.leaf_area_m2;
    out.sunlit_leaf_area_m2 += c.sunlit_leaf_area_m2;
    out.shaded_leaf_area_m2 += c.shaded_leaf_area_m2;
    out.lie += c.lie * c.leaf_area_m2;
    out.absorbed_par_mol_day += c.absorbed_par_mol_day;
  }
  out.lie = out.leaf_area_m2 > 0.0 ? out.lie / out.leaf_area_m2 : 0.0;
  out.star = kSphericalLeafProjection * out.lie;
  return out;
}

}  // namespace fspm::environment
