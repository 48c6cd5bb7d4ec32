#pragma once
// Charts for experiment reports, drawn with VTK's chart classes (vtkChartXY, vtkChartBox) in an
// offscreen context view and written through OpenImageIO, atomically. Only standard types in
// this header. Like the tree renders, VTK's OpenGL context needs an X display here (xvfb-run -a
// is enough).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "graphics/image.hpp"

namespace fspm::graphics {

struct ChartSeries {
  std::string name;  // legend entry
  std::vector<double> x, y;
  int color = -1;        // palette index (chart_color); -1: the series' own index
  bool dashed = false;   // a dashed line (e.g. mean ± standard deviation around a mean)
  bool markers = false;  // a dot at every point
  bool legend = true;    // listed in the legend, which is drawn when it lists several series
  bool line = true;      // false: dots only (values of a category axis are not a series)
};

struct ChartOptions {
  std::string title;
  std::string x_label;
  std::string y_label;
  int width = 800;
  int height = 600;
  // Ticks on the x axis at these positions with these labels (same length; e.g. the values of a
  // text parameter placed at 0, 1, 2); empty: VTK's own ticks.
  std::vector<double> x_ticks;
  std::vector<std::string> x_tick_labels;

  // Throws ValueError naming the field: a side outside 16..16384 pixels, or not one label per tick.
  void validate() const;
};

// The value axis of a chart whose values are all equal to v (to within 1e-9 of |v|): v ± 10 % of
// |v|, or [-0.1, 1] for v = 0, rather than the plotting library's range of about ±1e-7 around v,
// whose tick labels read as if the metric varied. Nothing when the values differ (or there are
// none): the library's own range then fits them.
std::optional<std::array<double, 2>> flat_value_range(const std::vector<double>& values);

// Colour of series (or box) i: the Tableau 10 palette, cycling (8-bit RGB).
std::array<unsigned char, 3> chart_color(std::size_t i);

// One line per series (points sorted as given), a legend when several are listed in it. Throws
// ValueError for no series, x ticks and labels of different lengths, x and y of different lengths,
// an empty or non-finite series, a bad size or an image format OpenImageIO does not write; IoError
// when no display can be opened or the file cannot be written (nothing is left half-written).
Image line_chart_image(const std::vector<ChartSeries>& series, const ChartOptions& options);
void write_line_chart(const std::vector<ChartSeries>& series, const ChartOptions& options,
                      const std::string& png_path);

// One box per group: whiskers at the minimum and maximum, box from the first to the third
// quartile (linear interpolation between order statistics, Hyndman and Fan type 7), a line at
// the median. Group names label the boxes. Throws like the line chart, and ValueError for a
// group without values or names not matching the groups.
Image box_plot_image(const std::vector<std::string>& group_names,
                     const std::vector<std::vector<double>>& groups, const ChartOptions& options);
void write_box_plot(const std::vector<std::string>& group_names,
                    const std::vector<std::vector<double>>& groups, const ChartOptions& options,
                    const std::string& png_path);

// Quantile q in [0, 1] of `values` by linear interpolation between order statistics (type 7,
// R's default). Throws ValueError when empty.
double quantile(std::vector<double> values, double q);

}  // namespace fspm::graphics
