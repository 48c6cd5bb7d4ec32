#include "graphics/chart_figure.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include "fspm/error.hpp"
#include "graphics/render.hpp"

namespace fspm::graphics {
namespace {

namespace fs = std::filesystem;

TEST(ChartFigure, QuantilesMatchTypeSeven) {
  // R: quantile(c(7, 1, 3, 5), c(0, .25, .5, .75, 1)) = 1, 2.5, 4, 5.5, 7.
  const std::vector<double> v = {7, 1, 3, 5};
  EXPECT_DOUBLE_EQ(quantile(v, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(quantile(v, 0.25), 2.5);
  EXPECT_DOUBLE_EQ(quantile(v, 0.5), 4.0);
  EXPECT_DOUBLE_EQ(quantile(v, 0.75), 5.5);
  EXPECT_DOUBLE_EQ(quantile(v, 1.0), 7.0);
  EXPECT_DOUBLE_EQ(quantile({2.0}, 0.3), 2.0);
  EXPECT_THROW(quantile({}, 0.5), ValueError);
  EXPECT_THROW(quantile(v, 1.5), ValueError);
}

// A metric equal in every run (a count fixed by the parameters, say) gets an axis of its value
// ± 10 %, worked out by hand here; differing values keep the plotting library's range.
TEST(ChartFigure, AllEqualValuesGetAnAxisOfTheValuePlusMinusTenPercent) {
  const auto a = flat_value_range({125.0, 125.0, 125.0});
  ASSERT_TRUE(a.has_value());
  EXPECT_DOUBLE_EQ((*a)[0], 112.5);  // 125 - 12.5
  EXPECT_DOUBLE_EQ((*a)[1], 137.5);
  const auto b = flat_value_range({-2.0, -2.0});
  ASSERT_TRUE(b.has_value());
  EXPECT_DOUBLE_EQ((*b)[0], -2.2);
  EXPECT_DOUBLE_EQ((*b)[1], -1.8);
  const auto zero = flat_value_range({0.0, 0.0, 0.0});
  ASSERT_TRUE(zero.has_value());
  EXPECT_EQ((*zero)[0], -0.1);  // the line clear of the frame, no negative counts labelled
  EXPECT_EQ((*zero)[1], 1.0);
  // Rounding noise (a mean of equal values) still counts as equal: 0.3 = 0.1 + 0.2 + 4e-17.
  const auto noisy = flat_value_range({0.3, 0.1 + 0.2});
  ASSERT_TRUE(noisy.has_value());
  EXPECT_NEAR((*noisy)[0], 0.27, 1e-12);
  EXPECT_NEAR((*noisy)[1], 0.33, 1e-12);
  EXPECT_FALSE(flat_value_range({1.0, 1.001}).has_value());
  EXPECT_FALSE(flat_value_range({}).has_value());
}

TEST(ChartFigure, BadInputIsValueErrorBeforeAnyRendering) {
  const ChartOptions o;
  EXPECT_THROW(line_chart_image({}, o), ValueError);
  EXPECT_THROW(line_chart_image({{"a", {1, 2}, {1}}}, o), ValueError);
  EXPECT_THROW(line_chart_image({{"a", {}, {}}}, o), ValueError);
  EXPECT_THROW(line_chart_image({{"a", {1, 2}, {1, NAN}}}, o), ValueError);
  EXPECT_THROW(box_plot_image({"a"}, {{1.0}, {2.0}}, o), ValueError);
  EXPECT_THROW(box_plot_image({"a"}, {{}}, o), ValueError);
  ChartOptions tiny;
  tiny.width = 2;
  EXPECT_THROW(line_chart_image({{"a", {1, 2}, {1, 2}}}, tiny), ValueError);
  ChartOptions ticks;
  ticks.x_ticks = {1, 2};
  ticks.x_tick_labels = {"one"};  // a label short
  EXPECT_THROW(line_chart_image({{"a", {1, 2}, {1, 2}}}, ticks), ValueError);
}

// Pixels of each palette colour (within a tolerance) and pixels that are not background white.
struct Census {
  std::size_t non_background = 0;
  std::vector<std::size_t> per_color;
};

Census census(const Image& image, std::size_t colors) {
  Census c;
  c.per_color.assign(colors, 0);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const auto* p = image.pixel(x, y);
      if (p[0] < 245 || p[1] < 245 || p[2] < 245) ++c.non_background;
      for (std::size_t i = 0; i < colors; ++i) {
        const auto k = chart_color(i);
        if (std::abs(p[0] - k[0]) < 30 && std::abs(p[1] - k[1]) < 30 &&
            std::abs(p[2] - k[2]) < 30) {
          ++c.per_color[i];
        }
      }
    }
  }
  return c;
}

class Charts : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!render_available()) GTEST_SKIP() << "built without VTK";
    if (!display_available()) GTEST_SKIP() << "no X display (run under xvfb-run -a)";
    dir_ = fs::temp_directory_path() / ("fspm_chart_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }
  fs::path dir_;
};

TEST_F(Charts, LineChartDrawsEachSeriesInItsOwnColour) {
  std::vector<ChartSeries> series(3);
  for (int s = 0; s < 3; ++s) {
    series[s].name = "run " + std::to_string(s);
    for (int i = 0; i <= 50; ++i) {
      series[s].x.push_back(i);
      series[s].y.push_back(std::sin(0.2 * i + s) + 3.0 * s);  // apart, so none hides another
    }
  }
  ChartOptions o;
  o.title = "Growth";
  o.x_label = "cycle";
  o.y_label = "metamers";
  o.width = 480;
  o.height = 360;
  const std::string png = (dir_ / "lines.png").string();
  write_line_chart(series, o, png);
  const Image image = read_image(png);
  ASSERT_EQ(image.width, 480);
  ASSERT_EQ(image.height, 360);
  const Census c = census(image, 3);
  EXPECT_GT(c.non_background, 2000u);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_GT(c.per_color[i], 150u) << "series " << i;
  // A colour no series uses stays absent.
  EXPECT_LT(census(image, 5).per_color[4], 20u);
  EXPECT_THROW(write_line_chart(series, o, (dir_ / "missing/x.png").string()), IoError);
  EXPECT_FALSE(fs::exists(dir_ / "missing"));
}

// A flat line at 125 on the axis [112.5, 137.5] lies in the middle of the plot's height, and its
// colour fills a horizontal run of pixels in one row band.
TEST_F(Charts, ConstantSeriesIsDrawnAsAFlatLineInTheMiddle) {
  ChartSeries flat{"flat", {10, 20, 30}, {125, 125, 125}, 0, false, true, false};
  ChartOptions o;
  o.title = "leaves (count)";
  o.width = 420;
  o.height = 300;
  const std::string png = (dir_ / "flat.png").string();
  write_line_chart({flat}, o, png);
  const Image image = read_image(png);
  const auto k = chart_color(0);
  int top = image.height, bottom = -1;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const auto* p = &image.rgba[4 * (static_cast<std::size_t>(y) * image.width + x)];
      if (std::abs(p[0] - k[0]) < 30 && std::abs(p[1] - k[1]) < 30 && std::abs(p[2] - k[2]) < 30) {
        top = std::min(top, y);
        bottom = std::max(bottom, y);
      }
    }
  }
  ASSERT_GE(bottom, 0) << "no line drawn";
  EXPECT_LT(bottom - top, 20);  // one line with its dots, not a zigzag
  const double middle = 0.5 * (top + bottom) / image.height;
  EXPECT_GT(middle, 0.3);
  EXPECT_LT(middle, 0.7);
}

TEST_F(Charts, BoxPlotDrawsOneColouredBoxPerGroup) {
  std::vector<std::vector<double>> groups(2);
  for (int i = 0; i < 40; ++i) {
    groups[0].push_back(1.0 + 0.05 * i);
    groups[1].push_back(4.0 + 0.1 * (i % 13));
  }
  ChartOptions o;
  o.title = "Edit distance";
  o.y_label = "distance";
  o.width = 400;
  o.height = 300;
  const std::string png = (dir_ / "box.png").string();
  write_box_plot({"T-G", "G-G"}, groups, o, png);
  const Image image = read_image(png);
  ASSERT_EQ(image.width, 400);
  const Census c = census(image, 2);
  EXPECT_GT(c.non_background, 2000u);
  EXPECT_GT(c.per_color[0], 200u);
  EXPECT_GT(c.per_color[1], 200u);
}

}  // namespace
}  // namespace fspm::graphics
