// The parts of the charts that need no VTK: validation, palette, quantiles, writing.
#include "graphics/chart_figure.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "fspm/error.hpp"

namespace fspm::graphics {

void ChartOptions::validate() const {
  if (width < 16 || height < 16 || width > 16384 || height > 16384) {
    throw ValueError("chart: width and height must be 16..16384 pixels");
  }
  if (x_ticks.size() != x_tick_labels.size()) {
    throw ValueError("chart: " + std::to_string(x_tick_labels.size()) + " x_tick_labels for " +
                     std::to_string(x_ticks.size()) + " x_ticks");
  }
}

std::array<unsigned char, 3> chart_color(std::size_t i) {
  static constexpr unsigned char kTableau10[10][3] = {
      {31, 119, 180}, {255, 127, 14},  {44, 160, 44},   {214, 39, 40},  {148, 103, 189},
      {140, 86, 75},  {227, 119, 194}, {127, 127, 127}, {188, 189, 34}, {23, 190, 207}};
  const auto* c = kTableau10[i % 10];
  return {c[0], c[1], c[2]};
}

std::optional<std::array<double, 2>> flat_value_range(const std::vector<double>& values) {
  if (values.empty()) return std::nullopt;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  const double v = 0.5 * (*lo + *hi);
  if (*hi - *lo > 1e-9 * std::abs(v)) return std::nullopt;
  // A margin of a tenth of the value keeps the line clear of the frame and the ticks readable
  // as the value itself (120, 130 for 125), not as its noise.
  // A metric that is always 0 is most often a count (leaves of a leafless plant): up to 1, and
  // only a tenth below 0, so the line shows above the frame without negative tick labels.
  if (v == 0.0) return std::array<double, 2>{-0.1, 1.0};
  const double margin = 0.1 * std::abs(v);
  return std::array<double, 2>{v - margin, v + margin};
}

double quantile(std::vector<double> values, double q) {
  if (values.empty()) throw ValueError("quantile of no values");
  if (!(q >= 0.0 && q <= 1.0)) throw ValueError("quantile must be in [0, 1]");
  std::sort(values.begin(), values.end());
  // Hyndman and Fan (1996) type 7: h = (n - 1) q, interpolate between floor(h) and ceil(h).
  const double h = (static_cast<double>(values.size()) - 1.0) * q;
  const auto lo = static_cast<std::size_t>(std::floor(h));
  const std::size_t hi = std::min(lo + 1, values.size() - 1);
  return values[lo] + (h - static_cast<double>(lo)) * (values[hi] - values[lo]);
}

void write_line_chart(const std::vector<ChartSeries>& series, const ChartOptions& options,
                      const std::string& png_path) {
  check_image_path(png_path);
  write_image(line_chart_image(series, options), png_path);
}

void write_box_plot(const std::vector<std::string>& group_names,
                    const std::vector<std::vector<double>>& groups, const ChartOptions& options,
                    const std::string& png_path) {
  check_image_path(png_path);
  write_image(box_plot_image(group_names, groups, options), png_path);
}

}  // namespace fspm::graphics
