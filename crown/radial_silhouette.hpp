#pragma once
// Argudo's first, discarded crown shape (4.2): the radial silhouette r(phi), the distance from the
// mask's centroid to the last crown pixel along the ray at angle phi (the last intersection, which
// overestimates concave crowns), and its revolution into 3D, R(phi, theta), interpolating the
// profile on the right of the crown with its mirror on the left by the horizontal angle. Kept as a
// baseline for the inflation (docs/crown.md); the pipeline uses the inflation.
#include <Eigen/Core>
#include <vector>

#include "crown/raster.hpp"

namespace fspm::crown {

class RadialSilhouette {
 public:
  // `angles` rays, evenly spaced. Throws ValueError for an empty mask or fewer than 4 angles.
  RadialSilhouette(const Mask& mask, int angles = 360);

  // Centroid of the crown pixels (column, row).
  const Eigen::Vector2d& centre_px() const { return centre_; }
  // r(phi) in pixels, phi in radians from the image's right, counterclockwise (toward the top),
  // linearly interpolated between rays.
  double radius_px(double phi) const;
  // R(phi, theta) for a 3D direction (x right, y away from the camera, z up): with alpha its
  // elevation and theta its horizontal angle from +x, (1 - |theta|/pi) r(alpha) +
  // (|theta|/pi) r(pi - alpha). Argudo writes the same revolution with r(phi) and r(-phi) in his
  // angle convention.
  double radius_px(const Eigen::Vector3d& direction) const;

 private:
  Eigen::Vector2d centre_;
  std::vector<double> radius_;
};

}  // namespace fspm::crown
