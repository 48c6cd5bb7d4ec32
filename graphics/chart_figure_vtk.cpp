// VTK charts rendered off screen: a vtkContextView holding a vtkChartXY (lines) or a vtkChartBox
// (box plots), its window rendered off screen on the X display and read back.
#include <vtkAxis.h>
#include <vtkChartBox.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotBox.h>
#include <vtkPlotPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "fspm/error.hpp"
#include "graphics/chart_figure.hpp"
#include "graphics/vtk_window_image.hpp"
#include "graphics/x_display.hpp"

namespace fspm::graphics {
namespace {

void check_finite(const std::vector<double>& v, const std::string& what) {
  for (double x : v) {
    if (!std::isfinite(x)) throw ValueError(what + " has a value that is not a finite number");
  }
}

// Renders `view` off screen at the options' size and reads it back (rows from the top).
template <typename Fill>
Image render_chart(const ChartOptions& o, Fill&& fill) {
  struct DisplayGuard {
    void* display = open_x_display();
    ~DisplayGuard() { close_x_display(display); }
  } x;
  if (x.display == nullptr) {
    throw IoError(
        "no X display for VTK's offscreen OpenGL context (DISPLAY unset or unreachable); run "
        "under a virtual server: xvfb-run -a ...");
  }
  vtkNew<vtkContextView> view;
  vtkRenderWindow* window = view->GetRenderWindow();
  window->SetDisplayId(x.display);
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(o.width, o.height);
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  fill(view.Get());
  window->Render();

  return window_image(window);
}

void style_title(vtkChart* chart, const std::string& title) {
  chart->SetTitle(title);
  chart->GetTitleProperties()->SetFontSize(16);
  chart->GetTitleProperties()->SetBold(true);
  chart->GetTitleProperties()->SetColor(0.1, 0.1, 0.1);
}

// All values equal: the axis spans flat_value_range instead of VTK's ±1e-7 around them.
void fix_flat_axis(vtkAxis* axis, const std::vector<double>& values) {
  const auto range = flat_value_range(values);
  if (!range) return;
  axis->SetBehavior(vtkAxis::FIXED);
  axis->SetRange((*range)[0], (*range)[1]);
}

}  // namespace

Image line_chart_image(const std::vector<ChartSeries>& series, const ChartOptions& o) {
  if (series.empty()) throw ValueError("a line chart needs at least one series");
  for (const auto& s : series) {
    if (s.x.size() != s.y.size()) {
      throw ValueError("series '" + s.name + "' has " + std::to_string(s.x.size()) + " x and " +
                       std::to_string(s.y.size()) + " y values");
    }
    if (s.x.empty()) throw ValueError("series '" + s.name + "' has no points");
    check_finite(s.x, "series '" + s.name + "'");
    check_finite(s.y, "series '" + s.name + "'");
  }
  o.validate();
  return render_chart(o, [&](vtkContextView* view) {
    vtkNew<vtkChartXY> chart;
    if (!o.x_ticks.empty()) {
      vtkNew<vtkDoubleArray> positions;
      vtkNew<vtkStringArray> labels;
      for (std::size_t i = 0; i < o.x_ticks.size(); ++i) {
        positions->InsertNextValue(o.x_ticks[i]);
        labels->InsertNextValue(o.x_tick_labels[i]);
      }
      vtkAxis* axis = chart->GetAxis(vtkAxis::BOTTOM);
      axis->SetCustomTickPositions(positions, labels);
      // Half a step of room on either side, so the first and last points are not on the frame.
      const auto [lo, hi] = std::minmax_element(o.x_ticks.begin(), o.x_ticks.end());
      const double pad = o.x_ticks.size() > 1 ? 0.5 * (*hi - *lo) / (o.x_ticks.size() - 1) : 0.5;
      axis->SetBehavior(vtkAxis::FIXED);
      axis->SetRange(*lo - pad, *hi + pad);
    }
    view->GetScene()->AddItem(chart);
    style_title(chart, o.title);
    std::vector<double> values;
    for (const ChartSeries& s : series) values.insert(values.end(), s.y.begin(), s.y.end());
    fix_flat_axis(chart->GetAxis(vtkAxis::LEFT), values);
    chart->GetAxis(vtkAxis::BOTTOM)->SetTitle(o.x_label);
    chart->GetAxis(vtkAxis::LEFT)->SetTitle(o.y_label);
    const auto listed =
        std::count_if(series.begin(), series.end(), [](const ChartSeries& s) { return s.legend; });
    chart->SetShowLegend(listed > 1);
    if (listed > 1) chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
    for (std::size_t i = 0; i < series.size(); ++i) {
      const ChartSeries& s = series[i];
      vtkNew<vtkTable> table;
      vtkNew<vtkDoubleArray> x, y;
      x->SetName("x");
      y->SetName(s.name.empty() ? ("series " + std::to_string(i + 1)).c_str() : s.name.c_str());
      table->AddColumn(x);
      table->AddColumn(y);
      table->SetNumberOfRows(static_cast<vtkIdType>(s.x.size()));
      for (std::size_t k = 0; k < s.x.size(); ++k) {
        table->SetValue(static_cast<vtkIdType>(k), 0, s.x[k]);
        table->SetValue(static_cast<vtkIdType>(k), 1, s.y[k]);
      }
      vtkPlot* line = chart->AddPlot(s.line ? vtkChart::LINE : vtkChart::POINTS);
      line->SetInputData(table, 0, 1);
      const auto c = chart_color(s.color >= 0 ? static_cast<std::size_t>(s.color) : i);
      line->SetColor(c[0], c[1], c[2], 255);
      line->SetWidth(s.dashed ? 1.5 : 2.5);
      if (s.dashed) line->GetPen()->SetLineType(vtkPen::DASH_LINE);
      line->SetLegendVisibility(s.legend);
      if (auto* points = vtkPlotPoints::SafeDownCast(line);
          points != nullptr && (s.markers || !s.line)) {
        points->SetMarkerStyle(vtkPlotPoints::CIRCLE);
        points->SetMarkerSize(8.0);
      }
    }
  });
}

Image box_plot_image(const std::vector<std::string>& group_names,
                     const std::vector<std::vector<double>>& groups, const ChartOptions& o) {
  if (groups.empty()) throw ValueError("a box plot needs at least one group");
  if (group_names.size() != groups.size()) {
    throw ValueError("box plot: " + std::to_string(group_names.size()) + " names for " +
                     std::to_string(groups.size()) + " groups");
  }
  for (std::size_t i = 0; i < groups.size(); ++i) {
    if (groups[i].empty()) throw ValueError("box plot group '" + group_names[i] + "' is empty");
    check_finite(groups[i], "box plot group '" + group_names[i] + "'");
  }
  o.validate();
  // vtkChartBox draws columns of five rows: minimum, first quartile, median, third quartile,
  // maximum.
  vtkNew<vtkTable> quartiles;
  vtkNew<vtkStringArray> labels;
  for (std::size_t i = 0; i < groups.size(); ++i) {
    vtkNew<vtkDoubleArray> column;
    const std::string name =
        group_names[i].empty() ? "group " + std::to_string(i + 1) : group_names[i];
    column->SetName(name.c_str());
    for (double q : {0.0, 0.25, 0.5, 0.75, 1.0}) column->InsertNextValue(quantile(groups[i], q));
    quartiles->AddColumn(column);
    labels->InsertNextValue(name);
  }
  return render_chart(o, [&](vtkContextView* view) {
    vtkNew<vtkChartBox> chart;
    view->GetScene()->AddItem(chart);
    style_title(chart, o.title);
    auto* box = vtkPlotBox::SafeDownCast(chart->GetPlot(0));
    box->SetInputData(quartiles);
    chart->SetColumnVisibilityAll(true);
    for (std::size_t i = 0; i < groups.size(); ++i) {
      const auto c = chart_color(i);
      double rgb[3] = {c[0] / 255.0, c[1] / 255.0, c[2] / 255.0};
      box->SetColumnColor(labels->GetValue(static_cast<vtkIdType>(i)), rgb);
    }
    box->SetLabels(labels);
    chart->GetYAxis()->SetTitle(o.y_label);
    std::vector<double> values;
    for (const auto& g : groups) values.insert(values.end(), g.begin(), g.end());
    fix_flat_axis(chart->GetYAxis(), values);
    chart->SetShowLegend(true);
  });
}

}  // namespace fspm::graphics
