// VTK offscreen rendering of a TriangleMesh. The window is created off screen on the current X
// display (a virtual one from xvfb-run is enough) and read back into an Image.
#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkGlyph3DMapper.h>
#include <vtkIdTypeArray.h>
#include <vtkImageData.h>
#include <vtkLightKit.h>
#include <vtkLookupTable.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty.h>
#include <vtkProperty2D.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <numbers>
#include <span>
#include <sstream>
#include <vector>

#include "fspm/error.hpp"
#include "graphics/attribute_title.hpp"
#include "graphics/instance_lod.hpp"
#include "graphics/relief_composite.hpp"
#include "graphics/render.hpp"
#include "graphics/vtk_window_image.hpp"
#include "graphics/x_display.hpp"

namespace fspm::graphics {
namespace {

// The material colour as 8-bit RGB (bark 115 82 51, leaf 64 140 38).
std::array<unsigned char, 3> material_rgb(Material material) {
  const std::array<float, 3> c = material_color(material);
  std::array<unsigned char, 3> rgb;
  for (int k = 0; k < 3; ++k) rgb[k] = static_cast<unsigned char>(std::lround(255.0f * c[k]));
  return rgb;
}

// A mesh with vertex colours (a crown from a photograph): each triangle the mean of its corners'
// colours, corners without one taking their material's.
void set_vertex_colored_cells(const TriangleMesh& mesh, vtkUnsignedCharArray* colors) {
  const std::vector<std::array<float, 3>> vertex = resolved_vertex_colors(mesh);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    std::array<unsigned char, 3> rgb;
    for (int k = 0; k < 3; ++k) {
      float sum = 0.0f;
      for (const std::uint32_t v : mesh.triangles[t]) sum += vertex[v][k];
      rgb[k] = static_cast<unsigned char>(std::lround(255.0f * std::clamp(sum / 3.0f, 0.0f, 1.0f)));
    }
    colors->SetTypedTuple(static_cast<vtkIdType>(t), rgb.data());
  }
}

vtkNew<vtkPolyData> to_polydata(const TriangleMesh& mesh, const std::string& color_by) {
  vtkNew<vtkPolyData> poly;
  const auto nv = static_cast<vtkIdType>(mesh.vertex_count());
  const auto nt = static_cast<vtkIdType>(mesh.triangle_count());
  vtkNew<vtkFloatArray> xyz;
  xyz->SetNumberOfComponents(3);
  xyz->SetNumberOfTuples(nv);
  std::memcpy(xyz->GetPointer(0), mesh.positions.data(), sizeof(float) * 3 * nv);
  vtkNew<vtkPoints> points;
  points->SetData(xyz);
  poly->SetPoints(points);

  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(nt + 1);
  connectivity->SetNumberOfTuples(3 * nt);
  for (vtkIdType t = 0; t <= nt; ++t) offsets->SetValue(t, 3 * t);
  for (vtkIdType t = 0; t < nt; ++t) {
    for (int k = 0; k < 3; ++k) connectivity->SetValue(3 * t + k, mesh.triangles[t][k]);
  }
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  poly->SetPolys(cells);

  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(nv);
  std::memcpy(normals->GetPointer(0), mesh.normals.data(), sizeof(float) * 3 * nv);
  poly->GetPointData()->SetNormals(normals);

  if (!color_by.empty()) {
    const auto values = mesh.attribute(color_by);
    vtkNew<vtkFloatArray> scalars;
    scalars->SetName(color_by.c_str());
    scalars->SetNumberOfTuples(nv);
    std::copy(values.begin(), values.end(), scalars->GetPointer(0));
    poly->GetPointData()->SetScalars(scalars);
  } else {
    vtkNew<vtkUnsignedCharArray> colors;
    colors->SetName("material_rgb");
    colors->SetNumberOfComponents(3);
    colors->SetNumberOfTuples(nt);
    if (mesh.has_vertex_colors()) {
      set_vertex_colored_cells(mesh, colors);
    } else {
      std::array<std::array<unsigned char, 3>, kMaterials.size()> rgb;
      for (Material m : kMaterials) rgb[static_cast<std::size_t>(m)] = material_rgb(m);
      for (vtkIdType t = 0; t < nt; ++t) {
        colors->SetTypedTuple(t, rgb[static_cast<std::size_t>(mesh.materials[t])].data());
      }
    }
    poly->GetCellData()->SetScalars(colors);
  }
  return poly;
}

// Degrees below the horizontal of the iso view of a wide, flat scene drawn on its ground: half
// the 30-degree view angle would put the horizon at the top edge; 10 degrees leaves the top sixth
// of the picture to the sky, so that a forest stands on a ground seen against a sky rather than
// on a ground that fills the picture like a background.
constexpr double kHorizonPitchDeg = 10.0;
// Scenes whose horizontal extent is this many times their height are seen over the horizon.
constexpr float kWideFlatRatio = 3.0f;

bool wide_and_flat(const Eigen::Vector3f& lo, const Eigen::Vector3f& hi) {
  const Eigen::Vector3f size = hi - lo;
  return std::max(size.x(), size.y()) > kWideFlatRatio * std::max(size.z(), 1e-3f);
}

void place_camera(vtkRenderer* renderer, View view, const Eigen::Vector3f& lo,
                  const Eigen::Vector3f& hi, bool horizon) {
  const Eigen::Vector3d center = (0.5f * (lo + hi)).cast<double>();
  Eigen::Vector3d dir = Eigen::Vector3d(1.0, -1.0, 0.8).normalized();  // focal point to eye
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  switch (view) {
    case View::kFront:
      dir = -Eigen::Vector3d::UnitY();
      break;
    case View::kSide:
      dir = Eigen::Vector3d::UnitX();
      break;
    case View::kTop:
      dir = Eigen::Vector3d::UnitZ();
      up = Eigen::Vector3d::UnitY();
      break;
    case View::kIso:
      dir = Eigen::Vector3d(1.0, -1.0, 0.8).normalized();
      if (horizon) {
        dir =
            Eigen::Vector3d(1.0, -1.0,
                            std::sqrt(2.0) * std::tan(kHorizonPitchDeg * 3.141592653589793 / 180.0))
                .normalized();
      }
      break;
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(center.data());
  const Eigen::Vector3d eye = center + dir;
  camera->SetPosition(eye.data());
  camera->SetViewUp(up.data());
  camera->SetViewAngle(30.0);
}

// Moves the eye along its line of sight to the nearest distance at which all eight corners of
// [lo, hi] are inside the view (ResetCamera fits the bounding sphere, which leaves wide, flat
// scenes such as a forest small in the frame), with a 6 % margin.
void fit_box(vtkCamera* camera, const Eigen::Vector3f& lo, const Eigen::Vector3f& hi,
             double aspect) {
  Eigen::Vector3d focal, eye, up;
  camera->GetFocalPoint(focal.data());
  camera->GetPosition(eye.data());
  camera->GetViewUp(up.data());
  const Eigen::Vector3d back = (eye - focal).normalized();  // focal point to eye
  const Eigen::Vector3d right = up.cross(back).normalized();
  const Eigen::Vector3d true_up = back.cross(right);
  const double tan_v = std::tan(0.5 * camera->GetViewAngle() * 3.141592653589793 / 180.0);
  const double tan_h = tan_v * aspect;
  double distance = 0.0;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d c((k & 1 ? hi : lo).x(), (k & 2 ? hi : lo).y(), (k & 4 ? hi : lo).z());
    const Eigen::Vector3d v = c - focal;
    const double z = v.dot(back);
    distance = std::max(
        {distance, z + std::abs(v.dot(true_up)) / tan_v, z + std::abs(v.dot(right)) / tan_h});
  }
  if (!(distance > 0.0) || !std::isfinite(distance)) return;
  const Eigen::Vector3d placed = focal + back * (1.06 * distance);
  camera->SetPosition(placed.data());
}

// A black bar of scale_bar_length(ortho_height_m) in the lower left corner with its length and
// unit above it, in pixels: the parallel projection maps ortho_height_m onto the image height.
void add_scale_bar(vtkRenderer* renderer, const RenderOptions& options) {
  const double length = scale_bar_length(options.ortho_height_m);
  if (length <= 0.0) return;
  const double px = length * options.height / options.ortho_height_m;
  const double x0 = 0.04 * options.width, y0 = 0.04 * options.height;
  const double thick = std::max(3.0, 0.008 * options.height);
  vtkNew<vtkPoints> corners;
  corners->InsertNextPoint(x0, y0, 0.0);
  corners->InsertNextPoint(x0 + px, y0, 0.0);
  corners->InsertNextPoint(x0 + px, y0 + thick, 0.0);
  corners->InsertNextPoint(x0, y0 + thick, 0.0);
  vtkNew<vtkCellArray> quad;
  const vtkIdType ids[4] = {0, 1, 2, 3};
  quad->InsertNextCell(4, ids);
  vtkNew<vtkPolyData> bar;
  bar->SetPoints(corners);
  bar->SetPolys(quad);
  vtkNew<vtkPolyDataMapper2D> mapper;
  mapper->SetInputData(bar);
  vtkNew<vtkActor2D> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.0, 0.0, 0.0);
  renderer->AddActor2D(actor);

  std::ostringstream label;
  label << length << ' ' << options.scale_bar_unit;
  vtkNew<vtkTextActor> text;
  text->SetInput(label.str().c_str());
  text->SetPosition(x0, y0 + thick + 4.0);
  text->GetTextProperty()->SetFontSize(std::max(12, options.height / 30));
  text->GetTextProperty()->SetColor(0.0, 0.0, 0.0);
  text->GetTextProperty()->ShadowOff();
  renderer->AddActor2D(text);
}

// The eight corners of the camera's view from `near_m` to `far_m` along its line of sight, near
// ones first, each four in the order (-,-), (+,-), (+,+), (-,+) across the image.
std::array<Eigen::Vector3d, 8> view_corners(vtkCamera* camera, double aspect, double near_m,
                                            double far_m) {
  Eigen::Vector3d focal, eye, up;
  camera->GetFocalPoint(focal.data());
  camera->GetPosition(eye.data());
  camera->GetViewUp(up.data());
  const Eigen::Vector3d ahead = (focal - eye).normalized();
  const Eigen::Vector3d right = ahead.cross(up).normalized();
  const Eigen::Vector3d true_up = right.cross(ahead);
  const double tan_v = std::tan(0.5 * camera->GetViewAngle() * 3.141592653589793 / 180.0);
  const bool parallel = camera->GetParallelProjection() != 0;
  std::array<Eigen::Vector3d, 8> corners;
  for (int k = 0; k < 8; ++k) {
    const double d = k < 4 ? near_m : far_m;
    const double half_h = parallel ? camera->GetParallelScale() : d * tan_v;
    const double sx = (k % 4 == 1 || k % 4 == 2) ? 1.0 : -1.0, sy = k % 4 >= 2 ? 1.0 : -1.0;
    corners[k] = eye + d * ahead + sy * half_h * true_up + sx * half_h * aspect * right;
  }
  return corners;
}

// The part of the plane z = ground_z inside the view volume given by its corners: a convex
// polygon whose vertices are the crossings of the volume's twelve edges with the plane.
std::vector<Eigen::Vector3d> ground_in_view(const std::array<Eigen::Vector3d, 8>& c,
                                            double ground_z) {
  std::vector<Eigen::Vector3d> points;
  const auto take = [&](const Eigen::Vector3d& p) { points.push_back(p); };
  const auto cross = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const double da = a.z() - ground_z, db = b.z() - ground_z;
    if (da == 0.0) take(a);
    if (db == 0.0) take(b);
    if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) take(a + (b - a) * (da / (da - db)));
  };
  for (int k = 0; k < 4; ++k) {
    cross(c[k], c[k + 4]);                // along the line of sight
    cross(c[k], c[(k + 1) % 4]);          // across the near end
    cross(c[k + 4], c[4 + (k + 1) % 4]);  // across the far end
  }
  return points;
}

// The ground: a slab of soil whose top face, at the bottom of [lo, hi], holds the plants well
// inside it and reaches the edges of the picture (to a horizon 40 camera distances away), and
// whose sides fill the picture below the ground line in horizontal parallel views, where the top
// face is seen edge on. Called with the camera in place; returns the nearest and farthest
// distances along the line of sight of the ground in view, for the clipping range.
std::array<double, 2> add_ground(vtkRenderer* renderer, const Eigen::Vector3f& lo,
                                 const Eigen::Vector3f& hi, double aspect) {
  const Eigen::Vector3f size = (hi - lo).cwiseMax(Eigen::Vector3f::Constant(0.1f));
  const double half = 0.9 * std::max(size.x(), size.y()) + 0.4 * size.z();
  const Eigen::Vector2d c = (0.5f * (lo + hi)).head<2>().cast<double>();
  Eigen::Vector2d xy_lo = c.array() - half, xy_hi = c.array() + half;
  vtkCamera* camera = renderer->GetActiveCamera();
  const double distance = camera->GetDistance();
  // A parallel view starts a quarter of the way to the focal point, in front of anything the
  // clipping range could cut off near the eye.
  const double near_m = camera->GetParallelProjection() != 0 ? 0.25 * distance : 0.0;
  const double far_m = 40.0 * distance;
  const auto corners = view_corners(camera, aspect, near_m, far_m);
  Eigen::Vector3d eye, focal;
  camera->GetPosition(eye.data());
  camera->GetFocalPoint(focal.data());
  const Eigen::Vector3d ahead = (focal - eye).normalized();
  std::array<double, 2> depth = {far_m, near_m};
  for (const Eigen::Vector3d& p : ground_in_view(corners, lo.z())) {
    xy_lo = xy_lo.cwiseMin(p.head<2>());
    xy_hi = xy_hi.cwiseMax(p.head<2>());
    depth[0] = std::min(depth[0], (p - eye).dot(ahead));
    depth[1] = std::max(depth[1], (p - eye).dot(ahead));
  }
  double bottom = lo.z() - 0.01 * size.z();
  for (const Eigen::Vector3d& p : corners) bottom = std::min(bottom, p.z());

  vtkNew<vtkPoints> points;
  for (int k = 0; k < 8; ++k) {
    const double x = (k % 4 == 1 || k % 4 == 2) ? xy_hi.x() : xy_lo.x();
    const double y = k % 4 >= 2 ? xy_hi.y() : xy_lo.y();
    points->InsertNextPoint(x, y, k < 4 ? lo.z() : bottom);
  }
  vtkNew<vtkCellArray> faces;
  const vtkIdType quads[5][4] = {{0, 1, 2, 3},
                                 {0, 1, 5, 4},
                                 {1, 2, 6, 5},
                                 {2, 3, 7, 6},
                                 {3, 0, 4, 7}};  // top and the four sides
  for (const auto& quad : quads) faces->InsertNextCell(4, quad);
  vtkNew<vtkPolyData> slab;
  slab->SetPoints(points);
  slab->SetPolys(faces);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(slab);
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> ground;
  ground->SetMapper(mapper);
  ground->GetProperty()->SetColor(0.55, 0.62, 0.45);
  ground->GetProperty()->SetAmbient(0.2);
  renderer->AddActor(ground);
  return depth;
}

// The relief crowns ray cast into the rendered picture against its depth buffer, lit from the
// light kit's key light (elevation 50 degrees, azimuth 10 degrees from the camera).
void add_relief_crowns(vtkRenderWindow* window, vtkRenderer* renderer, const RenderOptions& options,
                       Image& image) {
  const int w = options.width, h = options.height;
  std::vector<float> depth(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  window->GetZbufferData(0, 0, w - 1, h - 1, depth.data());
  vtkCamera* camera = renderer->GetActiveCamera();
  vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(
      static_cast<double>(w) / static_cast<double>(h), -1.0, 1.0);
  PictureCamera pc;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) pc.view_projection(r, c) = m->GetElement(r, c);
  }
  double position[3], focal[3], up[3];
  camera->GetPosition(position);
  camera->GetFocalPoint(focal);
  camera->GetViewUp(up);
  const Eigen::Vector3d back = (Eigen::Vector3d(position) - Eigen::Vector3d(focal)).normalized();
  const Eigen::Vector3d view_up = Eigen::Vector3d(up).normalized();
  const Eigen::Vector3d right = view_up.cross(back).normalized();
  const double elevation = 50.0 * std::numbers::pi / 180.0,
               azimuth = 10.0 * std::numbers::pi / 180.0;
  pc.sun = (std::cos(elevation) * (std::cos(azimuth) * back + std::sin(azimuth) * right) +
            std::sin(elevation) * view_up)
               .normalized()
               .cast<float>();
  composite_relief_crowns(options.relief_crowns, pc, depth, image);
}

// The box [lo, hi] grown to hold every placed relief crown, framed as the viewer frames it.
void frame_relief_crowns(const std::vector<ReliefCrown>& crowns, Eigen::Vector3f& lo,
                         Eigen::Vector3f& hi) {
  for (const ReliefCrown& c : crowns) {
    const Eigen::AlignedBox3f box = c.placed_bounds();
    if (box.isEmpty()) continue;
    lo = lo.cwiseMin(box.min());
    hi = hi.cwiseMax(box.max());
  }
}

// Sets up the renderer, lets `add_actors` fill it, adds the ground, lights and camera framing
// [lo, hi], renders off screen and reads the image back.
template <typename AddActors>
Image render_with(const RenderOptions& options, Eigen::Vector3f lo, Eigen::Vector3f hi,
                  AddActors&& add_actors) {
  if (!options.frame) frame_relief_crowns(options.relief_crowns, lo, hi);
  options.validate();
  struct DisplayGuard {
    void* display = open_x_display();
    ~DisplayGuard() { close_x_display(display); }
  } x;  // outlives the render window below, which borrows the connection
  if (x.display == nullptr) {
    throw IoError(
        "no X display for VTK's offscreen OpenGL context (DISPLAY unset or unreachable); run "
        "under a virtual server: xvfb-run -a fspm render ...");
  }

  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1.0, 1.0, 1.0);
  renderer->SetBackground2(0.78, 0.86, 0.96);
  renderer->GradientBackgroundOn();

  // Key, fill and back lights following the camera (Kitware's three-point light kit).
  renderer->RemoveAllLights();
  vtkNew<vtkLightKit> lights;
  lights->SetKeyLightIntensity(0.85);
  lights->AddLightsToRenderer(renderer);

  // Frame the tree, not the ground plane around it.
  place_camera(renderer, options.view, lo, hi,
               options.ground && options.ortho_height_m <= 0.0 && wide_and_flat(lo, hi));
  double bounds[6] = {lo.x(), hi.x(), lo.y(), hi.y(), lo.z(), hi.z()};
  renderer->ResetCamera(bounds);
  renderer->GetActiveCamera()->Zoom(1.1);
  fit_box(renderer->GetActiveCamera(), lo, hi,
          static_cast<double>(options.width) / static_cast<double>(options.height));
  if (options.ortho_height_m > 0.0) {
    // Parallel projection at a known scale: the image height spans ortho_height_m metres.
    renderer->GetActiveCamera()->ParallelProjectionOn();
    renderer->GetActiveCamera()->SetParallelScale(0.5 * options.ortho_height_m);
    if (!options.scale_bar_unit.empty()) add_scale_bar(renderer, options);
  }
  // Actors after the camera: a level-of-detail scene chooses its instances for this view (near
  // and far planes around the framed box until the actors are known).
  renderer->ResetCameraClippingRange(bounds);
  add_actors(renderer.Get());
  renderer->ResetCameraClippingRange();
  if (options.ground) {
    // The clipping range of the plants and obstacles, widened to the ground in view (the range
    // VTK would fit to the slab's whole bounds puts the near plane far out and cuts the ground).
    const std::array<double, 2> ground = add_ground(
        renderer, lo, hi, static_cast<double>(options.width) / static_cast<double>(options.height));
    double range[2];
    renderer->GetActiveCamera()->GetClippingRange(range);
    const double far = std::max(range[1], 1.01 * ground[1]);
    const double near = std::max(std::min(range[0], 0.9 * ground[0]), 1e-4 * far);
    renderer->GetActiveCamera()->SetClippingRange(near, far);
  }

  vtkNew<vtkRenderWindow> window;
  window->SetDisplayId(x.display);
  window->SetOffScreenRendering(1);
  window->SetSize(options.width, options.height);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  window->Render();

  Image image = window_image(window);
  if (!options.relief_crowns.empty()) add_relief_crowns(window, renderer, options, image);
  return image;
}

// Stone: the obstacle colour, flat faces, some ambient light so walls turned away from the key
// light stay grey rather than black, hardly any shine. Opaque, or a lighter see-through grey for
// obstacles that let light through.
void stone_look(vtkActor* actor, Material material = Material::kObstacle,
                float opacity = kTranslucentObstacleOpacity) {
  const auto rgb = material_rgb(material);
  vtkProperty* p = actor->GetProperty();
  p->SetColor(rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0);
  p->SetInterpolationToFlat();
  p->SetAmbient(0.35);
  p->SetDiffuse(0.75);
  p->SetSpecular(0.05);
  p->SetOpacity(material == Material::kTranslucentObstacle ? opacity : 1.0);
}

// Adds an actor for `mapper` with the shared surface look; the renderer keeps it alive.
vtkActor* add_surface_actor(vtkRenderer* renderer, vtkMapper* mapper) {
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetInterpolationToPhong();
  actor->GetProperty()->SetSpecular(0.15);
  actor->GetProperty()->SetSpecularPower(20.0);
  actor->GetProperty()->BackfaceCullingOff();
  renderer->AddActor(actor);
  return actor.Get();
}

// The mesh in its cell colours (materials, or the mean of its vertex colours; to_polydata).
vtkActor* add_cell_colored_actor(vtkRenderer* renderer, const TriangleMesh& mesh) {
  vtkNew<vtkPolyData> poly = to_polydata(mesh, "");
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  mapper->SetScalarModeToUseCellData();
  mapper->SetColorModeToDirectScalars();
  mapper->ScalarVisibilityOn();
  return add_surface_actor(renderer, mapper);
}

vtkActor* add_glyph_actor(vtkRenderer* renderer, vtkPolyData* instances, const TriangleMesh& part,
                          const std::array<unsigned char, 3>& rgb) {
  vtkNew<vtkPolyData> source = to_polydata(part, "");
  vtkNew<vtkGlyph3DMapper> mapper;
  mapper->SetInputData(instances);
  mapper->SetSourceData(source);
  mapper->SetOrientationModeToQuaternion();
  mapper->SetOrientationArray("orientation");
  mapper->SetScaleModeToScaleByVectorComponents();
  mapper->SetScaleArray("scale");
  mapper->ScalingOn();
  mapper->OrientOn();
  mapper->ScalarVisibilityOff();
  vtkActor* actor = add_surface_actor(renderer, mapper);
  actor->GetProperty()->SetColor(rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0);
  return actor;
}

// The triangles of one material as a mesh of their own (positions and normals only); with
// `keep`, only the triangles it accepts.
TriangleMesh material_part(const TriangleMesh& mesh, Material material,
                           const std::function<bool(std::size_t)>& keep = {}) {
  TriangleMesh part;
  std::vector<std::uint32_t> map(mesh.vertex_count(), 0xFFFFFFFFu);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (mesh.materials[t] != material || (keep && !keep(t))) continue;
    TriangleMesh::Triangle tri;
    for (int k = 0; k < 3; ++k) {
      std::uint32_t& m = map[mesh.triangles[t][k]];
      if (m == 0xFFFFFFFFu) {
        m = static_cast<std::uint32_t>(part.positions.size());
        part.positions.push_back(mesh.positions[mesh.triangles[t][k]]);
        part.normals.push_back(mesh.normals[mesh.triangles[t][k]]);
      }
      tri[k] = m;
    }
    part.triangles.push_back(tri);
    part.materials.push_back(material);
  }
  return part;
}

// A material's obstacles split by how see-through they are.
struct ObstaclePart {
  TriangleMesh mesh;
  float opacity = 1.0f;
};

// The obstacles of one material; translucent ones one part per translucency, each as
// see-through as its obstacle (translucent_obstacle_opacity).
std::vector<ObstaclePart> obstacle_parts(const TriangleMesh& mesh, Material material) {
  if (material != Material::kTranslucentObstacle || !mesh.has_attribute("translucency")) {
    return {{material_part(mesh, material), kTranslucentObstacleOpacity}};
  }
  const std::span<const float> gamma = mesh.attribute("translucency");
  std::map<float, int> seen;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (mesh.materials[t] == material) seen.emplace(gamma[mesh.triangles[t][0]], 0);
  }
  std::vector<ObstaclePart> parts;
  for (const auto& entry : seen) {
    const float g = entry.first;
    const auto same = [&](std::size_t t) { return gamma[mesh.triangles[t][0]] == g; };
    parts.push_back({material_part(mesh, material, same), translucent_obstacle_opacity(g)});
  }
  return parts;
}

// The obstacles of one material in stone, one actor per part.
void add_obstacle_actors(vtkRenderer* renderer, const TriangleMesh& mesh, Material material) {
  for (const ObstaclePart& part : obstacle_parts(mesh, material)) {
    vtkNew<vtkPolyData> poly = to_polydata(part.mesh, "");
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(poly);
    mapper->ScalarVisibilityOff();
    stone_look(add_surface_actor(renderer, mapper), material, part.opacity);
  }
}

// `mesh` without the triangles of one material (vertices and attributes kept as they are).
TriangleMesh without_material(const TriangleMesh& mesh, Material material) {
  TriangleMesh out = mesh;
  out.triangles.clear();
  out.materials.clear();
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (mesh.materials[t] == material) continue;
    out.triangles.push_back(mesh.triangles[t]);
    out.materials.push_back(mesh.materials[t]);
  }
  return out;
}

// Range of an attribute over the vertices the triangles use ([v, v + 1] when constant).
std::array<double, 2> attribute_range(const TriangleMesh& mesh, std::span<const float> values) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (const auto& t : mesh.triangles) {
    for (std::uint32_t i : t) {
      lo = std::min(lo, static_cast<double>(values[i]));
      hi = std::max(hi, static_cast<double>(values[i]));
    }
  }
  if (!(lo <= hi)) lo = hi = 0.0;
  if (hi <= lo) hi = lo + 1.0;
  return {lo, hi};
}

bool has_nan(std::span<const float> values) {
  return std::any_of(values.begin(), values.end(), [](float v) { return std::isnan(v); });
}

// The mesh coloured by options.color_by through a blue-to-red lookup table over `range`, with a
// scalar bar when `bar` (and options.scalar_bar).
vtkActor* add_colored_actor(vtkRenderer* renderer, const TriangleMesh& mesh,
                            const RenderOptions& options, std::array<double, 2> range, bool bar) {
  vtkNew<vtkPolyData> poly = to_polydata(mesh, options.color_by);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(poly);
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0);  // blue (low) to red (high)
  lut->SetTableRange(range.data());
  // Nodes without a value (nan: a branch where only buds or leaves were measured) keep the
  // bark's colour instead of reading as the scale's lowest value.
  const std::array<float, 3> bark = material_color(Material::kBark);
  lut->SetNanColor(bark[0], bark[1], bark[2], 1.0);
  lut->Build();
  mapper->SetLookupTable(lut);
  mapper->SetScalarModeToUsePointData();
  mapper->SetScalarRange(range.data());
  mapper->ScalarVisibilityOn();
  vtkActor* actor = add_surface_actor(renderer, mapper);
  if (!bar || !options.scalar_bar) return actor;
  vtkNew<vtkScalarBarActor> scalar_bar;
  scalar_bar->SetLookupTable(lut);
  const std::string title = attribute_title(options.color_by);
  scalar_bar->SetTitle(title.c_str());
  scalar_bar->SetNumberOfLabels(5);
  if (has_nan(mesh.attribute(options.color_by))) {
    scalar_bar->SetNanAnnotation("no value");
    scalar_bar->DrawNanAnnotationOn();
  }
  scalar_bar->SetMaximumWidthInPixels(std::max(60, options.width / 10));
  scalar_bar->GetTitleTextProperty()->SetColor(0.1, 0.1, 0.1);
  scalar_bar->GetLabelTextProperty()->SetColor(0.1, 0.1, 0.1);
  scalar_bar->GetTitleTextProperty()->ShadowOff();
  scalar_bar->GetLabelTextProperty()->ShadowOff();
  renderer->AddActor2D(scalar_bar);
  return actor;
}

// Crown volumes are seen through: the branches and the other crowns show behind them.
void crown_look(vtkActor* actor) { actor->GetProperty()->SetOpacity(kCrownOpacity); }

// Only the triangles of one material (vertices and attributes kept as they are).
TriangleMesh only_material(const TriangleMesh& mesh, Material material) {
  TriangleMesh out = mesh;
  out.triangles.clear();
  out.materials.clear();
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (mesh.materials[t] != material) continue;
    out.triangles.push_back(mesh.triangles[t]);
    out.materials.push_back(material);
  }
  return out;
}

// Plants (no obstacles) as an opaque actor and, for crown volumes, a translucent one; both on
// one colour scale when coloured by an attribute.
void add_plant_actors(vtkRenderer* renderer, const TriangleMesh& plants,
                      const RenderOptions& options) {
  const bool crowns = plants.triangle_count(Material::kCrown) > 0;
  const TriangleMesh opaque = crowns ? without_material(plants, Material::kCrown) : TriangleMesh{};
  const TriangleMesh& solid = crowns ? opaque : plants;
  const TriangleMesh crown = crowns ? only_material(plants, Material::kCrown) : TriangleMesh{};
  if (!options.color_by.empty()) {
    const auto range = attribute_range(plants, plants.attribute(options.color_by));
    if (!solid.empty()) add_colored_actor(renderer, solid, options, range, true);
    if (crowns) crown_look(add_colored_actor(renderer, crown, options, range, solid.empty()));
    return;
  }
  for (const TriangleMesh* part : {&solid, &crown}) {
    if (part->empty()) continue;
    vtkActor* actor = add_cell_colored_actor(renderer, *part);
    if (part == &crown) crown_look(actor);
  }
}

// One glyph actor per material of `mesh` (obstacles in stone, one per translucency).
void add_material_glyphs(vtkRenderer* renderer, vtkPolyData* placed, const TriangleMesh& mesh) {
  for (Material material : kMaterials) {
    if (mesh.triangle_count(material) == 0) continue;
    if (is_obstacle(material)) {
      for (const ObstaclePart& part : obstacle_parts(mesh, material)) {
        stone_look(add_glyph_actor(renderer, placed, part.mesh, material_rgb(material)), material,
                   part.opacity);
      }
      continue;
    }
    vtkActor* actor =
        add_glyph_actor(renderer, placed, material_part(mesh, material), material_rgb(material));
    if (material == Material::kCrown) crown_look(actor);
  }
}

// A mesh with vertex colours (a crown from a photograph, placed a few times in a scene) drawn
// explicitly, its instances flattened, with the colours as cell scalars: the glyph mapper colours
// a glyph as a whole.
void add_vertex_colored_instances(vtkRenderer* renderer, const TriangleMesh& mesh, std::uint32_t m,
                                  const std::vector<MeshInstance>& instances) {
  InstancedMesh placed;
  placed.meshes.push_back(mesh);
  for (MeshInstance inst : instances) {
    if (inst.mesh != m) continue;
    inst.mesh = 0;
    placed.instances.push_back(inst);
  }
  if (!placed.instances.empty()) add_cell_colored_actor(renderer, placed.flatten());
}

// GPU instancing through VTK's glyph mapper: one source per shared mesh and material, one glyph
// (position, quaternion, scale) per instance.
void add_instanced_actors(vtkRenderer* renderer, const std::vector<const TriangleMesh*>& meshes,
                          const std::vector<MeshInstance>& instances) {
  for (std::uint32_t m = 0; m < meshes.size(); ++m) {
    const TriangleMesh& mesh = *meshes[m];
    if (mesh.empty()) continue;
    if (mesh.has_vertex_colors()) {
      add_vertex_colored_instances(renderer, mesh, m, instances);
      continue;
    }
    vtkNew<vtkPoints> points;
    vtkNew<vtkFloatArray> orientation, scale;
    orientation->SetName("orientation");
    orientation->SetNumberOfComponents(4);
    scale->SetName("scale");
    scale->SetNumberOfComponents(3);
    for (const MeshInstance& inst : instances) {
      if (inst.mesh != m) continue;
      const float s = std::cbrt(inst.linear.determinant());
      const Eigen::Quaternionf q(inst.linear / s);
      points->InsertNextPoint(inst.translation.x(), inst.translation.y(), inst.translation.z());
      const float wxyz[4] = {q.w(), q.x(), q.y(), q.z()};  // VTK's quaternion order
      orientation->InsertNextTypedTuple(wxyz);
      const float sss[3] = {s, s, s};
      scale->InsertNextTypedTuple(sss);
    }
    if (points->GetNumberOfPoints() == 0) continue;
    vtkNew<vtkPolyData> placed;
    placed->SetPoints(points);
    placed->GetPointData()->AddArray(orientation);
    placed->GetPointData()->AddArray(scale);
    add_material_glyphs(renderer, placed, mesh);
  }
}

}  // namespace

bool render_available() { return true; }

Image render_mesh(const TriangleMesh& mesh, const RenderOptions& options) {
  if (!options.color_by.empty()) (void)mesh.attribute(options.color_by);  // ValueError first
  const Eigen::Vector3f lo = options.frame ? options.frame->min() : mesh.bbox_min();
  const Eigen::Vector3f hi = options.frame ? options.frame->max() : mesh.bbox_max();
  return render_with(options, lo, hi, [&](vtkRenderer* renderer) {
    if (mesh.empty()) return;
    // Obstacles always in stone, as an actor of their own (lit like stone, and outside the
    // colour scale, which spans the plants' values only).
    const TriangleMesh* plants = &mesh;
    TriangleMesh without_obstacles[2];
    int parts = 0;
    for (Material material : {Material::kObstacle, Material::kTranslucentObstacle}) {
      if (mesh.triangle_count(material) == 0) continue;
      add_obstacle_actors(renderer, mesh, material);
      without_obstacles[parts] = without_material(*plants, material);
      plants = &without_obstacles[parts++];
    }
    if (plants->empty()) return;
    add_plant_actors(renderer, *plants, options);
  });
}

Image render_scene(const InstancedMesh& scene, const RenderOptions& options) {
  if (!options.color_by.empty()) {
    // Colours per vertex and per instance (the order attribute) need the explicit mesh.
    return render_mesh(scene.flatten(), options);
  }
  Eigen::Vector3f lo, hi;
  scene.bounds(lo, hi);
  if (options.frame) {
    lo = options.frame->min();
    hi = options.frame->max();
  }
  std::vector<const TriangleMesh*> meshes;
  for (const TriangleMesh& m : scene.meshes) meshes.push_back(&m);
  return render_with(options, lo, hi, [&](vtkRenderer* renderer) {
    add_instanced_actors(renderer, meshes, scene.instances);
  });
}

Image render_lod_scene(const LodScene& scene, const LodOptions& lod, const RenderOptions& options,
                       std::size_t* triangles_drawn) {
  lod.validate();
  if (!options.color_by.empty()) {
    throw ValueError(
        "per-instance level of detail does not combine with colouring by an attribute");
  }
  // The camera frames every plant at its finest and the fixed meshes.
  std::vector<InstanceLod> finest(scene.placements.size());
  for (auto& c : finest) c.visible = true;
  const std::vector<const TriangleMesh*> meshes = scene.meshes();
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::infinity()), hi = -lo;
  for (const MeshInstance& inst : lod_instances(scene, finest)) {
    for (const auto& p : meshes[inst.mesh]->positions) {
      lo = lo.cwiseMin(inst.linear * p + inst.translation);
      hi = hi.cwiseMax(inst.linear * p + inst.translation);
    }
  }
  if (!(lo.x() <= hi.x())) lo = hi = Eigen::Vector3f::Zero();
  if (options.frame) {
    lo = options.frame->min();
    hi = options.frame->max();
  }
  return render_with(options, lo, hi, [&](vtkRenderer* renderer) {
    vtkCamera* camera = renderer->GetActiveCamera();
    Eigen::Vector3d eye;
    camera->GetPosition(eye.data());
    const double aspect = static_cast<double>(options.width) / options.height;
    vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0);
    Eigen::Matrix4d view_projection;
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) view_projection(r, c) = m->GetElement(r, c);
    }
    const std::vector<MeshInstance> instances =
        lod_instances(scene, select_lod(scene, eye, view_projection, lod));
    if (triangles_drawn != nullptr) *triangles_drawn = lod_triangle_count(scene, instances);
    add_instanced_actors(renderer, meshes, instances);
  });
}

}  // namespace fspm::graphics
