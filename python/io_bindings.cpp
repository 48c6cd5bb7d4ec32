// Python bindings: any input file as the data it holds (io/input_registry.hpp), by its kind
// (extension, or first bytes when the extension names none; fspm/file_kind.hpp).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <type_traits>
#include <variant>

#include "environment/scene_file.hpp"
#include "io/input_registry.hpp"
#include "python/bindings.hpp"

namespace fspm::python {
namespace {

// The data of a file as the Python object the other bindings give for it.
py::object to_python(io::InputData data) {
  return std::visit(
      [](auto&& value) -> py::object {
        using T = std::decay_t<decltype(value)>;
        if constexpr (std::is_same_v<T, scans::PointSet>) {
          return vector_rows(value.points);
        } else if constexpr (std::is_same_v<T, SceneDescription>) {
          return py::cast(environment::scene_from_description(value));
        } else if constexpr (std::is_same_v<T, std::vector<io::MeshStep>>) {
          py::list steps;
          for (auto& step : value) steps.append(py::make_tuple(step.time, std::move(step.mesh)));
          return steps;
        } else {
          return py::cast(std::move(value));
        }
      },
      std::move(data));
}

}  // namespace

void bind_io(py::module_& m) {
  m.def(
      "load",
      [](const std::string& path) {
        io::InputData data;
        {
          py::gil_scoped_release release;
          data = io::read_input(path);
        }
        return to_python(std::move(data));
      },
      py::arg("path"),
      "Read any input file fspm reads, as the file is, chosen by its extension (or, when the "
      "extension names none, its first bytes): a Tree (.tree, .treeb, .nwk, .mtg), a "
      "CompressedPlant (.ctree), PlantParams (GreenLab .toml), a Scene (.json), the Tree an "
      "L-system (.l) draws with its file's steps and seed, a TriangleMesh (.obj, .gltf, .glb, .vtp "
      "and .ply with faces), a list of (time, TriangleMesh) of a .pvd growth sequence, an (N, 3) "
      "float64 array of points in m (.ply without faces, .xyz/.txt/.csv, .pcd, .las) or a "
      "ClusterModel (.clusters); a folder written by fspm crown stands for its crown.glb");
}

}  // namespace fspm::python
