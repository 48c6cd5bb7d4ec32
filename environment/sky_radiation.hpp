#pragma once
// Radiation of a real sky: the extraterrestrial radiation, a clear-sky global radiation from the
// site's elevation and the sun, its split into direct and diffuse light, PAR in photon units, and
// the distribution of the diffuse light over the sky (CIE standard skies).
#include <Eigen/Core>
#include <string_view>

#include "fspm/name_table.hpp"

namespace fspm::environment {

// Solar constant (W m-2) of Campbell and Norman (1998, ch. 11).
inline constexpr double kSolarConstant_W_m2 = 1360.0;
// Share of global shortwave radiation that is PAR (400-700 nm; Spitters et al. 1986 take 0.5) and
// photons per joule of daylight PAR (4.57 umol/J, Thimijan and Heins 1983).
inline constexpr double kParShareOfGlobal = 0.5;
inline constexpr double kPhotonsPerJoulePar_umol = 4.57;

// Extraterrestrial irradiance on a horizontal plane (W m-2) for the sun's elevation and the day
// of the year (Spitters et al. 1986, eq. 1): S0 = Sc (1 + 0.033 cos(360 d / 365)) sin(beta).
double extraterrestrial_horizontal_W_m2(double sun_elevation_deg, int day_of_year);

struct HorizontalRadiation {
  double direct_W_m2 = 0.0;   // the sun's beam on a horizontal plane
  double diffuse_W_m2 = 0.0;  // the sky's diffuse light on a horizontal plane
  double global_W_m2() const { return direct_W_m2 + diffuse_W_m2; }
};

// Clear-sky global radiation on a horizontal plane (Campbell and Norman 1998, eq. 11.11-11.13
// with the air mass m = p_a / (101.3 cos z), eq. 3.7 for p_a at the elevation): beam
// Sc tau^m cos z and diffuse 0.3 (1 - tau^m) Sc cos z, atmospheric transmittance tau (0.75 on a
// clear day); the day-of-year correction of the solar constant as in eq. 1 of Spitters et al.
double clear_sky_global_W_m2(double sun_elevation_deg, int day_of_year, double elevation_m,
                             double transmittance = 0.75);

// Diffuse share of hourly global radiation from the atmospheric transmission Sg / S0 and the sun's
// elevation (Spitters et al. 1986, eq. 20). Global radiation of a sun below the horizon is diffuse.
double spitters_diffuse_fraction(double global_W_m2, double sun_elevation_deg, int day_of_year);
// Diffuse share of hourly global radiation from the clearness index kt = Sg / S0 (Erbs et al.
// 1982): 1 - 0.09 kt up to 0.22, a quartic in kt up to 0.80, 0.165 above.
double erbs_diffuse_fraction(double global_W_m2, double sun_elevation_deg, int day_of_year);

enum class DiffuseSplit { kSpitters, kErbs };
inline constexpr NameTable<DiffuseSplit, 2> kDiffuseSplitNames{
    "diffuse split",
    {{DiffuseSplit::kSpitters, "spitters", "Spitters et al. 1986"},
     {DiffuseSplit::kErbs, "erbs", "Erbs et al. 1982"}}};
// Throws ValueError for a name other than "spitters" or "erbs".
DiffuseSplit diffuse_split_from_name(std::string_view name);

// Global radiation split into direct and diffuse (Spitters et al. 1986 unless told).
HorizontalRadiation split_global(double global_W_m2, double sun_elevation_deg, int day_of_year,
                                 DiffuseSplit split = DiffuseSplit::kSpitters);

// Photosynthetic photon flux density (umol m-2 s-1) of a global shortwave irradiance (W m-2).
inline double par_umol_m2_s(double global_W_m2) {
  return global_W_m2 * kParShareOfGlobal * kPhotonsPerJoulePar_umol;
}

// Relative radiance of the diffuse sky in direction d (unit, z up) with the sun in direction s.
enum class DiffuseSky {
  kStandardOvercast,  // CIE standard overcast sky (Moon and Spencer 1942): (1 + 2 cos theta) / 3
  kClear,             // CIE standard clear sky (CIE S 011/E:2003, type 12)
  kUniform,           // uniform radiance
};
inline constexpr NameTable<DiffuseSky, 3> kDiffuseSkyNames{
    "diffuse sky",
    {{DiffuseSky::kStandardOvercast, "overcast", "CIE standard overcast"},
     {DiffuseSky::kClear, "clear", "CIE standard clear"},
     {DiffuseSky::kUniform, "uniform", "uniform radiance"}}};
double sky_radiance(DiffuseSky sky, const Eigen::Vector3d& d, const Eigen::Vector3d& sun);

}  // namespace fspm::environment
