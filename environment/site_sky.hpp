#pragma once
// A real sky for the growth and adaptation light models: the sun at a site over some hours of a
// day or over whole days (solar_position.hpp, clear-sky radiation split into direct and diffuse,
// sky_radiation.hpp). The light models that weight sky directions take its light per direction
// (sky_distribution.hpp); what takes one direction takes the direction its light comes from on
// average,
//
//   b = normalise( sum_t [ S_b(t) s(t) + S_d(t) m_d(t) ] ),
//
// S_b, S_d the direct and diffuse irradiance on a horizontal plane, s the sun's direction, m_d the
// diffuse sky's mean direction (radiance times cos theta). In the northern hemisphere b leans to
// the south, the more so the higher the latitude; at night-only hours it is the zenith.
#include <toml++/toml.h>
#include <Eigen/Core>
#include <string>
#include <string_view>

#include "environment/daylight.hpp"

namespace fspm::environment {

struct SiteSky {
  RealSky sky;   // site, date and hours (first_hour .. last_hour) of one day
  int days = 0;  // > 0: whole days from sky.date instead of the hours
};

// The mean light direction above (a unit vector, z > 0). Throws ValueError for an invalid sky.
Eigen::Vector3d mean_light_direction(const SiteSky& sky);

// The parameter-file table `sky = { site = { latitude, longitude, elevation[, utc_offset] },
// date = "YYYY-MM-DD", hours = "FROM:TO" | days = N }` (hours default to the whole day). Throws
// ValueError naming `file` and the line for a missing or bad field or an unknown key.
SiteSky parse_site_sky(const toml::node& node, const std::string& file);

// A TOML file holding only that table (`sky = { ... }`, or a [sky] section); throws IoError or
// ValueError naming the file.
SiteSky read_site_sky_file(const std::string& path);
// The same from the file's text, `file` naming it in messages.
SiteSky parse_site_sky_text(std::string_view text, const std::string& file);

}  // namespace fspm::environment
