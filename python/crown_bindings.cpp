// fspm.reconstruct_crown: a tree crown from one photograph (Argudo 2014, ch. 4-5; docs/crown.md).
// Built when fspm has OpenImageIO (the crown module); otherwise the function is absent.
#include "python/bindings.hpp"

#ifdef FSPM_HAVE_CROWN
#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <random>
#include <string>

#include "crown/auto_mask.hpp"
#include "crown/crown_from_photo.hpp"
#include "crown/cubemap.hpp"
#include "crown/image_io.hpp"

namespace fspm::python {
namespace {

crown::CrownModel reconstruct(const std::string& photo_path,
                              const std::optional<std::string>& mask_path, double height_m,
                              double depth_ratio, double relief, std::uint64_t seed) {
  const crown::Raster photo = crown::read_rgb(photo_path);
  const crown::Mask mask =
      mask_path ? crown::read_mask(*mask_path) : crown::auto_mask(photo, {}, photo_path);
  const crown::Mask foliage = crown::foreground(photo, crown::AutoMaskOptions{}.threshold);
  crown::CrownOptions options;
  options.height_m = height_m;
  options.depth_ratio = depth_ratio;
  options.relief_weight = relief;
  std::mt19937_64 rng(seed);
  return crown::reconstruct_crown(photo, mask, options, rng, &foliage);
}

// A cubemap as the (N, 6N, C) float32 strip of its faces side by side, as fspm crown writes it.
py::array_t<float> strip_array(const crown::Cubemap& cubemap) {
  const crown::Raster strip = crown::cubemap_strip(cubemap);
  py::array_t<float> out({static_cast<py::ssize_t>(strip.height),
                          static_cast<py::ssize_t>(strip.width),
                          static_cast<py::ssize_t>(strip.channels)});
  std::copy(strip.values.begin(), strip.values.end(), out.mutable_data());
  return out;
}

}  // namespace

void bind_crown(py::module_& m) {
  using crown::CrownModel;
  py::class_<CrownModel>(m, "CrownModel",
                         "A crown reconstructed from one photograph (docs/crown.md): closed mesh "
                         "in metres, z up, the photograph looking along +y")
      .def_property_readonly(
          "vertices", [](const CrownModel& c) { return vector_rows(c.mesh.positions); },
          "Vertex positions in m, an (N, 3) float32 array (crown, then the trunk if any)")
      .def_property_readonly(
          "colors", [](const CrownModel& c) { return vector_rows(c.mesh.colors); },
          "Vertex colours, linear RGB in [0, 1], an (N, 3) float32 array")
      .def_property_readonly(
          "triangles",
          [](const CrownModel& c) {
            py::array_t<std::uint32_t> out(
                {static_cast<py::ssize_t>(c.mesh.triangles.size()), py::ssize_t{3}});
            auto a = out.mutable_unchecked<2>();
            for (std::size_t t = 0; t < c.mesh.triangles.size(); ++t) {
              for (int k = 0; k < 3; ++k)
                a(static_cast<py::ssize_t>(t), k) = c.mesh.triangles[t][k];
            }
            return out;
          },
          "Vertex indices of each triangle, counter-clockwise seen from outside, (M, 3) uint32")
      .def_property_readonly(
          "color_cubemap", [](const CrownModel& c) { return strip_array(c.color); },
          "Colour cubemap, an (N, 6N, 3) float32 strip of the faces front (-y), right (+x), back "
          "(+y), left (-x), top (+z), bottom (-z), as fspm crown writes it (docs/crown.md)")
      .def_property_readonly(
          "radius_cubemap", [](const CrownModel& c) { return strip_array(c.radius); },
          "Radius cubemap, an (N, 6N, 1) float32 strip: metres from `centre` to the surface")
      .def_property_readonly(
          "centre",
          [](const CrownModel& c) {
            return std::vector<float>(c.centre.data(), c.centre.data() + 3);
          },
          "The crown's centre in m, [x, y, z]: the radii are measured from it")
      .def_readonly("volume_m3", &CrownModel::volume_m3, "Volume of the crown in m^3")
      .def_readonly("silhouette_pixels", &CrownModel::silhouette_pixels,
                    "Pixels of the crown's silhouette S (8-connected), at the working resolution")
      .def_readonly("crown_pixels", &CrownModel::crown_pixels, "Pixels of the crown mask")
      .def_readonly("metres_per_pixel", &CrownModel::metres_per_pixel,
                    "Scale of the photograph, m per pixel")
      .def_readonly("working_factor", &CrownModel::working_factor,
                    "Photograph pixels per working pixel along each side (docs/crown.md)")
      .def_property_readonly(
          "seconds",
          [](const CrownModel& c) {
            py::dict d;
            for (const auto& [stage, s] : c.seconds) d[stage.c_str()] = s;
            return d;
          },
          "Seconds per stage (resample, base_mesh, relief, texture_synthesis, composition), a "
          "dict");

  m.def("reconstruct_crown", &reconstruct, py::arg("photo"), py::arg("mask") = py::none(),
        py::arg("height_m") = 10.0, py::arg("depth_ratio") = 1.0, py::arg("relief") = 0.15,
        py::arg("seed") = 1,
        "A CrownModel from a photograph file and its crown mask file (white on black; None: found "
        "against sky and ground). height_m: the crown's height in m; depth_ratio: depth over "
        "width; relief: Argudo's rho. Raises OSError for unreadable files, ValueError otherwise",
        py::call_guard<py::gil_scoped_release>());
}

}  // namespace fspm::python

#else

namespace fspm::python {
void bind_crown(py::module_&) {}
}  // namespace fspm::python

#endif
