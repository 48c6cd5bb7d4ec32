#pragma once
// Geometry of a measured plant where its file gives only part of it (OpenAlea's PlantFrame): the
// entities' top points, lengths and radii where measured, inferred everywhere else.
//
// Positions: a measured top point is kept; entities between two measured ones along an axis
// (a chain of '<' successors, e.g. the E2 ... E34 of a range E1<<E35 whose last one was
// digitised) are placed evenly on the segment between them; the rest are drawn by a turtle that
// continues the bearer's heading along an axis and turns branches ('+') away from it by their
// insertion angle (default 45 degrees) around an azimuth (default: the golden angle, 137.5
// degrees, from one branch of an axis to the next), each entity as long as its measured length
// or the default length. Radii: a measured radius is kept; between two measured ones along an
// axis they are interpolated linearly; elsewhere the pipe model (Shinozaki et al. 1964) gives a
// node the radius whose cross-section is the sum of its children's, tips the smallest measured
// radius (or the default).
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace fspm {

inline constexpr std::size_t kNoFrameParent = static_cast<std::size_t>(-1);

// What was measured of one entity, in metres and degrees. Entities are given parents first.
struct FrameEntity {
  std::size_t parent = kNoFrameParent;
  bool branch = false;  // borne by its parent ('+'), not its successor ('<')
  std::optional<Eigen::Vector3d> top;
  std::optional<double> length_m;
  std::optional<double> radius_m;
  std::optional<double> insertion_deg;  // angle between the branch and its bearer
  std::optional<double> azimuth_deg;    // turn of the branch around its bearer
};

struct FrameDefaults {
  double length_m = 0.1;
  double tip_radius_m = 0.002;
  double insertion_deg = 45.0;
  double divergence_deg = 137.5;
};

// Bits of FramedEntity::inferred.
inline constexpr std::uint8_t kInferredPosition = 1;
inline constexpr std::uint8_t kInferredRadius = 2;

struct FramedEntity {
  Eigen::Vector3d start = Eigen::Vector3d::Zero();
  Eigen::Vector3d end = Eigen::Vector3d::Zero();
  double radius_m = 0.0;
  std::uint8_t inferred = 0;
};

std::vector<FramedEntity> plant_frame(const std::vector<FrameEntity>& entities,
                                      const FrameDefaults& defaults);

}  // namespace fspm
