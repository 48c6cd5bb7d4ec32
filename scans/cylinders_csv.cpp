#include "scans/cylinders_csv.hpp"

#include <ostream>

#include "fspm/atomic_file.hpp"
#include "fspm/number_text.hpp"

namespace fspm::scans {

std::string cylinders_csv(const std::vector<QsmCylinder>& cylinders) {
  std::string out =
      "start_x,start_y,start_z,axis_x,axis_y,axis_z,length,radius,parent,branch,order,nested\n";
  for (const QsmCylinder& c : cylinders) {
    for (const Eigen::Vector3d* v : {&c.start, &c.axis}) {
      for (int k = 0; k < 3; ++k) {
        append_number(out, (*v)[k]);
        out += ',';
      }
    }
    append_number(out, c.length_m);
    out += ',';
    append_number(out, c.radius_m);
    out += ',' + std::to_string(c.parent + 1) + ',' + std::to_string(c.branch + 1) + ',' +
           std::to_string(c.order) + ',' + (c.nested ? "1" : "0") + '\n';
  }
  return out;
}

void write_cylinders_csv(const std::vector<QsmCylinder>& cylinders, const std::string& path) {
  const std::string text = cylinders_csv(cylinders);
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace fspm::scans
