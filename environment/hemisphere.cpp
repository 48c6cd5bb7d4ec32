#include "environment/hemisphere.hpp"

#include <string>

#include "fspm/error.hpp"

namespace fspm::environment {

HemisphereDirections::HemisphereDirections(int count) {
  if (count < 1) {
    throw ValueError("direction count must be at least 1, got " + std::to_string(count));
  }
  const double pi = std::numbers::pi;
  cell_sr_ = 2.0 * pi / count;
  // Rings of roughly square cells: side s = sqrt(cell area), about (pi/2)/s rings.
  const int rings = std::max(1, static_cast<int>(std::lround(0.5 * pi / std::sqrt(cell_sr_))));
  std::vector<double> share(rings);
  double total = 0.0;
  for (int r = 0; r < rings; ++r) {
    const double theta = (r + 0.5) * 0.5 * pi / rings;
    share[r] = std::sin(theta);
    total += share[r];
  }
  std::vector<int> sizes(rings);
  int assigned = 0;
  for (int r = 0; r < rings; ++r) {
    sizes[r] = std::max(1, static_cast<int>(std::lround(count * share[r] / total)));
    assigned += sizes[r];
  }
  // Fix rounding on the largest rings so the sizes sum to count.
  while (assigned != count) {
    int best = rings - 1;
    for (int r = 0; r < rings; ++r) {
      if (assigned > count ? sizes[r] > sizes[best] : share[r] > share[best]) best = r;
    }
    if (assigned > count && sizes[best] == 1) break;  // cannot happen for rings <= count
    sizes[best] += assigned > count ? -1 : 1;
    assigned += assigned > count ? -1 : 1;
  }
  // Each cell has equal area 2*pi/N, so a ring of n cells spans n/N in z (Archimedes).
  double z_top = 1.0;
  for (int r = 0; r < rings; ++r) {
    if (sizes[r] <= 0) continue;
    const double dz = static_cast<double>(sizes[r]) / count;
    const double z = z_top - 0.5 * dz;
    z_top -= dz;
    const int first = static_cast<int>(dirs_.size());
    const double step = 2.0 * pi / sizes[r];
    const double offset = (r % 2) * 0.5 * step;  // stagger neighbouring rings
    const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    for (int k = 0; k < sizes[r]; ++k) {
      const double phi = offset + (k + 0.5) * step;
      dirs_.emplace_back(s * std::cos(phi), s * std::sin(phi), z);
    }
    ring_first_.push_back(first);
    ring_size_.push_back(sizes[r]);
    ring_z_.push_back(z);
    ring_offset_.push_back(offset);
  }
  const Eigen::Index n = static_cast<Eigen::Index>(dirs_.size());
  xs_.resize(n);
  ys_.resize(n);
  zs_.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    xs_[i] = dirs_[i].x();
    ys_[i] = dirs_[i].y();
    zs_[i] = dirs_[i].z();
  }
}

}  // namespace fspm::environment
