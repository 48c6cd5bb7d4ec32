#pragma once
// Variance shadow maps (Donnelly and Lauritzen, as used by Pirk 6.2.3): the shadow map stores the
// first two moments of the depth seen from the light, M1 = E(x) and M2 = E(x^2) (Pirk eq. 6.10),
// which survive filtering (blurring, linear interpolation) unlike the depths themselves. From the
// filtered moments the mean mu = M1 and variance sigma^2 = M2 - M1^2 (eq. 6.11) bound the share of
// the filter region at least as far from the light as a receiver at depth t, by the one-sided
// Chebyshev inequality P(x >= t) <= p_max = sigma^2 / (sigma^2 + (t - mu)^2) for t > mu (eq. 6.12,
// printed there with (t - mu^2), a misprint: the bound is in the squared distance to the mean).
// The viewer's shaders evaluate the same formulas; these are their CPU twins, for tests.

namespace fspm::graphics {

// Smallest variance used, in squared light-space depth units (depth in [0, 1] across the light's
// view volume): keeps a lit surface from shadowing itself where the filtered variance is ~0.
inline constexpr double kVsmMinVariance = 2e-6;
// Light-bleeding reduction: bounds below this are taken as full shadow and the rest stretched back
// to [0, 1] (Lauritzen, "Summed-area variance shadow maps", GPU Gems 3): where two occluders
// overlap, the bound of eq. 6.12 is loose and lets light through the nearer one's shadow.
inline constexpr double kVsmBleedReduction = 0.2;

// p_max of Pirk eq. 6.12 for a receiver at light-space depth t from the moments m1 = E(x),
// m2 = E(x^2): 1 where t <= mu (the receiver is in front of the mean occluder), else
// sigma^2 / (sigma^2 + (t - mu)^2) with sigma^2 = max(m2 - m1^2, min_variance) (eq. 6.11).
double chebyshev_upper_bound(double m1, double m2, double t, double min_variance = kVsmMinVariance);

// The light reaching the receiver, in [0, 1]: the bound with light bleeding reduced,
// clamp((p_max - bleed) / (1 - bleed), 0, 1). `bleed` in [0, 1).
double variance_shadow_light(double m1, double m2, double t, double min_variance = kVsmMinVariance,
                             double bleed = kVsmBleedReduction);

}  // namespace fspm::graphics
