// ParaView .pvd collection: one .vtp per age of a growth sequence, time steps = ages.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <ostream>
#include <set>
#include <sstream>

#include "fspm/atomic_file.hpp"
#include "fspm/error.hpp"
#include "graphics/mesh_writers.hpp"

namespace fspm::graphics {

std::vector<double> default_ages(const TreeGraph& tree, std::size_t max_frames) {
  std::set<double> births(tree.birth_times().begin(), tree.birth_times().end());
  if (births.empty()) return {};
  if (births.size() <= max_frames || max_frames < 2) {
    return {births.begin(), births.end()};
  }
  const double lo = *births.begin();
  const double hi = *births.rbegin();
  std::vector<double> ages(max_frames);
  for (std::size_t i = 0; i < max_frames; ++i) {
    ages[i] = lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(max_frames - 1);
  }
  return ages;
}

std::vector<PvdFrame> write_pvd(const TreeGraph& tree, const MeshOptions& options,
                                std::vector<double> ages, const std::string& path) {
  if (ages.empty()) throw ValueError("a growth sequence needs at least one age", path);
  for (double a : ages) {
    if (!std::isfinite(a)) throw ValueError("ages must be finite numbers", path);
  }
  std::sort(ages.begin(), ages.end());
  ages.erase(std::unique(ages.begin(), ages.end()), ages.end());

  const std::filesystem::path pvd(path);
  const std::string stem = pvd.stem().string();
  std::vector<PvdFrame> frames;
  for (std::size_t i = 0; i < ages.size(); ++i) {
    MeshOptions at_age = options;
    at_age.max_birth_time = ages[i];
    const TriangleMesh mesh = mesh_tree(tree, at_age);
    std::ostringstream name;
    name << stem << '_' << std::setw(4) << std::setfill('0') << i << ".vtp";
    std::filesystem::path vtp = pvd;
    vtp.replace_filename(name.str());
    write_vtp(mesh, vtp.string());
    frames.push_back({ages[i], vtp.string(), mesh.vertex_count(), mesh.triangle_count()});
  }
  write_file_atomically(path, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <Collection>\n";
    out << std::setprecision(17);
    for (const PvdFrame& f : frames) {
      out << "    <DataSet timestep=\"" << f.age << "\" group=\"\" part=\"0\" file=\""
          << std::filesystem::path(f.vtp_path).filename().string() << "\"/>\n";
    }
    out << "  </Collection>\n</VTKFile>\n";
  });
  return frames;
}

}  // namespace fspm::graphics
