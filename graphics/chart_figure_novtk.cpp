#include "fspm/error.hpp"
#include "graphics/chart_figure.hpp"

namespace fspm::graphics {

Image line_chart_image(const std::vector<ChartSeries>&, const ChartOptions&) {
  throw ValueError("fspm was built without VTK (FSPM_WITH_VTK=OFF): charts are not available");
}

Image box_plot_image(const std::vector<std::string>&, const std::vector<std::vector<double>>&,
                     const ChartOptions&) {
  throw ValueError("fspm was built without VTK (FSPM_WITH_VTK=OFF): charts are not available");
}

}  // namespace fspm::graphics
