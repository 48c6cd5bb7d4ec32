#pragma once
// The sun's position at a site and time: the Astronomical Almanac's low-precision algorithm as
// Michalsky (1988) gives it (valid 1950-2050, stated accuracy 0.01 degree), with the topocentric
// parallax and the atmospheric refraction of the NREL solar position algorithm (Reda and Andreas
// 2004, eq. 38-42). Directions: z up, x east, y north; azimuth clockwise from north.
#include <Eigen/Core>

namespace fspm::environment {

struct Site {
  double latitude_deg = 0.0;   // north positive
  double longitude_deg = 0.0;  // east positive
  double elevation_m = 0.0;    // above sea level
  double utc_offset_h = 0.0;   // local clock time minus UTC (Golden, Colorado: -7)
  // Throws ValueError naming the field: a latitude beyond +-90, a non-finite value.
  void validate() const;
};

struct CalendarDate {
  int year = 2000;
  int month = 1;  // 1..12
  int day = 1;    // 1..31
  // Throws ValueError naming the field: a year outside 1950-2050 (the solar position's range),
  // a month outside 1-12 or a day outside 1-31.
  void validate() const;
};

struct SolarPosition {
  double zenith_deg = 90.0;  // topocentric, refraction included
  double azimuth_deg = 0.0;  // clockwise from north
  double declination_deg = 0.0;
  Eigen::Vector3d direction() const;  // unit vector to the sun
  double elevation_deg() const { return 90.0 - zenith_deg; }
};

// Air pressure of the standard atmosphere at an elevation (hPa = mbar; ICAO 1993).
double standard_pressure_hpa(double elevation_m);

// Day of the year (1..366) of a date; Julian day of a date at `hour_ut` (Meeus 1991, ch. 7).
int day_of_year(const CalendarDate& date);
double julian_day(const CalendarDate& date, double hour_ut);

// The sun at local clock time `local_hour` (0..24) of `date`. Pressure and temperature set the
// refraction (defaults: the standard atmosphere at the site's elevation, 10 degrees C).
// Throws ValueError for a date outside 1950-2050, a latitude beyond +-90 or a bad month/day.
SolarPosition solar_position(const Site& site, const CalendarDate& date, double local_hour,
                             double pressure_hpa = -1.0, double temperature_c = 10.0);

}  // namespace fspm::environment
