#pragma once
// Occlusion of sky directions by spherical caps: the inner loop of the sky light (Pirk eq. 4.3),
// shared by LightModel (double precision) and ClusterLightField (single precision).
//
// A direction d lies in a cap when d . axis >= cos(alpha); each cap holding it multiplies its
// visibility by the cap's transmission gamma (Pirk eq. 4.4). Written once with Google Highway and
// compiled for every x86-64 vector instruction set; the best one of the running processor is
// picked at run time (environment/simd_target.hpp forces another).
#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace fspm::environment {

// One occluding cap as the kernel reads it: unit axis, cosine of the half-angle, transmission.
template <typename T>
struct OccludingCap {
  T axis_x, axis_y, axis_z;
  T cos_a;
  T gamma;
};

// A cap of the light models (axis, cos_a, gamma) in the kernel's precision.
template <typename T, class Cap>
OccludingCap<T> occluding_cap(const Cap& c) {
  return {static_cast<T>(c.axis.x()), static_cast<T>(c.axis.y()), static_cast<T>(c.axis.z()),
          static_cast<T>(c.cos_a), static_cast<T>(c.gamma)};
}

// All `caps` packed into `out` (kept by the caller to reuse its memory).
template <typename T, class Cap>
std::span<const OccludingCap<T>> occluding_caps(std::span<const Cap> caps,
                                                std::vector<OccludingCap<T>>& out) {
  out.resize(caps.size());
  for (std::size_t k = 0; k < caps.size(); ++k) out[k] = occluding_cap<T>(caps[k]);
  return out;
}

// Sky directions as three columns (structure of arrays), each with one entry per direction.
template <typename T>
struct DirectionColumns {
  const T* x;
  const T* y;
  const T* z;
};

// vis[i] *= gamma_k for every cap k with x[i]*ax + y[i]*ay + z[i]*az >= cos_a, caps taken in order.
// Every target does the same IEEE operations per direction (products and sums unfused, the same
// order), so all targets and the plain loop give the same bits.
void occlude_by_caps(std::span<double> vis, DirectionColumns<double> dirs,
                     std::span<const OccludingCap<double>> caps);
void occlude_by_caps(std::span<float> vis, DirectionColumns<float> dirs,
                     std::span<const OccludingCap<float>> caps);

// The Highway target occlude_by_caps runs now ("avx3", "avx2", "sse4", "scalar", ...).
std::string sky_occlusion_target();

}  // namespace fspm::environment
