#pragma once
// Obstacles around a plant: a growth scene's wall may be 40 m long beside a 5 m tree, and a
// picture framing all of it shows the tree as a dot. Renders keep only what lies near the plants.
#include <Eigen/Core>

#include "environment/scene.hpp"

namespace fspm::io {

// The x/y region kept around plants with bounds [lo, hi]: their bounding box grown on each side,
// in x and y, by the largest of its x and y sizes, half its height and 1 m; z is unbounded.
void obstacle_region(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                     Eigen::Vector2d& region_lo, Eigen::Vector2d& region_hi);

// The scene's occluders near the region [region_lo, region_hi] (x and y; z unbounded): each box
// cut along its own axes to the region's extent on them (exact for boxes whose axes are
// horizontal or vertical in x/y, such as walls along x or y; a slanted box keeps a little more),
// boxes that miss the region dropped; spheres and meshes whose bounds miss it dropped, the others
// kept whole. The ground and the sky are left out.
environment::Scene obstacles_near(const environment::Scene& scene, const Eigen::Vector2d& region_lo,
                                  const Eigen::Vector2d& region_hi);

}  // namespace fspm::io
