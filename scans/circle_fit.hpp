#pragma once
// An algebraic least-squares circle through points in a plane (Kasa 1976): minimises
// sum (x^2 + y^2 + D x + E y + F)^2, a linear problem that tolerates the partial arcs a scanner
// sees of a stem. The points are first centred on their mean, which keeps the squares small
// (at projected coordinates of 10^6 m, x^2 would leave no digits for a radius of centimetres).
//
// The robust fit reweights the same problem (iteratively reweighted least squares with Tukey's
// biweight, Beaton & Tukey 1974; scale from the median absolute deviation of the residuals), so
// that points off the stem's ring in a breast-height slice (a branch's foot, leaves, a second
// stem, a misregistered scan) stop pulling the circle: the practice of stem-diameter fits on
// terrestrial scans (Pueschel et al. 2013, circle fits with outlier rejection).
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

struct RobustCircle {
  Circle circle;             // rms_m over the inliers
  std::vector<char> inlier;  // per point: within the inlier band of the circle
  std::size_t inliers = 0;
  double median_residual_m = 0.0;  // median |distance from the circle| over all points
};

struct RobustCircleOptions {
  int iterations = 50;     // from a start pulled off by outliers it takes 10-20
  double tukey_c = 4.685;  // biweight cut-off in robust standard deviations (95 % efficiency)
  double inlier_sigmas = 3.0;
  double min_scale_m = 0.002;  // the robust standard deviation is never taken below this
};

// Kasa's circle reweighted by Tukey's biweight, starting from `start` (Kasa's circle of all
// points when empty: a start near one of two stems keeps the fit on that stem). Empty where the
// Kasa fit is.
std::optional<RobustCircle> fit_circle_robust(const std::vector<Eigen::Vector2d>& points,
                                              const RobustCircleOptions& options = {},
                                              const std::optional<Circle>& start = std::nullopt);

// How many of `sectors` equal angular sectors about `centre` hold a point marked in `use`
// (all points when `use` is empty): the arc of the circle the points cover.
int angular_sectors(const std::vector<Eigen::Vector2d>& points, const std::vector<char>& use,
                    const Eigen::Vector2d& centre, int sectors = 12);

// The longest run of consecutive sectors (of `sectors` about `centre`, wrapping around) that hold
// a point marked in `use`: the longest unbroken arc. Branches crossing a slice about a stem hit a
// circle at scattered angles; a stem's own surface is one arc.
int longest_arc_sectors(const std::vector<Eigen::Vector2d>& points, const std::vector<char>& use,
                        const Eigen::Vector2d& centre, int sectors = 36);

}  // namespace fspm::scans
