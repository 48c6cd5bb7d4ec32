// Bindings of the graphics module: tree meshes (generalized cylinders and leaf quads) as numpy
// views, OBJ/PLY/VTP/GLB/PVD export, and VTK offscreen renders to numpy images and PNG files
// (rendering needs fspm built with VTK; without it the functions raise ParameterError).
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "graphics/image.hpp"
#include "graphics/mesh_writers.hpp"
#include "graphics/render.hpp"
#include "graphics/tree_mesher.hpp"
#include "graphics/triangle_mesh.hpp"
#include "python/bindings.hpp"

namespace fspm::python {
namespace {

namespace gr = fspm::graphics;

gr::MeshOptions mesh_options(const std::optional<gr::MeshOptions>& options,
                             const py::kwargs& overrides) {
  gr::MeshOptions o = options.value_or(gr::MeshOptions{});
  if (overrides.size() > 0) set_fields(py::cast(&o, py::return_value_policy::reference), overrides);
  return o;
}

// (H, W, 4) uint8 numpy array taking over the image's pixels.
py::array image_array(gr::Image&& image) {
  auto* owned = new gr::Image(std::move(image));
  py::capsule owner(owned, [](void* p) { delete static_cast<gr::Image*>(p); });
  return py::array_t<std::uint8_t>(
      {py::ssize_t{owned->height}, py::ssize_t{owned->width}, py::ssize_t{4}}, owned->rgba.data(),
      owner);
}

gr::Image image_from(
    const py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>& a) {
  if (a.ndim() != 3 || (a.shape(2) != 3 && a.shape(2) != 4)) {
    throw ValueError("image: expected a uint8 array of shape (height, width, 3 or 4)");
  }
  gr::Image image;
  image.height = static_cast<int>(a.shape(0));
  image.width = static_cast<int>(a.shape(1));
  const auto channels = static_cast<std::size_t>(a.shape(2));
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  image.rgba.assign(pixels * 4, 255);
  const std::uint8_t* src = a.data();
  for (std::size_t i = 0; i < pixels; ++i) {
    for (std::size_t c = 0; c < channels; ++c) image.rgba[4 * i + c] = src[channels * i + c];
  }
  return image;
}

void bind_mesh_options(py::module_& m) {
  py::class_<gr::MeshOptions> mo(m, "MeshOptions",
                                 "How a tree is meshed: ring resolution, caps, leaves, junctions");
  // Junctions are a name, like the command line's --junctions.
  mo.def_property(
      "junctions",
      [](const gr::MeshOptions& o) { return std::string(gr::junction_mode_name(o.junctions)); },
      [](gr::MeshOptions& o, const std::string& name) {
        o.junctions = gr::junction_mode_from_name(name);
      },
      "'separate' (one closed tube per chain) or 'continuous' (Reynolds)");
  // Foliage of leaf clusters is a name too, like --foliage.
  mo.def_property(
      "foliage",
      [](const gr::MeshOptions& o) {
        return std::string(gr::kFoliageModeNames.name(o.foliage.mode));
      },
      [](gr::MeshOptions& o, const std::string& name) {
        o.foliage.mode = gr::foliage_mode_from_name(name);
      },
      "Leaf clusters (with leaves=True): 'leaves' (a cloud of leaves) or 'volumes' (translucent "
      "crown spheres)");
  Fields<gr::MeshOptions>(mo)
      .add("reynolds_width", &gr::MeshOptions::reynolds_width,
           "Continuous junctions only: radius along each axis from Reynolds' expression 1 instead "
           "of the node radii (False)")
      .add("edge_length_m", &gr::MeshOptions::edge_length_m,
           "Target edge of a tube's rings: sides = ceil(2 pi r / edge_length_m), clamped to "
           "[min_sides, max_sides] (m, > 0; 0.01)")
      .add("min_sides", &gr::MeshOptions::min_sides,
           "Fewest sides of a tube's rings (integer >= 3; 3)")
      .add("max_sides", &gr::MeshOptions::max_sides,
           "Most sides of a tube's rings (integer >= min_sides; 16)")
      .add(
          "min_radius_m", &gr::MeshOptions::min_radius_m,
          "Radii below this are raised to it, so twigs give no degenerate triangles (m, > 0; 1e-4)")
      .add("camera_m", &gr::MeshOptions::camera_m,
           "Camera position (x, y, z in m) for level of detail, or None (no level of detail)")
      .add("lod_distance_m", &gr::MeshOptions::lod_distance_m,
           "Beyond this distance from camera_m the edge length grows in proportion to the distance "
           "(m, > 0; 5)")
      .add("caps", &gr::MeshOptions::caps,
           "Close every tube with a cap at its base and its tip (True)")
      .add("bark", &gr::MeshOptions::bark, "Mesh the internode tubes (False: leaves only; True)")
      .add("leaves", &gr::MeshOptions::leaves,
           "Mesh leaf nodes as quads and leaf clusters as foliage (False)")
      .add("leaf_width_ratio", &gr::MeshOptions::leaf_width_ratio,
           "Leaf blade width / leaf length (> 0; 0.5)")
      .add("leaf_bend", &gr::MeshOptions::leaf_bend,
           "Droop of the blade tip as a fraction of its length (0 = flat quad; 0)")
      .add("leaf_bend_segments", &gr::MeshOptions::leaf_bend_segments,
           "Segments of a bent blade (integer >= 1; 4)")
      .add("max_birth_time", &gr::MeshOptions::max_birth_time,
           "Nodes born after this time (and their subtrees) are left out; the 'age' attribute is "
           "measured from it (growth cycles or years; inf = keep all)")
      .add("foliage_seed", &gr::MeshOptions::foliage_seed,
           "Seed of the leaf placement in clusters (same seed, same mesh)")
      .existing("junctions")
      .existing("foliage")
      .finish();
  mo.def(
      "validate", [](const gr::MeshOptions& o) { o.validate(); },
      "Raises ParameterError naming the first field out of range (mesh_tree checks this too)");
}

using TM = gr::TriangleMesh;

void bind_triangle_mesh(py::module_& m) {
  py::class_<TM>(m, "TriangleMesh", "An indexed triangle mesh with per-vertex attributes")
      .def_property_readonly("vertex_count", &TM::vertex_count, "Number of vertices")
      .def(
          "triangle_count",
          [](const TM& mesh, std::optional<std::string> material) {
            if (!material) return mesh.triangle_count();
            return mesh.triangle_count(gr::material_from_name(*material));
          },
          py::arg("material") = py::none(),
          "Triangles, or those of 'bark', 'leaf', 'obstacle', 'crown', 'translucent_obstacle' or "
          "'terrain'")
      .def_property_readonly(
          "positions",
          [](py::object self) {
            return column(std::span(self.cast<const TM&>().positions), self, 3);
          },
          "Vertex positions (V, 3) float32, a read-only view")
      .def_property_readonly(
          "normals",
          [](py::object self) {
            return column(std::span(self.cast<const TM&>().normals), self, 3);
          },
          "Unit vertex normals (V, 3) float32")
      .def_property_readonly(
          "uvs",
          [](py::object self) { return column(std::span(self.cast<const TM&>().uvs), self, 2); },
          "Texture coordinates (V, 2) float32")
      .def_property_readonly(
          "triangles",
          [](py::object self) {
            return column(std::span(self.cast<const TM&>().triangles), self, 3);
          },
          "Vertex indices (T, 3) uint32, counter-clockwise seen from outside")
      .def_property_readonly(
          "materials",
          [](py::object self) {
            const auto& mat = self.cast<const TM&>().materials;
            return column(std::span<const std::uint8_t>(
                              reinterpret_cast<const std::uint8_t*>(mat.data()), mat.size()),
                          self);
          },
          "Per triangle: 0 bark, 1 leaf, 2 obstacle")
      .def("attribute_names", &TM::attribute_names,
           "Names of the per-vertex attributes (age, birth_time, order, ... and the tree's own)")
      .def(
          "attribute",
          [](py::object self, const std::string& name) {
            return column(self.cast<const TM&>().attribute(name), self);
          },
          py::arg("name"), "A per-vertex float32 attribute (read-only view)")
      .def_property_readonly(
          "bbox_min", &TM::bbox_min,
          "Smallest x, y, z of the vertices (m, or model units; zeros when empty)")
      .def_property_readonly(
          "bbox_max", &TM::bbox_max,
          "Largest x, y, z of the vertices (m, or model units; zeros when empty)")
      .def(
          "write",
          [](const TM& mesh, const std::string& path) {
            py::gil_scoped_release release;
            gr::write_mesh(mesh, path);
          },
          py::arg("path"), "Write .obj (+ .mtl), .ply, .vtp or .glb by extension, atomically")
      .def("__repr__", [](const TM& mesh) {
        return "<fspm.TriangleMesh with " + std::to_string(mesh.vertex_count()) + " vertices, " +
               std::to_string(mesh.triangle_count()) + " triangles>";
      });
}

void bind_meshing(py::module_& m) {
  m.def(
      "mesh_tree",
      [](const TreeGraph& tree, std::optional<gr::MeshOptions> options, const py::kwargs& kw) {
        const gr::MeshOptions o = mesh_options(options, kw);
        py::gil_scoped_release release;
        return o.junctions == gr::JunctionMode::kContinuous ? gr::mesh_tree_continuous(tree, o)
                                                            : gr::mesh_tree(tree, o);
      },
      py::arg("tree"), py::arg("options") = py::none(),
      "Mesh a tree; MeshOptions fields may be given as keyword arguments");
  m.def(
      "count_mesh",
      [](const TreeGraph& tree, std::optional<gr::MeshOptions> options, const py::kwargs& kw) {
        const gr::MeshCounts c = gr::count_mesh(tree, mesh_options(options, kw));
        py::dict d;
        d["vertices"] = c.vertices;
        d["triangles"] = c.triangles;
        d["tubes"] = c.tubes;
        d["leaves"] = c.leaves;
        d["clusters"] = c.clusters;
        return d;
      },
      py::arg("tree"), py::arg("options") = py::none(),
      "What mesh_tree would produce (vertices, triangles, tubes, leaves, clusters) without "
      "building it");
  m.def(
      "sides_for_radius",
      [](double radius, std::optional<gr::MeshOptions> options, double distance) {
        return gr::sides_for_radius(radius, options.value_or(gr::MeshOptions{}), distance);
      },
      py::arg("radius"), py::arg("options") = py::none(), py::arg("distance") = 0.0,
      "Ring resolution of a tube of this radius");
}

void bind_mesh_writers(py::module_& m) {
  const auto writer = [&m](const char* name, void (*fn)(const TM&, const std::string&),
                           const char* doc) {
    m.def(
        name,
        [fn](const TM& mesh, const std::string& path) {
          py::gil_scoped_release release;
          fn(mesh, path);
        },
        py::arg("mesh"), py::arg("path"), doc);
  };
  writer("write_mesh", &gr::write_mesh, "Any single-mesh format by extension, atomically");
  writer("write_obj", &gr::write_obj, "Wavefront OBJ and its .mtl beside it");
  writer("write_ply", &gr::write_ply, "Binary PLY with attributes as vertex properties");
  writer("write_vtp", &gr::write_vtp, "VTK XML PolyData with attributes as point data");
  writer("write_glb", &gr::write_glb, "Binary glTF 2.0");
  m.def(
      "write_pvd",
      [](const TreeGraph& tree, const std::string& path, std::optional<std::vector<double>> ages,
         std::optional<gr::MeshOptions> options) {
        std::vector<gr::PvdFrame> frames;
        {
          py::gil_scoped_release release;
          frames = gr::write_pvd(tree, options.value_or(gr::MeshOptions{}),
                                 ages ? *ages : gr::default_ages(tree), path);
        }
        return dict_list(frames, [](py::dict& d, const gr::PvdFrame& f) {
          d["age"] = f.age;
          d["file"] = f.vtp_path;
          d["vertices"] = f.vertices;
          d["triangles"] = f.triangles;
        });
      },
      py::arg("tree"), py::arg("path"), py::arg("ages") = py::none(),
      py::arg("options") = py::none(),
      "ParaView growth sequence: one .vtp per age beside `path` and the .pvd listing them");
}

void bind_mesh(py::module_& m) {
  bind_mesh_options(m);
  bind_triangle_mesh(m);
  bind_meshing(m);
  bind_mesh_writers(m);
}

void bind_render(py::module_& m) {
  m.def("render_available", &gr::render_available, "True when fspm was built with VTK");
  m.def("display_available", &gr::display_available,
        "True when an X display can be opened (VTK renders need one; Xvfb is enough)");
  m.def(
      "render_mesh",
      [](const gr::TriangleMesh& mesh, int width, int height, const std::string& view,
         const std::string& color_by, bool ground, bool scalar_bar) {
        gr::RenderOptions o;
        o.width = width;
        o.height = height;
        o.view = gr::view_from_name(view);
        o.color_by = color_by;
        o.ground = ground;
        o.scalar_bar = scalar_bar;
        gr::Image image;
        {
          py::gil_scoped_release release;
          image = gr::render_mesh(mesh, o);
        }
        return image_array(std::move(image));
      },
      py::arg("mesh"), py::arg("width") = 1024, py::arg("height") = 768, py::arg("view") = "iso",
      py::arg("color_by") = "", py::arg("ground") = true, py::arg("scalar_bar") = true,
      "Offscreen VTK render of a mesh: an (height, width, 4) uint8 RGBA array, row 0 at the top");
  m.def(
      "write_image",
      [](const py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>& image,
         const std::string& path) {
        const gr::Image img = image_from(image);
        py::gil_scoped_release release;
        gr::write_image(img, path);
      },
      py::arg("image"), py::arg("path"),
      "Write an RGB(A) uint8 array as .png, .tif, .jpg ... (OpenImageIO), atomically");
  m.def(
      "read_image",
      [](const std::string& path) {
        gr::Image image;
        {
          py::gil_scoped_release release;
          image = gr::read_image(path);
        }
        return image_array(std::move(image));
      },
      py::arg("path"), "Read an image as an (height, width, 4) uint8 RGBA array");
}

}  // namespace

void bind_graphics(py::module_& m) {
  bind_mesh(m);
  bind_render(m);
}

}  // namespace fspm::python
