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

// Argudo 5.2's drawing order: the first `fixed` points stay first (they are always drawn); after
// them each point is the one of those left whose summed distance to the points placed after the
// fixed ones is largest, so that any prefix covers the crown evenly and a distant crown drawn
// with few billboards is not lopsided. Ties keep the input order; at the first free position
// (an empty sum) the first point left is taken. Returns the points reordered.
std::vector<Eigen::Vector3f> progressive_order(std::vector<Eigen::Vector3f> points,
                                               std::size_t fixed);

// The ball scaled to the crown's largest radius around `centre`, keeping the points inside the
// crown (closer to the centre than the radius cubemap in their direction), in progressive_order
// with the level-1 octree points (at most 8) fixed.
std::vector<Eigen::Vector3f> billboard_centres(const Cubemap& radius, const Eigen::Vector3f& centre,
                                               std::mt19937_64& rng);

}  // namespace fspm::crown
