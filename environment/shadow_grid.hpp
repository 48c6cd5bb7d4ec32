#pragma once
// Shadow propagation in a voxel grid (Palubicki et al. 2009, section 4.1, "shadow propagation").
// Every bud adds shade to the pyramid of voxels below it: the voxel (i +- p, j +- p, k - q) gets
// a * b^-q for q = 0..q_max and |p| <= q. A bud's light is Q = max(C - s + a, 0) (s the shade of
// its voxel, the + a removes its own), reported here as Q / C in [0, 1]; its optimal growth
// direction points to the least shaded of the 26 neighbouring voxels. The shade is local: nothing
// further than q_max voxels away reaches a bud, which is what lets a tree beside a wall keep the
// light of its far side.
//
// Obstacles take part as voxels: a voxel overlapping an obstacle is fully shaded (no light for a
// bud inside it, never chosen as a growth direction) and casts obstacle_shade * C * (1 -
// translucency) times the share of the voxel it fills into the pyramid below it, so an opaque
// roof darkens what lies under it and a wall shades the buds within about q_max voxels of it. The
// pyramid is vertical, the light taken from the zenith as in Palubicki's model, unless the grid is
// given the direction the light comes from on average (a real sky's PAR-weighted mean direction,
// sky_distribution.hpp): then every pyramid leans along it, layer k + q above a voxel summed over
// the square of half width q around the point q layers up that direction (rounded to a voxel), as
// voxels in the sun's shadow are found from its azimuth and elevation in voxel models of cities
// (Gorte et al. 2018), so shade falls on the side away from the sun.
//
// The pyramid sum is computed per layer from 2D summed-area tables, so a voxel's shade costs
// O(q_max) whatever the number of buds; it is computed only for the voxels asked about. Buffers
// are kept between resets.
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "environment/scene.hpp"

namespace fspm::environment {

struct ShadowGridParams {
  double voxel_size_m = 0.15;
  double shade_a = 1.0;     // a: shade a bud casts into its own voxel
  double shade_b = 2.0;     // b: each layer further down receives 1/b of the layer above
  int depth_voxels = 8;     // q_max
  double full_light = 3.0;  // C: the light of an unshaded voxel, in units of a
  // Shade a voxel filled by an opaque obstacle casts, in units of C. 0.1 gives a bud one voxel
  // from a tall opaque wall one voxel thick Q / C = 1 - 0.1 * sum_q (2q + 1) 2^-q = 0.51, about
  // the half sky the wall hides.
  double obstacle_shade = 0.1;
};

class ShadowGrid {
 public:
  explicit ShadowGrid(const ShadowGridParams& params);
  // New parameters for a grid whose buffers are reused, with the vertical pyramid again; call
  // reset() before adding anything.
  void set_params(const ShadowGridParams& params);

  // Leans every pyramid toward `toward_light` (z > 0, any length; the zenith gives Palubicki's
  // vertical pyramid and the same shades bit for bit), by at most kMaxLeanDeg from the zenith;
  // call before reset(). Throws ValueError for a direction that is not finite or not above the
  // horizon.
  void set_light_direction(const Eigen::Vector3d& toward_light);
  // The lean's axis: the unit vector the pyramids lean toward (the zenith by default).
  Eigen::Vector3d light_axis() const {
    return Eigen::Vector3d(lean_.x(), lean_.y(), 1.0).normalized();
  }
  // A lower mean light direction leans the pyramids this much: its shade lands within
  // q_max tan(60 deg) voxels to the side instead of running off along the grid.
  static constexpr double kMaxLeanDeg = 60.0;

  // Empties the grid and sizes it to cover every bud inside [lo, hi] together with every voxel
  // whose shade can reach them (q_max voxels beside and above).
  void reset(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);
  // Marks the voxels the scene's occluders overlap (boxes, spheres, triangle meshes; the ground
  // only shades below itself and is skipped) as obstacles and as shade sources.
  void add_obstacles(const Scene& scene);
  // A bud at p casts a (strength 1) or `weight` times a.
  void add_bud(const Eigen::Vector3d& p, double weight = 1.0);
  // Propagates the shade of every source; call after the last add_* and before any query.
  void propagate();
  // Remembers the sources added so far (the obstacles) so that clear_buds() can return to them:
  // a grid re-filled with moving buds at every step rasterizes its obstacles once.
  void keep_obstacles();
  // Removes every bud, keeping the obstacles of the last keep_obstacles() (or none).
  void clear_buds();
  // Whether a bud anywhere in [lo, hi] lies in the grid with all the voxels that can shade it.
  bool covers(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) const;

  // Palubicki's Q / C for a bud at p (its own shade a removed), in [0, 1].
  double bud_light(const Eigen::Vector3d& p) const;
  // Unit vector from p towards the least shaded neighbouring voxels (their mean when several tie);
  // straight up when every neighbour is an obstacle.
  Eigen::Vector3d growth_direction(const Eigen::Vector3d& p) const;
  // Mean light direction at p: the zenith (the lean's axis) tilted toward the less shaded side
  // (central differences over the four side neighbours, an obstacle voxel counting as C + a of
  // shade) by up to the 45 degrees of the shadow pyramid. Smooth where growth_direction picks one
  // of 26.
  Eigen::Vector3d light_direction(const Eigen::Vector3d& p) const;

  // The same spread over the eight voxel centres around p with trilinear weights (summing to 1):
  // the bud casts `weight` a shared among them, and its light and light direction are the
  // corners' values interpolated, the bud's own shares removed exactly (a lone bud sees 1). At a
  // voxel centre these are add_bud, bud_light and light_direction; between centres they change
  // continuously with p, where the nearest voxel jumps as p crosses a voxel face.
  void add_bud_spread(const Eigen::Vector3d& p, double weight = 1.0);
  double spread_bud_light(const Eigen::Vector3d& p) const;
  Eigen::Vector3d spread_light_direction(const Eigen::Vector3d& p) const;

  // The eight voxel centres around a point and their weights, found once for a bud that is added
  // and then read (locate() is false for a point too far out to place; such a bud casts nothing
  // and sees full light).
  struct Corners {
    Eigen::Vector3i base;  // voxel of the lower-left-front centre
    Eigen::Vector3d t;     // the point's position between the centres, each in [0, 1)
    double w[8];           // trilinear weight of corner c (bits x, y, z)
    bool all_inside;       // the eight corners lie in the grid
    std::size_t at;        // index of base when all_inside
  };
  bool locate(const Eigen::Vector3d& p, Corners& k) const;
  void add_bud_spread(const Corners& k, double weight = 1.0);
  double spread_bud_light(const Corners& k) const;

  // Shade s of the voxel containing p (0 outside the grid), for tests.
  double shade(const Eigen::Vector3d& p) const;
  bool obstacle(const Eigen::Vector3d& p) const;
  Eigen::Vector3i dimensions() const { return n_; }

 private:
  bool voxel_of(const Eigen::Vector3d& p, Eigen::Vector3i& v) const;
  // The voxel range reset() gives to buds in [lo, hi]: q_max + 1 voxels beside and above, and on
  // the side the pyramids lean toward as many more as they shift.
  void voxel_span(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, Eigen::Vector3d& first,
                  Eigen::Vector3d& last) const;
  void update_lean_shifts();
  double leaning_pyramid_sum(int i, int j, int k) const;
  // The weight of the upper corners inside lower corner c's square one layer up.
  double upper_share_in_square(const Corners& k, int c) const;
  bool inside(const Eigen::Vector3i& v) const {
    return (v.array() >= 0).all() && (v.array() < n_.array()).all();
  }
  // Index of corner c when all eight lie in the grid.
  std::size_t corner_index(const Corners& k, int c) const {
    return k.at + (c & 1) + ((c >> 1) & 1) * static_cast<std::size_t>(n_.x()) +
           ((c >> 2) & 1) * static_cast<std::size_t>(n_.x()) * n_.y();
  }
  Eigen::Vector3d light_direction_at(const Eigen::Vector3i& v) const;
  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * n_.y() + j) * n_.x() + i;
  }
  Eigen::Vector3d voxel_center(int i, int j, int k) const;
  void mark_obstacle(int i, int j, int k, double translucency, double fraction);
  template <typename Inside>
  void fill_region(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double translucency,
                   const Inside& inside);
  void add_box(const Box& box);
  void fill_aligned_box(const Box& box, const Eigen::Vector3i& axes, const Eigen::Vector3d& lo,
                        const Eigen::Vector3d& hi);
  void add_sphere(const Sphere& sphere);
  void add_mesh(const TriangleMesh& mesh);
  void build_summed_area_tables();
  double box_sum(int k, int i0, int i1, int j0, int j1) const;
  double voxel_shade(int i, int j, int k) const { return voxel_shade(index(i, j, k), i, j, k); }
  // The same for the voxel at index `at` (= index(i, j, k)).
  double voxel_shade(std::size_t at, int i, int j, int k) const;
  double pyramid_sum(int i, int j, int k) const;

  ShadowGridParams p_;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();  // corner of voxel (0, 0, 0)
  Eigen::Vector3i n_ = Eigen::Vector3i::Zero();
  std::vector<double> source_;           // shade cast per voxel, in units of a
  std::vector<double> obstacle_source_;  // source_ after keep_obstacles()
  mutable std::vector<double> shade_;    // s per voxel, computed when first asked
  // shade_ holds the current s where its stamp equals stamp_ (clear_buds() only bumps stamp_).
  mutable std::vector<std::uint32_t> shade_stamp_;
  std::uint32_t stamp_ = 1;
  std::vector<std::size_t> touched_;  // voxels add_bud() changed since the last clear
  std::vector<double> falloff_;       // b^-q
  // The lean: horizontal shift per layer toward the light (tan of the lean, per axis), and the
  // square's centre shift for layer q, round(q lean), per axis; leaning_ when any shift is not 0.
  Eigen::Vector2d lean_ = Eigen::Vector2d::Zero();
  std::vector<int> shift_x_, shift_y_;
  bool leaning_ = false;
  std::vector<std::uint8_t> obstacle_;
  std::vector<double> sat_;  // per layer (nx + 1) x (ny + 1) summed-area table of source_
};

}  // namespace fspm::environment
