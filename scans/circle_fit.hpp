#pragma once
// An algebraic least-squares circle through points in a plane (Kasa 1976): minimises
// sum (x^2 + y^2 + D x + E y + F)^2, a linear problem that tolerates the partial arcs a scanner
// sees of a stem. The points are first centred on their mean, which keeps the squares small
// (at projected coordinates of 10^6 m, x^2 would leave no digits for a radius of centimetres).
#include <Eigen/Core>
#include <optional>
#include <vector>

namespace fspm::scans {

struct Circle {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius_m = 0.0;
  double rms_m = 0.0;  // root-mean-square distance of the points from the circle
};

// Empty for fewer than 3 points, collinear points or a non-finite result.
std::optional<Circle> fit_circle_kasa(const std::vector<Eigen::Vector2d>& points);

}  // namespace fspm::scans
