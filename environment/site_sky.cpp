#include "environment/site_sky.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "environment/sky_distribution.hpp"
#include "fspm/closest_name.hpp"
#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "fspm/toml_text.hpp"

namespace fspm::environment {

Eigen::Vector3d mean_light_direction(const SiteSky& site_sky) {
  return sky_distribution(site_sky).mean_direction();
}

namespace {

[[noreturn]] void bad(const toml::node& n, const std::string& file, const std::string& what) {
  throw ValueError("sky: " + what, file, static_cast<int>(n.source().begin.line));
}

double number(const toml::node& table_node, const toml::table& t, const char* key,
              const std::string& file, std::optional<double> fallback, double lo, double hi) {
  const toml::node* n = t.get(key);
  if (n == nullptr) {
    if (fallback) return *fallback;
    bad(table_node, file, std::string("site.") + key + " is missing");
  }
  const auto v = n->value<double>();
  if (!v || !std::isfinite(*v) || *v < lo || *v > hi) {
    bad(*n, file,
        std::string("site.") + key + ": expected a number in [" + std::to_string(lo) + ", " +
            std::to_string(hi) + "]");
  }
  return *v;
}

void refuse_unknown(const toml::table& t, const std::string& prefix,
                    const std::vector<std::string>& known, const std::string& file) {
  for (auto&& [key, node] : t) {
    const std::string k(key.str());
    bool found = false;
    for (const std::string& name : known) found = found || name == k;
    if (!found) bad(node, file, unknown_key_message(prefix + k, k, known));
  }
}

}  // namespace

SiteSky parse_site_sky(const toml::node& node, const std::string& file) {
  const toml::table* t = node.as_table();
  if (t == nullptr) bad(node, file, "expected a table { site = {...}, date = ..., hours = ... }");
  refuse_unknown(*t, "sky.", {"site", "date", "hours", "days"}, file);
  SiteSky out;
  const toml::node* site = t->get("site");
  if (site == nullptr || !site->is_table()) bad(node, file, "expected site = { latitude, ... }");
  const toml::table& s = *site->as_table();
  refuse_unknown(s, "sky.site.", {"latitude", "longitude", "elevation", "utc_offset"}, file);
  out.sky.site.latitude_deg = number(*site, s, "latitude", file, std::nullopt, -90, 90);
  out.sky.site.longitude_deg = number(*site, s, "longitude", file, std::nullopt, -180, 180);
  out.sky.site.elevation_m = number(*site, s, "elevation", file, 0.0, -500, 9000);
  out.sky.site.utc_offset_h = number(*site, s, "utc_offset", file, 0.0, -14, 14);
  const toml::node* date = t->get("date");
  if (date == nullptr) bad(node, file, "date is missing (\"YYYY-MM-DD\")");
  if (const auto d = date->value<toml::date>()) {
    out.sky.date = {d->year, d->month, d->day};
  } else {
    try {
      out.sky.date = parse_date(date->value<std::string>().value_or(""));
    } catch (const ValueError& e) {
      bad(*date, file, std::string("date: ") + e.what());
    }
  }
  const toml::node* hours = t->get("hours");
  const toml::node* days = t->get("days");
  if (hours != nullptr && days != nullptr) bad(*days, file, "give hours or days, not both");
  if (hours != nullptr) {
    try {
      parse_hours(hours->value<std::string>().value_or(""), out.sky);
    } catch (const ValueError& e) {
      bad(*hours, file, std::string("hours: ") + e.what());
    }
  }
  if (days != nullptr) {
    const auto v = days->value<std::int64_t>();
    if (!v || *v < 1 || *v > 3660) bad(*days, file, "days: expected an integer in [1, 3660]");
    out.days = static_cast<int>(*v);
  }
  try {
    out.sky.validate();
  } catch (const ValueError& e) {
    bad(node, file, e.what());
  }
  return out;
}

SiteSky parse_site_sky_text(std::string_view text, const std::string& file) {
  const toml::table table = parse_toml_text(text, file);
  refuse_unknown(table, "", {"sky"}, file);
  const toml::node* sky = table.get("sky");
  if (sky == nullptr) throw ValueError("expected a table sky = { site = {...}, date, ... }", file);
  return parse_site_sky(*sky, file);
}

SiteSky read_site_sky_file(const std::string& path) {
  return parse_site_sky_text(read_text_input_file(path), path);
}

}  // namespace fspm::environment
