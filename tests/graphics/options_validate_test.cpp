// The graphics option structs check themselves the one way: validate() accepts the defaults and
// throws ValueError whose message names the field out of range.
#include <gtest/gtest.h>

#include <string>

#include "fspm/error.hpp"
#include "graphics/chart_figure.hpp"
#include "graphics/foliage.hpp"
#include "graphics/impostor.hpp"
#include "graphics/instance_lod.hpp"
#include "graphics/poisson_disk.hpp"
#include "graphics/render.hpp"
#include "graphics/tessellation_level.hpp"
#include "graphics/tree_mesher.hpp"
#include "graphics/viewer.hpp"
#include "graphics/wind_animation.hpp"
#include "tests/validate_refusal.hpp"

namespace fspm::graphics {
namespace {

using test_support::refusal;

#define EXPECT_REFUSED_NAMING(options, field)                                   \
  do {                                                                          \
    const std::string message = refusal(options);                               \
    EXPECT_NE(message.find(field), std::string::npos) << "'" << message << "'"; \
  } while (false)

TEST(OptionsValidate, DefaultsPass) {
  EXPECT_NO_THROW(MeshOptions{}.validate());
  EXPECT_NO_THROW(FoliageOptions{}.validate());
  EXPECT_NO_THROW(WindOptions{}.validate());
  EXPECT_NO_THROW(LodOptions{}.validate());
  EXPECT_NO_THROW(ImpostorViews{}.validate());
  EXPECT_NO_THROW(TessellationLimits{}.validate());
  EXPECT_NO_THROW(ChartOptions{}.validate());
  EXPECT_NO_THROW(RenderOptions{}.validate());
}

TEST(OptionsValidate, EachRefusalNamesItsField) {
  MeshOptions mesh;
  mesh.edge_length_m = 0.0;
  EXPECT_REFUSED_NAMING(mesh, "edge_length_m");
  mesh = {};
  mesh.axis_subdivisions = 0;
  EXPECT_REFUSED_NAMING(mesh, "axis_subdivisions");
  mesh = {};
  mesh.leaves = true;
  mesh.foliage.sphere_stacks = 1;  // the foliage is checked with leaves on
  EXPECT_REFUSED_NAMING(mesh, "sphere_stacks");

  FoliageOptions foliage;
  foliage.leaves_per_cluster = 0;
  EXPECT_REFUSED_NAMING(foliage, "leaves_per_cluster");

  WindOptions wind;
  wind.bias = 1.5;
  EXPECT_REFUSED_NAMING(wind, "bias");
  wind = {};
  wind.amplitude_rad = -0.1;
  EXPECT_REFUSED_NAMING(wind, "amplitude_rad");

  LodOptions lod;
  lod.jitter = 1.0;
  EXPECT_REFUSED_NAMING(lod, "jitter");
  lod = {};
  lod.leaf_fractions = {1.0, 0.5, 0.75};
  EXPECT_REFUSED_NAMING(lod, "leaf_fractions");

  ImpostorViews views;
  views.azimuths = 2;
  EXPECT_REFUSED_NAMING(views, "azimuths");

  TessellationLimits limits;
  limits.max_face_area_m2 = 0.0;
  EXPECT_REFUSED_NAMING(limits, "max_face_area_m2");

  ChartOptions chart;
  chart.x_ticks = {0.0, 1.0};
  chart.x_tick_labels = {"a"};
  EXPECT_REFUSED_NAMING(chart, "x_tick_labels");

  RenderOptions render;
  render.height = 0;
  EXPECT_REFUSED_NAMING(render, "height");

  PoissonDiskOptions disk;
  disk.width_m = 10.0;
  disk.depth_m = 10.0;
  disk.min_distance_m = 0.0;
  EXPECT_REFUSED_NAMING(disk, "min_distance_m");
}

TEST(OptionsValidate, ViewerOptionsNameTheField) {
  EXPECT_NO_THROW(ViewerOptions{}.validate());
  ViewerOptions o;
  o.height = 0;
  EXPECT_REFUSED_NAMING(o, "height");
  o = ViewerOptions{};
  o.frames = 0;
  EXPECT_REFUSED_NAMING(o, "frames");
  o = ViewerOptions{};
  o.shadow_cascades = kMaxShadowCascades + 1;
  EXPECT_REFUSED_NAMING(o, "shadow_cascades");
  o.shadow_cascades = kMaxShadowCascades;
  EXPECT_NO_THROW(o.validate());
  o.camera_distance_m = -1.0;
  EXPECT_REFUSED_NAMING(o, "camera_distance_m");
}

}  // namespace
}  // namespace fspm::graphics
