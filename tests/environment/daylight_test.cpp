#include "environment/daylight.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "environment/radiation_file.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {
namespace {

// The worked example of the NREL solar position algorithm (Reda and Andreas 2004, table A4.1 and
// A5.1): Golden, Colorado, 17 October 2003, 12:30:30 local time (UTC - 7), 820 mbar, 11 C.
TEST(SolarPosition, MatchesTheNrelWorkedExample) {
  const Site golden{39.742476, -105.1786, 1830.14, -7.0};
  const CalendarDate date{2003, 10, 17};
  const SolarPosition s =
      solar_position(golden, date, 12.0 + 30.0 / 60.0 + 30.0 / 3600.0, 820.0, 11.0);
  EXPECT_NEAR(s.zenith_deg, 50.11162, 0.01);
  EXPECT_NEAR(s.azimuth_deg, 194.34024, 0.01);
  EXPECT_NEAR(s.declination_deg, -9.31434, 0.01);  // geocentric declination of the example
  // Its sun transit, 11:46:08 local time: the sun due south (within 10 s of azimuth change).
  const SolarPosition noon =
      solar_position(golden, date, 11.0 + 46.0 / 60.0 + 8.0 / 3600.0, 820.0, 11.0);
  EXPECT_NEAR(noon.azimuth_deg, 180.0, 0.06);
  const Eigen::Vector3d d = s.direction();
  EXPECT_NEAR(d.norm(), 1.0, 1e-12);
  EXPECT_NEAR(std::acos(d.z()) * 180.0 / M_PI, 50.11162, 0.01);
  EXPECT_LT(d.x(), 0.0);  // azimuth 194: a little west of south
  EXPECT_LT(d.y(), 0.0);
}

TEST(SolarPosition, RejectsBadInput) {
  EXPECT_THROW(solar_position({95.0, 0, 0, 0}, {2003, 1, 1}, 12.0), ValueError);
  EXPECT_THROW(solar_position({45.0, 0, 0, 0}, {1900, 1, 1}, 12.0), ValueError);
  EXPECT_THROW(solar_position({45.0, 0, 0, 0}, {2003, 13, 1}, 12.0), ValueError);
  RealSky sky;
  sky.date.day = 32;
  EXPECT_THROW(sky.validate(), ValueError);
  sky.date.day = 1;
  sky.first_hour = 14, sky.last_hour = 10;
  EXPECT_THROW(sky.validate(), ValueError);
}

// Each refusal names the field it refuses; valid values pass.
TEST(SolarPosition, ValidateNamesTheField) {
  const auto message = [](const auto& value) {
    try {
      value.validate();
    } catch (const ValueError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(message(Site{39.7, -105.2, 1830.0, -7.0}), "");
  EXPECT_EQ(message(CalendarDate{2003, 10, 17}), "");
  EXPECT_NE(message(Site{95.0, 0, 0, 0}).find("latitude_deg"), std::string::npos);
  EXPECT_NE(message(Site{45.0, NAN, 0, 0}).find("longitude_deg"), std::string::npos);
  EXPECT_NE(message(Site{45.0, 0, INFINITY, 0}).find("elevation_m"), std::string::npos);
  EXPECT_NE(message(Site{45.0, 0, 0, NAN}).find("utc_offset_h"), std::string::npos);
  EXPECT_NE(message(CalendarDate{1900, 1, 1}).find("date: year"), std::string::npos);
  EXPECT_NE(message(CalendarDate{2003, 13, 1}).find("date: month"), std::string::npos);
  EXPECT_NE(message(CalendarDate{2003, 1, 0}).find("date: day"), std::string::npos);
}

// Spitters et al. (1986) eq. 20: all diffuse below Sg/S0 = 0.22, the quadratic between 0.22 and
// 0.35; a split always sums to the global radiation.
TEST(SkyRadiation, SpittersSplit) {
  const int doy = 172;
  const double s0 = extraterrestrial_horizontal_W_m2(60.0, doy);
  EXPECT_NEAR(s0,
              kSolarConstant_W_m2 * (1 + 0.033 * std::cos(2 * M_PI * doy / 365.0)) *
                  std::sin(60.0 * M_PI / 180.0),
              1e-9);
  EXPECT_DOUBLE_EQ(spitters_diffuse_fraction(0.2 * s0, 60.0, doy), 1.0);
  EXPECT_NEAR(spitters_diffuse_fraction(0.3 * s0, 60.0, doy), 1.0 - 6.4 * 0.08 * 0.08, 1e-12);
  for (const double g : {10.0, 200.0, 500.0, 900.0}) {
    const HorizontalRadiation r = split_global(g, 60.0, doy);
    EXPECT_NEAR(r.direct_W_m2 + r.diffuse_W_m2, g, 1e-9);
    EXPECT_GE(r.direct_W_m2, 0.0);
  }
  // A clear sky at noon in June at 45 N: 800-1000 W m-2, more at altitude.
  const double g0 = clear_sky_global_W_m2(68.0, doy, 0.0);
  EXPECT_GT(g0, 800.0);
  EXPECT_LT(g0, 1000.0);
  EXPECT_GT(clear_sky_global_W_m2(68.0, doy, 2000.0), g0);
}

// Erbs et al. (1982): the three pieces meet at kt = 0.22 and 0.80 (the published coefficients
// are rounded: within 1e-3), and every split sums to the global radiation.
TEST(SkyRadiation, ErbsSplit) {
  const int doy = 172;
  const double s0 = extraterrestrial_horizontal_W_m2(50.0, doy);
  const auto f = [&](double kt) { return erbs_diffuse_fraction(kt * s0, 50.0, doy); };
  EXPECT_NEAR(f(0.22), f(0.22 + 1e-9), 1e-3);
  EXPECT_NEAR(f(0.80), f(0.80 + 1e-9), 1e-3);
  EXPECT_NEAR(f(0.1), 1.0 - 0.009, 1e-12);
  EXPECT_DOUBLE_EQ(f(0.9), 0.165);
  EXPECT_GT(f(0.3), f(0.6));  // clearer hours are less diffuse
  const HorizontalRadiation r = split_global(0.6 * s0, 50.0, doy, DiffuseSplit::kErbs);
  EXPECT_NEAR(r.direct_W_m2 + r.diffuse_W_m2, 0.6 * s0, 1e-9);
  EXPECT_NEAR(r.diffuse_W_m2, f(0.6) * 0.6 * s0, 1e-9);
  EXPECT_THROW(diffuse_split_from_name("liu"), ValueError);
}

RealSky summer_day() {
  RealSky sky;
  sky.site = {45.0, 7.0, 300.0, 1.0};
  sky.date = {2024, 6, 21};
  sky.first_hour = 8.0;
  sky.last_hour = 16.0;
  return sky;
}

// A horizontal unobstructed point receives direct + diffuse = the given global radiation: a
// constant 500 W m-2 over 8 hours is 500 * 0.5 * 4.57 umol/J * 8 h = 32.904 mol m-2.
TEST(Daylight, OpenPointUnderAConstantSky) {
  RealSky sky = summer_day();
  sky.global_W_m2 = 500.0;
  const CanopyLight open(Scene{}, {});
  const std::vector<Eigen::Vector3d> points{{0, 0, 0}, {3, 1, 2}};
  const auto out = daylight_at(open, sky, points);
  for (const DaylightSample& s : out) {
    EXPECT_NEAR(s.par_umol_m2_s, 500.0 * 0.5 * 4.57, 1e-9);
    EXPECT_NEAR(s.daily_par_mol_m2, 500.0 * 0.5 * 4.57 * 8 * 3600 * 1e-6, 1e-9);
    EXPECT_NEAR(s.open_fraction, 1.0, 1e-12);
  }
  // The clear sky of the site: the open point gets the integral of the global radiation.
  sky.global_W_m2 = -1.0;
  double expected = 0.0;
  for (const SkyStep& s : sky_steps(sky)) {
    expected += par_umol_m2_s(clear_sky_global_W_m2(s.sun_elevation_deg, 173, 300.0)) * 3600 *
                (8.0 / static_cast<double>(sky_steps(sky).size())) * 1e-6;
  }
  EXPECT_NEAR(daylight_at(open, sky, points)[0].daily_par_mol_m2, expected, 1e-9);
  EXPECT_GT(expected, 15.0);  // a clear June day at 45 N: about 50 mol m-2 over 24 h
}

// Measured hourly global radiation: 500 W m-2 in the hours 8-15 and none otherwise is the held
// 500 W m-2 from 8 to 16 h; bad files name the line.
TEST(Daylight, HourlyGlobalRadiationFromACsv) {
  std::string csv = "# a sunny morning\nhour,global_W_m2\n";
  for (int h = 0; h < 24; ++h) {
    csv += std::to_string(h) + "," + (h >= 8 && h < 16 ? "500" : "0") + "\n";
  }
  RealSky sky = summer_day();
  sky.first_hour = 0.0;
  sky.last_hour = 24.0;
  sky.hourly_global_W_m2 = parse_hourly_global_csv(csv, "day.csv");
  const CanopyLight open(Scene{}, {});
  const std::vector<Eigen::Vector3d> p{{0, 0, 0}};
  EXPECT_NEAR(daylight_at(open, sky, p)[0].daily_par_mol_m2, 500.0 * 0.5 * 4.57 * 8 * 3600 * 1e-6,
              1e-9);
  try {
    parse_hourly_global_csv("hour,global_W_m2\n3,100\n3,200\n", "day.csv");
    FAIL() << "a repeated hour was accepted";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_NE(std::string(e.what()).find("day.csv"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parse_hourly_global_csv("hour,global_W_m2\n24,100\n"), ParseError);
  EXPECT_THROW(parse_hourly_global_csv("hour,global_W_m2\n5,-1\n"), ParseError);
  EXPECT_THROW(parse_hourly_global_csv("hour,W\n5,1\n"), ParseError);
}

// Diffuse light alone (Sg / S0 < 0.22) under an opaque sphere at the zenith of a CIE overcast
// sky, L = (1 + 2 cos theta) / 3: the sphere takes
// [(1 - cos^2 a) / 2 + 2 (1 - cos^3 a) / 3] / (7 / 6) of the horizontal irradiance.
TEST(Daylight, OvercastSkyUnderASphere) {
  RealSky sky = summer_day();
  sky.global_W_m2 = 50.0;
  Scene scene;
  scene.sky.directions = 16384;
  scene.spheres.push_back({Eigen::Vector3d(0, 0, 2), 1.0, 0.0, true});
  const CanopyLight light(scene, {});
  const std::vector<Eigen::Vector3d> p{{0, 0, 0}};
  const double ca = std::sqrt(0.75);
  const double blocked = ((1 - ca * ca) / 2 + 2 * (1 - ca * ca * ca) / 3) / (7.0 / 6.0);
  EXPECT_NEAR(daylight_at(light, sky, p)[0].open_fraction, 1.0 - blocked, 1e-2);
  EXPECT_LT(blocked, 0.35);
  EXPECT_GT(blocked, 0.25);
}

// The sun's beam through a cluster: Beer-Lambert along the chord the sun's ray crosses.
TEST(Daylight, SunBeamThroughACluster) {
  const std::vector<Sphere> clusters{{Eigen::Vector3d(0, 0, 3), 0.5, 0.2, false}};
  const CanopyLight light(Scene{}, clusters);
  EXPECT_NEAR(light.transmission_along({0, 0, 0}, Eigen::Vector3d::UnitZ()), 0.2, 1e-12);
  EXPECT_NEAR(light.transmission_along({0, 0, 3}, Eigen::Vector3d::UnitZ()), std::sqrt(0.2), 1e-12);
  EXPECT_EQ(light.transmission_along({0, 0, 4}, Eigen::Vector3d::UnitZ()), 1.0);
  // A clear CIE sky is brightest near the sun and darker opposite it.
  const Eigen::Vector3d sun = Eigen::Vector3d(1, 0, 1).normalized();
  EXPECT_GT(sky_radiance(DiffuseSky::kClear, Eigen::Vector3d(0.9, 0, 0.8).normalized(), sun),
            sky_radiance(DiffuseSky::kClear, Eigen::Vector3d(-0.9, 0, 0.8).normalized(), sun));
}

// The sun's beam for many points at once (clusters binned by their shadow) equals the beam point
// by point, on random crowns and sun directions.
TEST(Daylight, BatchedSunBeamEqualsOnePointAtATime) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Sphere> clusters;
  for (int i = 0; i < 300; ++i) {
    const double r = 0.2 + 0.5 * u(rng);
    clusters.push_back({Eigen::Vector3d(6 * u(rng), 6 * u(rng), 1 + 5 * u(rng)), r,
                        cluster_translucency(r), false});
  }
  Scene scene;
  scene.boxes.push_back(Box::wall({7, -5}, {7, 10}, 0.0, 3.0, 0.2));
  const CanopyLight light(scene, clusters);
  std::vector<Eigen::Vector3d> points;
  std::vector<std::uint32_t> ignore;
  for (int i = 0; i < 200; ++i) {
    points.push_back({6 * u(rng), 6 * u(rng), 6 * u(rng)});
    ignore.push_back(i % 3 == 0 ? static_cast<std::uint32_t>(i) : kNoSphere);
  }
  std::vector<double> beam(points.size());
  int shaded = 0;
  for (const Eigen::Vector3d& sun :
       {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, -2, 1).normalized(),
        Eigen::Vector3d(-3, 1, 0.4).normalized()}) {
    light.transmission_along(points, sun, ignore, beam);
    for (std::size_t k = 0; k < points.size(); ++k) {
      EXPECT_NEAR(beam[k], light.transmission_along(points[k], sun, ignore[k]), 1e-12) << k;
      shaded += beam[k] < 0.99;
    }
  }
  EXPECT_GT(shaded, 100);
}

// The day through voxels (one sweep per direction) against the exact paths through the spheres:
// an open point gets the global radiation exactly; in a random crown beside a wall each point's
// daily PAR is within a few per cent of the open sky of the exact value, on average closer.
TEST(Daylight, ThroughVoxelsAgreesWithTheSpheres) {
  RealSky sky = summer_day();
  Scene open;
  open.sky.directions = 64;
  const std::vector<Eigen::Vector3d> far{{30, 30, 1}};
  const std::vector<Sphere> none;
  EXPECT_NEAR(daylight_through_voxels(none, open, sky, far, 0.5)[0].open_fraction, 1.0, 1e-6);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Sphere> clusters;
  for (int i = 0; i < 300; ++i) {
    const double r = 0.3 + 0.3 * u(rng);
    clusters.push_back({Eigen::Vector3d(6 * u(rng), 6 * u(rng), 1 + 5 * u(rng)), r,
                        cluster_translucency(r), false});
  }
  Scene scene = open;
  scene.boxes.push_back(Box::wall({7, -5}, {7, 10}, 0.0, 3.0, 0.2));
  const CanopyLight exact(scene, clusters);
  std::vector<Eigen::Vector3d> points;
  for (const Sphere& c : clusters) points.push_back(c.center);
  const auto e = daylight_at(exact, sky, points);
  const auto v = daylight_through_voxels(clusters, scene, sky, points, 0.5);
  double mae = 0.0, worst = 0.0, mean = 0.0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double d = std::abs(v[k].open_fraction - e[k].open_fraction);
    mae += d / static_cast<double>(points.size());
    mean += e[k].open_fraction / static_cast<double>(points.size());
    worst = std::max(worst, d);
  }
  std::printf(
      "daylight through 0.5 m voxels against the spheres: mean open fraction %.3f, "
      "mean |difference| %.3f, largest %.3f\n",
      mean, mae, worst);
  EXPECT_LT(mean, 0.7);  // the crown shades
  EXPECT_LT(mae, 0.06);
  EXPECT_LT(worst, 0.25);
}

}  // namespace
}  // namespace fspm::environment
