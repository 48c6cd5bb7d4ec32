#include "environment/solar_position.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "fspm/error.hpp"

namespace fspm::environment {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

double wrap360(double a) {
  a = std::fmod(a, 360.0);
  return a < 0.0 ? a + 360.0 : a;
}

}  // namespace

void Site::validate() const {
  if (!(std::abs(latitude_deg) <= 90.0)) {
    throw ValueError("site: latitude_deg must be in [-90, 90], got " +
                     std::to_string(latitude_deg));
  }
  if (!std::isfinite(longitude_deg)) throw ValueError("site: longitude_deg must be finite");
  if (!std::isfinite(elevation_m)) throw ValueError("site: elevation_m must be finite");
  if (!std::isfinite(utc_offset_h)) throw ValueError("site: utc_offset_h must be finite");
}

void CalendarDate::validate() const {
  if (year < 1950 || year > 2050) {
    throw ValueError(
        "date: year must be in 1950-2050 (the solar position's range, Michalsky 1988), got " +
        std::to_string(year));
  }
  if (month < 1 || month > 12) {
    throw ValueError("date: month must be in 1-12, got " + std::to_string(month));
  }
  if (day < 1 || day > 31)
    throw ValueError("date: day must be in 1-31, got " + std::to_string(day));
}

Eigen::Vector3d SolarPosition::direction() const {
  const double z = zenith_deg * kDeg, a = azimuth_deg * kDeg;
  return {std::sin(z) * std::sin(a), std::sin(z) * std::cos(a), std::cos(z)};
}

double standard_pressure_hpa(double elevation_m) {
  return 1013.25 * std::pow(1.0 - 2.25577e-5 * elevation_m, 5.25588);
}

int day_of_year(const CalendarDate& date) {
  static constexpr int kBefore[12] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
  const bool leap = (date.year % 4 == 0 && date.year % 100 != 0) || date.year % 400 == 0;
  return kBefore[date.month - 1] + date.day + (leap && date.month > 2 ? 1 : 0);
}

double julian_day(const CalendarDate& date, double hour_ut) {
  int y = date.year, m = date.month;
  if (m <= 2) y -= 1, m += 12;
  const int a = y / 100;
  const int b = 2 - a + a / 4;
  return std::floor(365.25 * (y + 4716)) + std::floor(30.6001 * (m + 1)) + date.day + b - 1524.5 +
         hour_ut / 24.0;
}

SolarPosition solar_position(const Site& site, const CalendarDate& date, double local_hour,
                             double pressure_hpa, double temperature_c) {
  site.validate();
  date.validate();
  const double hour_ut = local_hour - site.utc_offset_h;
  // Michalsky (1988): ecliptic coordinates from the days since J2000.0 (n, fraction included).
  const double n = julian_day(date, hour_ut) - 2451545.0;
  const double mean_longitude = wrap360(280.460 + 0.9856474 * n);
  const double g = wrap360(357.528 + 0.9856003 * n) * kDeg;  // mean anomaly
  const double lambda = (mean_longitude + 1.915 * std::sin(g) + 0.020 * std::sin(2.0 * g)) * kDeg;
  const double epsilon = (23.439 - 0.0000004 * n) * kDeg;
  const double ra = std::atan2(std::cos(epsilon) * std::sin(lambda), std::cos(lambda));
  const double dec = std::asin(std::sin(epsilon) * std::sin(lambda));
  // Greenwich mean sidereal time (hours); n already holds the fraction of the day.
  const double gmst = std::fmod(6.697375 + 0.0657098242 * n + hour_ut, 24.0);
  const double lmst = gmst + site.longitude_deg / 15.0;
  const double hour_angle = lmst * 15.0 * kDeg - ra;
  const double lat = site.latitude_deg * kDeg;
  const double sin_el =
      std::sin(dec) * std::sin(lat) + std::cos(dec) * std::cos(lat) * std::cos(hour_angle);
  const double el = std::asin(std::clamp(sin_el, -1.0, 1.0));
  const double az = std::atan2(
      -std::sin(hour_angle) * std::cos(dec),
      std::sin(dec) * std::cos(lat) - std::cos(dec) * std::sin(lat) * std::cos(hour_angle));
  // Topocentric: the parallax of the sun's mean distance (8.794 arcsec) lowers it.
  double e0 = el / kDeg - 8.794 / 3600.0 * std::cos(el);
  // Refraction (Reda and Andreas 2004, eq. 42), only for a sun above the horizon.
  const double p = pressure_hpa > 0.0 ? pressure_hpa : standard_pressure_hpa(site.elevation_m);
  if (e0 > -0.26667 - 0.5667) {
    e0 += p / 1010.0 * 283.0 / (273.0 + temperature_c) * 1.02 /
          (60.0 * std::tan((e0 + 10.3 / (e0 + 5.11)) * kDeg));
  }
  SolarPosition out;
  out.zenith_deg = 90.0 - e0;
  out.azimuth_deg = wrap360(az / kDeg);
  out.declination_deg = dec / kDeg;
  return out;
}

}  // namespace fspm::environment
