#include "environment/sky_occlusion_kernel.hpp"

#include "environment/simd_target.hpp"
#include "fspm/dcheck.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>

// Highway compiles the code between HWY_BEFORE_NAMESPACE and HWY_AFTER_NAMESPACE once per target
// by including this file again for each (foreach_target.h); HWY_ONCE marks the single pass for
// the rest. This file is built with -ffp-contract=off (environment/CMakeLists.txt): a fused
// multiply-add on some targets would move directions across a cap's rim differently per target.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "environment/sky_occlusion_kernel.cpp"
#include <hwy/foreach_target.h>  // before highway.h
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace fspm::environment {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The cap as broadcast vectors.
template <class D>
struct CapVectors {
  hn::Vec<D> ax, ay, az, cos_a, gamma;
};

template <class D, typename T>
HWY_INLINE CapVectors<D> broadcast(D d, const OccludingCap<T>& c) {
  return {hn::Set(d, c.axis_x), hn::Set(d, c.axis_y), hn::Set(d, c.axis_z), hn::Set(d, c.cos_a),
          hn::Set(d, c.gamma)};
}

// One vector of directions against one cap: (x*ax + y*ay) + z*az >= cos_a, then vis *= gamma.
template <class D, class V = hn::Vec<D>>
HWY_INLINE V occlude(const CapVectors<D>& c, V x, V y, V z, V vis) {
  const V dot = hn::Add(hn::Add(hn::Mul(x, c.ax), hn::Mul(y, c.ay)), hn::Mul(z, c.az));
  return hn::IfThenElse(dot >= c.cos_a, hn::Mul(vis, c.gamma), vis);
}

// kVectors vectors of directions stay in registers while every cap is applied: the visibilities
// are loaded and stored once per block, not once per cap, and each cap is broadcast once per block.
// (Arrays of vectors need a target of fixed vector size, as every x86 target is.)
template <std::size_t kVectors, class D, typename T>
HWY_INLINE void occlude_block(D d, T* HWY_RESTRICT vis, const T* HWY_RESTRICT x,
                              const T* HWY_RESTRICT y, const T* HWY_RESTRICT z,
                              const OccludingCap<T>* caps, std::size_t count) {
  static_assert(!HWY_HAVE_SCALABLE, "arrays of vectors need a fixed vector size");
  const std::size_t n = hn::Lanes(d);
  hn::Vec<D> vx[kVectors], vy[kVectors], vz[kVectors], vv[kVectors];
  for (std::size_t v = 0; v < kVectors; ++v) {
    vx[v] = hn::LoadU(d, x + v * n);
    vy[v] = hn::LoadU(d, y + v * n);
    vz[v] = hn::LoadU(d, z + v * n);
    vv[v] = hn::LoadU(d, vis + v * n);
  }
  for (std::size_t k = 0; k < count; ++k) {
    const CapVectors<D> c = broadcast(d, caps[k]);
    for (std::size_t v = 0; v < kVectors; ++v) vv[v] = occlude(c, vx[v], vy[v], vz[v], vv[v]);
  }
  for (std::size_t v = 0; v < kVectors; ++v) hn::StoreU(vv[v], d, vis + v * n);
}

// Blocks as large as the registers hold (AVX-512 has 32 vector registers: eight vectors of each of
// x, y, z and visibility; the other targets 16: four), then blocks of four, then single vectors,
// then the last partial vector through a padded copy (a full load past the end would read memory
// that is not ours). The growth model's 64-direction sky is one block on AVX-512.
template <typename T>
void occlude_by_caps_t(T* HWY_RESTRICT vis, const T* HWY_RESTRICT x, const T* HWY_RESTRICT y,
                       const T* HWY_RESTRICT z, std::size_t size, const OccludingCap<T>* caps,
                       std::size_t count) {
  const hn::ScalableTag<T> d;
  const std::size_t n = hn::Lanes(d);
  constexpr bool kWide = HWY_TARGET == HWY_AVX3 || HWY_TARGET == HWY_AVX3_DL;
  std::size_t i = 0;
  if constexpr (kWide) {
    for (; i + 8 * n <= size; i += 8 * n) {
      occlude_block<8>(d, vis + i, x + i, y + i, z + i, caps, count);
    }
  }
  for (; i + 4 * n <= size; i += 4 * n) {
    occlude_block<4>(d, vis + i, x + i, y + i, z + i, caps, count);
  }
  for (; i + n <= size; i += n) occlude_block<1>(d, vis + i, x + i, y + i, z + i, caps, count);
  if (i == size) return;
  HWY_ALIGN T pv[hn::MaxLanes(d)] = {}, px[hn::MaxLanes(d)] = {}, py[hn::MaxLanes(d)] = {},
              pz[hn::MaxLanes(d)] = {};
  const std::size_t left = size - i;
  std::memcpy(pv, vis + i, left * sizeof(T));
  std::memcpy(px, x + i, left * sizeof(T));
  std::memcpy(py, y + i, left * sizeof(T));
  std::memcpy(pz, z + i, left * sizeof(T));
  occlude_block<1>(d, pv, px, py, pz, caps, count);
  std::memcpy(vis + i, pv, left * sizeof(T));
}

void OccludeByCapsF64(double* vis, const double* x, const double* y, const double* z,
                      std::size_t size, const OccludingCap<double>* caps, std::size_t count) {
  occlude_by_caps_t(vis, x, y, z, size, caps, count);
}

void OccludeByCapsF32(float* vis, const float* x, const float* y, const float* z, std::size_t size,
                      const OccludingCap<float>* caps, std::size_t count) {
  occlude_by_caps_t(vis, x, y, z, size, caps, count);
}

std::int64_t OccludeByCapsTarget() { return HWY_TARGET; }

}  // namespace HWY_NAMESPACE
}  // namespace fspm::environment
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fspm::environment {

// Caps as the light models make them: a transmission in [0, 1] and the cosine of a half-angle.
template <typename T>
bool caps_are_caps(std::span<const OccludingCap<T>> caps) {
  return std::all_of(caps.begin(), caps.end(), [](const OccludingCap<T>& c) {
    return c.gamma >= 0 && c.gamma <= 1 && c.cos_a >= -1 && c.cos_a <= 1;
  });
}

HWY_EXPORT(OccludeByCapsF64);
HWY_EXPORT(OccludeByCapsF32);
HWY_EXPORT(OccludeByCapsTarget);

void occlude_by_caps(std::span<double> vis, DirectionColumns<double> dirs,
                     std::span<const OccludingCap<double>> caps) {
  if (vis.empty() || caps.empty()) return;
  FSPM_DCHECK(dirs.x != nullptr && dirs.y != nullptr && dirs.z != nullptr,
              "a direction column for every visibility");
  FSPM_DCHECK(caps_are_caps(caps), "cap transmissions in [0, 1], cosines in [-1, 1]");
  settle_simd_target();
  HWY_DYNAMIC_DISPATCH(OccludeByCapsF64)
  (vis.data(), dirs.x, dirs.y, dirs.z, vis.size(), caps.data(), caps.size());
}

void occlude_by_caps(std::span<float> vis, DirectionColumns<float> dirs,
                     std::span<const OccludingCap<float>> caps) {
  if (vis.empty() || caps.empty()) return;
  FSPM_DCHECK(dirs.x != nullptr && dirs.y != nullptr && dirs.z != nullptr,
              "a direction column for every visibility");
  FSPM_DCHECK(caps_are_caps(caps), "cap transmissions in [0, 1], cosines in [-1, 1]");
  settle_simd_target();
  HWY_DYNAMIC_DISPATCH(OccludeByCapsF32)
  (vis.data(), dirs.x, dirs.y, dirs.z, vis.size(), caps.data(), caps.size());
}

std::string sky_occlusion_target() {
  settle_simd_target();
  std::string name = hwy::TargetName(HWY_DYNAMIC_DISPATCH(OccludeByCapsTarget)());
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return name;
}

}  // namespace fspm::environment
#endif  // HWY_ONCE
