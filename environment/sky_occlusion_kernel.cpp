#include "environment/sky_occlusion_kernel.hpp"

#include "environment/simd_target.hpp"

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

// Four vectors of directions stay in registers while every cap is applied: the visibilities are
// loaded and stored once per block, not once per cap.
template <class D, typename T>
HWY_INLINE void occlude_four(D d, T* HWY_RESTRICT vis, const T* HWY_RESTRICT x,
                             const T* HWY_RESTRICT y, const T* HWY_RESTRICT z,
                             const OccludingCap<T>* caps, std::size_t count) {
  const std::size_t n = hn::Lanes(d);
  const auto x0 = hn::LoadU(d, x), x1 = hn::LoadU(d, x + n), x2 = hn::LoadU(d, x + 2 * n),
             x3 = hn::LoadU(d, x + 3 * n);
  const auto y0 = hn::LoadU(d, y), y1 = hn::LoadU(d, y + n), y2 = hn::LoadU(d, y + 2 * n),
             y3 = hn::LoadU(d, y + 3 * n);
  const auto z0 = hn::LoadU(d, z), z1 = hn::LoadU(d, z + n), z2 = hn::LoadU(d, z + 2 * n),
             z3 = hn::LoadU(d, z + 3 * n);
  auto v0 = hn::LoadU(d, vis), v1 = hn::LoadU(d, vis + n), v2 = hn::LoadU(d, vis + 2 * n),
       v3 = hn::LoadU(d, vis + 3 * n);
  for (std::size_t k = 0; k < count; ++k) {
    const CapVectors<D> c = broadcast(d, caps[k]);
    v0 = occlude(c, x0, y0, z0, v0);
    v1 = occlude(c, x1, y1, z1, v1);
    v2 = occlude(c, x2, y2, z2, v2);
    v3 = occlude(c, x3, y3, z3, v3);
  }
  hn::StoreU(v0, d, vis);
  hn::StoreU(v1, d, vis + n);
  hn::StoreU(v2, d, vis + 2 * n);
  hn::StoreU(v3, d, vis + 3 * n);
}

// One vector of directions through every cap.
template <class D, typename T>
HWY_INLINE void occlude_one(D d, T* HWY_RESTRICT vis, const T* HWY_RESTRICT x,
                            const T* HWY_RESTRICT y, const T* HWY_RESTRICT z,
                            const OccludingCap<T>* caps, std::size_t count) {
  const auto vx = hn::LoadU(d, x), vy = hn::LoadU(d, y), vz = hn::LoadU(d, z);
  auto v = hn::LoadU(d, vis);
  for (std::size_t k = 0; k < count; ++k) v = occlude(broadcast(d, caps[k]), vx, vy, vz, v);
  hn::StoreU(v, d, vis);
}

// Blocks of four vectors, then single vectors, then the last partial vector through a padded copy
// (a full load past the end would read memory that is not ours).
template <typename T>
void occlude_by_caps_t(T* HWY_RESTRICT vis, const T* HWY_RESTRICT x, const T* HWY_RESTRICT y,
                       const T* HWY_RESTRICT z, std::size_t size, const OccludingCap<T>* caps,
                       std::size_t count) {
  const hn::ScalableTag<T> d;
  const std::size_t n = hn::Lanes(d);
  std::size_t i = 0;
  for (; i + 4 * n <= size; i += 4 * n) occlude_four(d, vis + i, x + i, y + i, z + i, caps, count);
  for (; i + n <= size; i += n) occlude_one(d, vis + i, x + i, y + i, z + i, caps, count);
  if (i == size) return;
  HWY_ALIGN T pv[hn::MaxLanes(d)] = {}, px[hn::MaxLanes(d)] = {}, py[hn::MaxLanes(d)] = {},
              pz[hn::MaxLanes(d)] = {};
  const std::size_t left = size - i;
  std::memcpy(pv, vis + i, left * sizeof(T));
  std::memcpy(px, x + i, left * sizeof(T));
  std::memcpy(py, y + i, left * sizeof(T));
  std::memcpy(pz, z + i, left * sizeof(T));
  occlude_one(d, pv, px, py, pz, caps, count);
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

HWY_EXPORT(OccludeByCapsF64);
HWY_EXPORT(OccludeByCapsF32);
HWY_EXPORT(OccludeByCapsTarget);

void occlude_by_caps(std::span<double> vis, DirectionColumns<double> dirs,
                     std::span<const OccludingCap<double>> caps) {
  if (vis.empty() || caps.empty()) return;
  settle_simd_target();
  HWY_DYNAMIC_DISPATCH(OccludeByCapsF64)
  (vis.data(), dirs.x, dirs.y, dirs.z, vis.size(), caps.data(), caps.size());
}

void occlude_by_caps(std::span<float> vis, DirectionColumns<float> dirs,
                     std::span<const OccludingCap<float>> caps) {
  if (vis.empty() || caps.empty()) return;
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
