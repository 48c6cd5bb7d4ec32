#pragma once
// Billboard centres for the detailed crown (Argudo 5.2): blue-noise points in the unit ball from
// the cell centres of the first three octree levels of [-1, 1]^3, each moved by a uniform offset
// in [-d_L, d_L] per axis (d_L the cell side at level L), those outside the ball dropped: about
// 300 points (Argudo obtained 320).
#include <Eigen/Core>
#include <random>
#include <vector>

#include "crown/cubemap.hpp"

namespace fspm::crown {

std::vector<Eigen::Vector3f> blue_noise_ball(std::mt19937_64& rng);

// The ball scaled to the crown's largest radius around `centre`, keeping the points inside the
// crown (closer to the centre than the radius cubemap in their direction).
std::vector<Eigen::Vector3f> billboard_centres(const Cubemap& radius, const Eigen::Vector3f& centre,
                                               std::mt19937_64& rng);

}  // namespace fspm::crown
