#pragma once
// A real sky's light over some hours of a day or whole days as a distribution over directions,
// for every light model that weights sky directions (Pirk eq. 4.3's cos^2 sky replaced by it):
// the sun's beam from each of its positions and the diffuse sky (CIE radiance times cos theta),
// each weighted by the PAR it brings onto a horizontal plane over the period (mol m-2).
//
//   w(cell i) = sum_t [ S_b(t) dt [s(t) in cell i] + S_d(t) dt L_t(d_i) cos(theta_i) /
//               sum_j L_t(d_j) cos(theta_j) ]            (in PAR photons, sky_radiation.hpp)
//
// so that the light relative to the open sky, sum_i w_i T_i / sum_i w_i, is the share of the
// period's PAR a point receives, and sum_i w_i T_i its absolute PAR (mol m-2). Over several days
// the sun's positions are merged into bins of about 2 degrees (their weighted mean direction), so
// a season costs a few hundred directions instead of one per step.
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "environment/daylight.hpp"
#include "environment/hemisphere.hpp"
#include "environment/site_sky.hpp"

namespace fspm::environment {

struct SkyDistribution {
  DiffuseSky diffuse = DiffuseSky::kStandardOvercast;
  // The sun's positions (unit vectors, z > 0) with the PAR of its beam (mol m-2 on a horizontal
  // plane over the period) and the PAR of the diffuse sky while it stood there (the CIE clear
  // sky's radiance follows the sun; night steps carry nothing).
  std::vector<Eigen::Vector3d> suns;
  std::vector<double> direct_mol_m2;
  std::vector<double> diffuse_mol_m2;
  double seconds = 0.0;  // length of the period, night included
  int days = 1;          // whole days of the period (1 for some hours of one day)

  double open_direct_mol_m2() const;
  double open_diffuse_mol_m2() const;
  // PAR an unobstructed horizontal plane receives over the period (direct + diffuse).
  double open_mol_m2() const { return open_direct_mol_m2() + open_diffuse_mol_m2(); }
  // The PAR of the period reaching each cell of `dirs` (mol m-2 on a horizontal plane): the
  // diffuse sky by its radiance at the cell's centre, each sun position whole in the cell holding
  // it. Sums to open_mol_m2().
  std::vector<double> cell_mol_m2(const HemisphereDirections& dirs) const;
  // The direction the light comes from on average, normalise(sum_t S_b s + S_d m_d) (site_sky.hpp).
  Eigen::Vector3d mean_direction() const;
};

// The distribution of one RealSky (its hours of its date, every step its own sun position) or of
// a SiteSky (its hours, or whole days from its date, sun positions merged into ~2 degree bins
// when days > 1). Throws ValueError for an invalid sky.
SkyDistribution sky_distribution(const RealSky& sky);
SkyDistribution sky_distribution(const SiteSky& sky);

// Makes `sky` the real sky's: its weights per direction (sky_weights, sky.hpp) become those of the
// distribution, its brightest point the mean direction (for what still takes one direction), the
// closed forms of the cos^2 sky are switched off, and its shadow-volume cutoff is lowered by the
// distribution's peak against the cos^2 sky's: an occluder covering n of N cells removes at most
// n w_max / sum w of the light, 3 n / N under the cos^2 sky (light_model.hpp).
void apply_sky_distribution(Sky& sky, std::shared_ptr<const SkyDistribution> distribution);

// PAR at each point through leaf clusters swept in voxels of voxel_m (CanopySweep) and the
// scene's obstacles under the distribution: one sweep per diffuse direction
// (scene.sky.directions) and one per sun position. Each point's own cluster shades it.
// daily_par_mol_m2 is the PAR of the period divided by its days, par_umol_m2_s its mean flux.
std::vector<DaylightSample> daylight_through_voxels(std::span<const Sphere> clusters,
                                                    const Scene& scene, const SkyDistribution& sky,
                                                    std::span<const Eigen::Vector3d> points,
                                                    double voxel_m);

}  // namespace fspm::environment
