// Wavefront OBJ with an MTL material library: one material per kind of surface (bark, leaf,
// obstacle, crown, translucent obstacle), and one per translucency of translucent obstacles.
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "fspm/atomic_file.hpp"
#include "graphics/mesh_writers.hpp"

namespace fspm::graphics {
namespace {

// The fixed materials, then one `translucent_obstacle_<gamma>` per translucency of the
// translucent obstacles, at their opacity 1 - gamma (translucent_obstacle_opacity).
void write_mtl(const std::string& path, const std::map<float, std::string>& translucent) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "# fspm materials\n"
           "newmtl bark\nKa 0 0 0\nKd 0.45 0.32 0.20\nKs 0.05 0.05 0.05\nNs 10\nillum 2\n\n"
           "newmtl leaf\nKa 0 0 0\nKd 0.25 0.55 0.15\nKs 0.10 0.10 0.10\nNs 20\nillum 2\n\n"
           "newmtl obstacle\nKa 0 0 0\nKd 0.62 0.61 0.58\nKs 0.02 0.02 0.02\nNs 5\nillum 2\n\n"
           "newmtl crown\nKa 0 0 0\nKd 0.35 0.62 0.25\nKs 0.02 0.02 0.02\nNs 5\nd 0.35\nillum 2\n\n"
           "newmtl translucent_obstacle\nKa 0 0 0\nKd 0.80 0.80 0.77\nKs 0.02 0.02 0.02\nNs 5\n"
           "d 0.4\nillum 2\n\n"
           "newmtl terrain\nKa 0 0 0\nKd 0.52 0.50 0.34\nKs 0.02 0.02 0.02\nNs 5\nillum 2\n";
    for (const auto& [gamma, name] : translucent) {
      out << fmt::format(
          "\nnewmtl {}\nKa 0 0 0\nKd 0.80 0.80 0.77\nKs 0.02 0.02 0.02\nNs 5\nd {:.3g}\nillum 2\n",
          name, translucent_obstacle_opacity(gamma));
    }
  });
}

// The material name of each triangle; translucent obstacles with the vertex attribute
// "translucency" take the name of their gamma, listed in `translucent`.
std::vector<std::string> triangle_material_names(const TriangleMesh& mesh,
                                                 std::map<float, std::string>& translucent) {
  std::vector<std::string> names(mesh.triangle_count());
  const bool gammas = mesh.has_attribute("translucency");
  for (std::size_t i = 0; i < names.size(); ++i) {
    const Material m = i < mesh.materials.size() ? mesh.materials[i] : Material::kBark;
    names[i] = material_name(m);
    if (m != Material::kTranslucentObstacle || !gammas) continue;
    const float gamma = mesh.attribute("translucency")[mesh.triangles[i][0]];
    auto [it, added] = translucent.emplace(gamma, "");
    if (added)
      it->second = fmt::format("translucent_obstacle_{:g}", std::round(gamma * 1000.0) / 1000.0);
    names[i] = it->second;
  }
  return names;
}

}  // namespace

void write_obj(const TriangleMesh& mesh, const std::string& path) {
  const std::filesystem::path obj(path);
  std::filesystem::path mtl = obj;
  mtl.replace_extension(".mtl");
  std::map<float, std::string> translucent;
  const std::vector<std::string> names = triangle_material_names(mesh, translucent);
  // The .obj and its .mtl both, or neither (a full disk on the .obj must not leave the .mtl).
  OutputTransaction both;
  write_mtl(mtl.string(), translucent);
  write_file_atomically(path, [&](std::ostream& out) {
    fmt::memory_buffer buf;
    auto flush = [&] {
      out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
      buf.clear();
    };
    fmt::format_to(std::back_inserter(buf), "# fspm mesh: {} vertices, {} triangles\nmtllib {}\n",
                   mesh.vertex_count(), mesh.triangle_count(), mtl.filename().string());
    for (const auto& p : mesh.positions) {
      fmt::format_to(std::back_inserter(buf), "v {} {} {}\n", p.x(), p.y(), p.z());
      if (buf.size() > (1 << 20)) flush();
    }
    for (const auto& n : mesh.normals) {
      fmt::format_to(std::back_inserter(buf), "vn {} {} {}\n", n.x(), n.y(), n.z());
      if (buf.size() > (1 << 20)) flush();
    }
    for (const auto& t : mesh.uvs) {
      fmt::format_to(std::back_inserter(buf), "vt {} {}\n", t.x(), t.y());
      if (buf.size() > (1 << 20)) flush();
    }
    const std::string* current = nullptr;
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
      if (current == nullptr || names[i] != *current) {
        current = &names[i];
        fmt::format_to(std::back_inserter(buf), "usemtl {}\n", names[i]);
      }
      const auto& t = mesh.triangles[i];
      fmt::format_to(std::back_inserter(buf), "f {0}/{0}/{0} {1}/{1}/{1} {2}/{2}/{2}\n", t[0] + 1,
                     t[1] + 1, t[2] + 1);
      if (buf.size() > (1 << 20)) flush();
    }
    flush();
  });
  both.commit();
}

}  // namespace fspm::graphics
