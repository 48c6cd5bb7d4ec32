#include "graphics/relief_crown.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <string>

#include "fspm/error.hpp"

namespace fspm::graphics {
namespace {

struct FaceCoordinates {
  int face = 0;
  float u = 0.0f;  // in [-1, 1], right on the face as drawn
  float v = 0.0f;  // in [-1, 1], down
};

// The inverse of crown/cubemap.cpp's texel_direction: which face a direction falls on, and where.
FaceCoordinates face_coordinates(const Eigen::Vector3f& d) {
  const Eigen::Vector3f a = d.cwiseAbs();
  if (a.z() >= a.x() && a.z() >= a.y()) {
    const bool top = d.z() > 0.0f;
    return {top ? 4 : 5, d.x() / a.z(), (top ? -d.y() : d.y()) / a.z()};
  }
  if (a.x() >= a.y()) {
    const bool right = d.x() > 0.0f;
    return {right ? 1 : 3, (right ? d.y() : -d.y()) / a.x(), -d.z() / a.x()};
  }
  const bool front = d.y() < 0.0f;
  return {front ? 0 : 2, (front ? d.x() : -d.x()) / a.y(), -d.z() / a.y()};
}

// Bilinear lookup of `Channels` channels of a 6N x N strip within the face of d, clamped to the
// face's outer texel centres (at (i + 0.5) / N) so no sample leaves it.
template <int Channels, typename T>
Eigen::Matrix<float, Channels, 1> sample_strip(const std::vector<T>& strip, int n,
                                               const Eigen::Vector3f& d) {
  const FaceCoordinates f = face_coordinates(d);
  const float x = std::clamp(0.5f * (f.u + 1.0f) * n - 0.5f, 0.0f, n - 1.0f);
  const float y = std::clamp(0.5f * (f.v + 1.0f) * n - 0.5f, 0.0f, n - 1.0f);
  const int x0 = std::min(static_cast<int>(x), n - 1), y0 = std::min(static_cast<int>(y), n - 1);
  const int x1 = std::min(x0 + 1, n - 1), y1 = std::min(y0 + 1, n - 1);
  const float fx = x - x0, fy = y - y0;
  auto at = [&](int xi, int yi) {
    const std::size_t texel = static_cast<std::size_t>(yi) * 6 * n + f.face * n + xi;
    Eigen::Matrix<float, Channels, 1> v;
    for (int k = 0; k < Channels; ++k) v[k] = static_cast<float>(strip[Channels * texel + k]);
    return v;
  };
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x1, y0)) +
         fy * ((1 - fx) * at(x0, y1) + fx * at(x1, y1));
}

}  // namespace

float ReliefCrown::max_radius_m() const {
  return radius_m.empty() ? 0.0f : *std::max_element(radius_m.begin(), radius_m.end());
}

Eigen::AlignedBox3f ReliefCrown::placed_bounds() const {
  Eigen::AlignedBox3f box;
  const float r = max_radius_m();
  for (const Eigen::Matrix4f& m : placements) {
    for (int k = 0; k < 8; ++k) {
      const Eigen::Vector3f corner =
          centre_m + r * Eigen::Vector3f(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
      box.extend((m * corner.homogeneous()).head<3>());
    }
  }
  return box;
}

void ReliefCrown::validate() const {
  const auto n = static_cast<std::size_t>(std::max(face_size, 0));
  if (face_size < 1) throw ValueError("relief crown: expected a cubemap face_size >= 1");
  if (radius_m.size() != 6 * n * n || rgb.size() != 3 * 6 * n * n) {
    throw ValueError("relief crown: expected radius_m and rgb strips of 6N x N texels (N = " +
                     std::to_string(n) + ")");
  }
  for (float r : radius_m) {
    if (!std::isfinite(r) || r < 0.0f) {
      throw ValueError("relief crown: expected radius_m values that are finite and >= 0");
    }
  }
  if (!(max_radius_m() > 0.0f) || !centre_m.allFinite()) {
    throw ValueError("relief crown: expected a finite centre_m and a radius_m above 0");
  }
  for (const Eigen::Matrix4f& m : placements) {
    if (!m.allFinite() || std::abs(m.block<3, 3>(0, 0).determinant()) < 1e-12f) {
      throw ValueError("relief crown: expected finite, invertible placements");
    }
  }
  for (const Eigen::Vector3f& b : billboards_m) {
    if (!b.allFinite()) throw ValueError("relief crown: expected finite billboards_m");
  }
}

float billboard_count(float radius_px, std::size_t available) {
  if (!(radius_px >= kBillboardFromPx) || available == 0) return 0.0f;
  const float all = static_cast<float>(available);
  const float share =
      std::min(1.0f, (radius_px * radius_px) / (kAllBillboardsPx * kAllBillboardsPx));
  return std::min(all, std::max(kFewestBillboards, share * all));
}

float relief_radius_m(const ReliefCrown& crown, const Eigen::Vector3f& direction) {
  return sample_strip<1>(crown.radius_m, crown.face_size, direction)[0];
}

Eigen::Vector3f relief_color(const ReliefCrown& crown, const Eigen::Vector3f& direction) {
  return sample_strip<3>(crown.rgb, crown.face_size, direction) / 255.0f;
}

bool relief_ray_hit(const ReliefCrown& crown, float bound, const Eigen::Vector3f& origin,
                    const Eigen::Vector3f& dir, float& t) {
  const Eigen::Vector3f oc = origin - crown.centre_m;
  const float b = oc.dot(dir);
  const float disc = b * b - (oc.squaredNorm() - bound * bound);
  if (disc < 0.0f) return false;
  const float t0 = std::max(-b - std::sqrt(disc), 0.0f), t1 = -b + std::sqrt(disc);
  if (t1 <= t0) return false;
  const auto inside = [&](float s) {
    const Eigen::Vector3f q = origin + s * dir - crown.centre_m;
    const float r = q.norm();
    return r < 1e-6f * bound || r <= relief_radius_m(crown, q);
  };
  const float dt = (t1 - t0) / kReliefSteps;
  float s = t0;
  int i = 0;
  for (; i <= kReliefSteps && !inside(s); ++i) s += dt;
  if (i > kReliefSteps) return false;
  float lo = std::max(s - dt, t0), hi = s;
  for (int k = 0; k < 16 && i > 0; ++k) {
    const float mid = 0.5f * (lo + hi);
    (inside(mid) ? hi : lo) = mid;
  }
  t = hi;
  return true;
}

Eigen::Vector3f relief_shade(const Eigen::Vector3f& albedo, const Eigen::Vector3f& q,
                             float surface_r, float bound, const Eigen::Vector3f& n,
                             const Eigen::Vector3f& sun) {
  // The constants of kCrownGlsl's crown_shade (graphics/viewer_relief_glfw.cpp).
  const float height = std::clamp(0.5f + 0.5f * q.z() / bound, 0.0f, 1.0f);
  const float depth = std::clamp(q.norm() / std::max(surface_r, 1e-6f * bound), 0.0f, 1.0f);
  const float occlusion = (0.8f + 0.2f * height) * (0.75f + 0.25f * depth);
  const float light = 0.35f + 0.65f * std::max(n.dot(sun), 0.0f);
  Eigen::Vector3f c = albedo * occlusion * light;
  for (int k = 0; k < 3; ++k) c[k] = std::pow(std::clamp(c[k], 0.0f, 1.0f), 1.0f / 1.2f);
  return c;
}

}  // namespace fspm::graphics
