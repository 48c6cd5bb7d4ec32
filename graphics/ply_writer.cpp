// Binary little-endian PLY: x y z nx ny nz s t and every attribute as a float vertex property;
// faces as uchar-counted uint index lists with a uchar material (0 bark, 1 leaf, 2 obstacle,
// 3 crown, 4 translucent obstacle).
#include <bit>
#include <cstring>
#include <ostream>
#include <vector>

#include "fspm/atomic_file.hpp"
#include "graphics/mesh_writers.hpp"

namespace fspm::graphics {

static_assert(std::endian::native == std::endian::little, "PLY writer assumes little endian");

namespace {
std::string property_name(const std::string& name) {
  std::string out = name;
  for (char& c : out) {
    if (c == ' ' || c == '\t' || c == '\n') c = '_';
  }
  return out.empty() ? std::string("unnamed") : out;
}
}  // namespace

void write_ply(const TriangleMesh& mesh, const std::string& path) {
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        out << "ply\nformat binary_little_endian 1.0\ncomment fspm mesh\n"
            << "element vertex " << mesh.vertex_count() << "\n"
            << "property float x\nproperty float y\nproperty float z\n"
            << "property float nx\nproperty float ny\nproperty float nz\n"
            << "property float s\nproperty float t\n";
        for (const auto& a : mesh.attributes)
          out << "property float " << property_name(a.name) << "\n";
        out << "element face " << mesh.triangle_count() << "\n"
            << "property list uchar uint vertex_indices\nproperty uchar material\nend_header\n";
        const std::size_t per_vertex = 8 + mesh.attributes.size();
        std::vector<float> row;
        constexpr std::size_t kBlock = 65536;
        row.reserve(kBlock * per_vertex);
        for (std::size_t i = 0; i < mesh.vertex_count(); ++i) {
          const auto& p = mesh.positions[i];
          const auto& n = mesh.normals[i];
          const auto& t = mesh.uvs[i];
          row.insert(row.end(), {p.x(), p.y(), p.z(), n.x(), n.y(), n.z(), t.x(), t.y()});
          for (const auto& a : mesh.attributes) row.push_back(a.values[i]);
          if (row.size() >= kBlock * per_vertex || i + 1 == mesh.vertex_count()) {
            out.write(reinterpret_cast<const char*>(row.data()),
                      static_cast<std::streamsize>(row.size() * sizeof(float)));
            row.clear();
          }
        }
        std::vector<char> faces;
        faces.reserve(kBlock * 14);
        for (std::size_t i = 0; i < mesh.triangle_count(); ++i) {
          char rec[14];
          rec[0] = 3;
          std::memcpy(rec + 1, mesh.triangles[i].data(), 12);
          rec[13] =
              static_cast<char>(i < mesh.materials.size() ? mesh.materials[i] : Material::kBark);
          faces.insert(faces.end(), rec, rec + 14);
          if (faces.size() >= kBlock * 14 || i + 1 == mesh.triangle_count()) {
            out.write(faces.data(), static_cast<std::streamsize>(faces.size()));
            faces.clear();
          }
        }
      },
      true);
}

}  // namespace fspm::graphics
