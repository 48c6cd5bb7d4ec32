#include "scans/point_set_writer.hpp"

#include <algorithm>
#include <filesystem>
#include <ostream>

#include "fspm/atomic_file.hpp"
#include "fspm/error.hpp"
#include "fspm/file_kind.hpp"
#include "fspm/number_text.hpp"

namespace fspm::scans {

void write_point_set(const PointSet& ps, const std::string& path) {
  // The point readers refuse an empty file, so an empty one would be a result no one can read.
  if (ps.points.empty()) {
    throw ValueError(
        "no point to write: the point set is empty (a scan of a tree with no visible surface, "
        "or too low a density)",
        path);
  }
  // By kind (fspm/file_kind.hpp); of the XYZ kind's extensions only .xyz, written space-separated.
  const FileKind kind = file_kind_by_extension(path);
  if (kind == FileKind::kPly) {
    double largest = 0.0;
    for (const Eigen::Vector3d& p : ps.points) largest = std::max(largest, p.cwiseAbs().maxCoeff());
    const bool wide = largest > kPlyFloatLimitM;
    write_file_atomically(
        path,
        [&](std::ostream& out) {
          const char* type = wide ? "double" : "float";
          out << "ply\nformat binary_little_endian 1.0\ncomment fspm point set\nelement vertex "
              << ps.points.size() << "\nproperty " << type << " x\nproperty " << type
              << " y\nproperty " << type << " z\nend_header\n";
          for (const Eigen::Vector3d& p : ps.points) {
            if (wide) {
              out.write(reinterpret_cast<const char*>(p.data()), 3 * sizeof(double));
              continue;
            }
            const float xyz[3] = {static_cast<float>(p.x()), static_cast<float>(p.y()),
                                  static_cast<float>(p.z())};
            out.write(reinterpret_cast<const char*>(xyz), sizeof xyz);
          }
        },
        true);
  } else if (kind == FileKind::kXyz && table_extension(path) == ".xyz") {
    write_file_atomically(path, [&](std::ostream& out) {
      std::string line;
      for (const Eigen::Vector3d& p : ps.points) {
        line.clear();
        for (int c = 0; c < 3; ++c) {
          append_number(line, p[c]);
          line += c < 2 ? ' ' : '\n';
        }
        out << line;
      }
    });
  } else {
    const std::string ext = std::filesystem::path(path).extension().string();
    throw ValueError("unknown point-set extension '" + ext + "', expected .ply or .xyz", path);
  }
}

}  // namespace fspm::scans
