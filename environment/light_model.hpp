#pragma once
// Sky light at points (Pirk eq. 4.3): i(p) = c * integral over the upper hemisphere of
// I(d) * V(p, d), with I = cos^2(angle between d and the brightest sky point) and V the product
// of the translucencies of the occluders the ray p + t d crosses; c makes an unoccluded point
// receive exactly 1. The mean light direction is the same integral of I * V * d, normalised.
//
// Shadow volumes (Pirk Fig. 4.4): an occluder only matters at points from which it covers a
// significant share of the sky. A sphere (radius r, translucency g) seen at half angle alpha
// removes at most 3 (1 - g)(1 - cos alpha) of the light (its cap's solid angle times max I over
// the hemisphere integral 2 pi / 3); its shadow volume is the part of the ball of radius
// r / sin(alpha_min) below its top, where this bound reaches Sky::significance. Shadow volumes are
// binned in a uniform grid, so a query visits only the occluders whose volume contains its cell.
//
// Evaluation: over the stratified directions, each sphere's cap is rasterized onto the direction
// rings (only the cells it covers are visited), boxes and meshes are ray-cast inside their
// bounding cap. When every occluder relevant to a point is a sphere, their caps lie above the
// horizon and do not overlap (at most 16 of them), the integral is evaluated analytically
// (closed-form cap integrals of cos^2) and is exact.
//
// Boxes (and walls) are integrated in closed form too when Sky::analytic_boxes is set
// (light_model_boxes.cpp): a box seen from p is the union of its front faces' spherical polygons
// clipped to the horizon (spherical_polygon.hpp, Arvo 1995), and overlapping boxes are expanded
// by inclusion-exclusion over the polygons' intersections, so boxes alone are exact at any
// direction count. Sphere caps above the horizon enter linearly; where a cap overlaps another
// occluder, crosses the horizon, or a mesh is relevant, only the difference between the true
// visibility (product of translucencies) and the closed form's model is sampled, on finer
// stratified directions and only inside those caps and meshes.
#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "environment/hemisphere.hpp"
#include "environment/scene.hpp"
#include "environment/sphere_cap.hpp"

namespace fspm::environment {

struct LightSample {
  double light = 1.0;                                    // in [0, 1]
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // unit mean light direction
};

inline constexpr std::uint32_t kNoSphere = std::numeric_limits<std::uint32_t>::max();

class LightModel {
 public:
  // Copies the scene's occluders and builds the shadow-volume index. Throws ValueError for a sky
  // with fewer than 1 direction.
  explicit LightModel(const Scene& scene);

  // Light at p, ignoring sphere `ignore` (an index into scene.spheres, e.g. a bud's own cluster).
  LightSample evaluate(const Eigen::Vector3d& p, std::uint32_t ignore = kNoSphere) const;
  void evaluate(std::span<const Eigen::Vector3d> points, std::span<LightSample> out) const;

  // Reference: every direction ray-cast against every occluder (no shadow volumes, no
  // analytic shortcut). For tests.
  LightSample evaluate_brute_force(const Eigen::Vector3d& p) const;

  const HemisphereDirections& directions() const { return dirs_; }
  const Scene& scene() const { return scene_; }
  // Average number of spheres a query found in its grid cell (diagnostics).
  std::size_t index_entries() const { return cell_items_.size(); }

 private:
  using Cap = SphereCap;
  struct BoxSky;
  struct Region;
  struct FineSky;
  LightSample sampled(const Eigen::Vector3d& p, std::span<const Cap> caps, double all_factor,
                      bool boxes) const;
  LightSample finish(const Eigen::Vector3d& p, std::vector<double>& vis, bool boxes) const;
  bool box_relevant(std::size_t i, const Eigen::Vector3d& p) const;
  bool mesh_relevant(std::size_t i, const Eigen::Vector3d& p) const;
  void apply_meshes(const Eigen::Vector3d& p, std::vector<double>& vis) const;
  // Closed-form path for points with relevant boxes (light_model_boxes.cpp); false when the
  // closed forms are not finite (then the caller samples).
  bool analytic_with_boxes(const Eigen::Vector3d& p, std::span<const Cap> caps, double all,
                           LightSample& out) const;
  void sample_residual(const Eigen::Vector3d& p, std::span<const Cap> caps,
                       std::span<const BoxSky> boxes, bool boxes_exact, double& integral,
                       Eigen::Vector3d& moment) const;
  void sample_fine(const FineSky& fine, const Eigen::Vector3d& p, std::span<const Cap> caps,
                   std::span<const BoxSky> boxes, bool all_caps, std::span<const Region> regions,
                   double& integral, Eigen::Vector3d& moment) const;
  void build_fine_directions();
  // Construction steps: sky weights I(d), shadow-volume radii, the index of sphere volumes.
  void set_sky_weights();
  void set_shadow_reaches();
  void build_sphere_index();
  bool choose_index_cell(std::vector<double>& finite, double clamp);
  void fill_sphere_index(double clamp);
  void sphere_volume_box(std::uint32_t i, double clamp, Eigen::Vector3d& lo,
                         Eigen::Vector3d& hi) const;

  Scene scene_;
  HemisphereDirections dirs_;
  std::vector<double> weight_;  // I(d) per direction
  double weight_sum_ = 0.0;
  Eigen::Vector3d open_direction_ = Eigen::Vector3d::UnitZ();
  // Finer directions for the remainder of the closed-form box path (built only with boxes):
  // kFewCapsRefinement times the sky's directions when at most kMaxAnalyticCaps caps are relevant
  // (the remainder is then sampled only inside overlapping caps), kManyCapsRefinement times
  // otherwise (inside every cap: the cost grows with it); at most kMaxResidualDirections, never
  // fewer than the sky's.
  static constexpr int kFewCapsRefinement = 16;
  static constexpr int kManyCapsRefinement = 4;
  static constexpr int kMaxResidualDirections = 16384;
  struct FineSky {
    HemisphereDirections dirs;
    std::vector<double> weight;  // I(d)
    double weight_sum = 0.0;
    FineSky(int count, const Eigen::Vector3d& brightest);
  };
  std::optional<FineSky> fine_few_, fine_many_;
  std::vector<double> reach2_;      // squared shadow-volume radius per sphere (inf: unbounded)
  std::vector<double> box_reach2_;  // the same for boxes and meshes (by bounding sphere)
  std::vector<double> mesh_reach2_;
  // Uniform grid of shadow volumes (CSR).
  Eigen::Vector3d grid_lo_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d grid_hi_ = Eigen::Vector3d::Zero();
  Eigen::Vector3i grid_n_ = Eigen::Vector3i::Zero();
  double cell_ = 1.0;
  std::vector<std::uint32_t> cell_start_, cell_items_, all_spheres_;
};

// Squared shadow-volume radius of an occluder with bounding radius r and translucency g (see
// above): the distance beyond which it removes less than `significance` of the light; infinite
// for no significance, negative when it never matters.
double shadow_reach2(double r, double g, double significance);

}  // namespace fspm::environment
