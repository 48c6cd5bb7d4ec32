#pragma once
// The shapes that cast shadows (Pirk 4.3.2, Fig. 4.4): leaf clusters (spheres), boxes (axis-aligned
// or oriented; walls are thin oriented boxes), a ground plane and triangle meshes. Each carries a
// translucency gamma in [0, 1] (0 opaque, 1 transparent); a ray that crosses it is multiplied by
// gamma. Solid occluders also stop growth.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace fspm::environment {

// Pirk eq. 4.4: a leaf cluster of radius r lets through gamma0^r of the light.
double cluster_translucency(double radius_m, double gamma0 = 0.5);

struct Sphere {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius_m = 1.0;
  double translucency = 0.0;
  bool solid = false;  // leaf clusters do not stop growth
  // Throws ValueError naming the first value out of range (see validate of Box).
  void validate() const;
};

// A box with centre, half extents along its own axes and a rotation (identity: axis-aligned).
struct Box {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Vector3d half_extent = Eigen::Vector3d::Ones();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // columns: the box axes in world frame
  double translucency = 0.0;
  bool solid = true;

  static Box from_min_max(const Eigen::Vector3d& min, const Eigen::Vector3d& max);
  // A vertical wall from (x0, y0) to (x1, y1) at the base height, `thickness_m` thick.
  static Box wall(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double base_z_m,
                  double height_m, double thickness_m);
  // Radius of the sphere around the centre that contains the box.
  double bounding_radius() const { return half_extent.norm(); }
  // Height of the box's highest corner.
  double top_z() const;
  bool contains(const Eigen::Vector3d& p) const;
  // Entry distance t >= 0 of the ray origin + t * dir into the box (0 if the origin is inside), or
  // a negative value when the ray misses.
  double ray_entry(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir) const;
  // A point (to_local) or a direction (local_direction) in the box frame, and ray_entry for a ray
  // given in that frame: ray_entry(o, d) == ray_entry_local(to_local(o), local_direction(d))
  // bit for bit, so that many rays from one point, or many points along fixed directions, convert
  // once.
  Eigen::Vector3d to_local(const Eigen::Vector3d& p) const;
  Eigen::Vector3d local_direction(const Eigen::Vector3d& dir) const;
  double ray_entry_local(const Eigen::Vector3d& o, const Eigen::Vector3d& d) const;
  // Each of Sphere, Box and Ground throws ValueError naming the first value out of range:
  // finite positions, a radius and half extents > 0, a rotation with orthonormal columns,
  // translucency in [0, 1]. The Python bindings check what they build with these (the scene file
  // reader checks each value where it reads it, with its file and line).
  void validate() const;
};

// Fixed ray directions in a box's frame, prepared for slab tests from many origins: the inverse of
// every component is taken once, and the directions are stored by component so that one origin's
// tests over all of them run as a branch-free loop.
class BoxRayDirections {
 public:
  BoxRayDirections() = default;
  // `local_dirs`: the directions in the box frame (Box::local_direction).
  explicit BoxRayDirections(std::span<const Eigen::Vector3d> local_dirs);
  std::size_t size() const { return inv_[0].size(); }
  // hit[i] = 1 when the ray local_origin + t * dir_i enters the box (Box::ray_entry_local(
  // local_origin, dir_i) >= 0, bit for bit: the same products, minima and maxima), else 0.
  void hits(const Box& box, const Eigen::Vector3d& local_origin, std::span<std::uint8_t> hit) const;

 private:
  std::array<std::vector<double>, 3> inv_;  // 1 / component (0 where the ray is parallel)
  std::array<std::vector<std::uint8_t>, 3> parallel_;
};

// The plane z = height; everything below it is inside the ground.
struct Ground {
  double height_m = 0.0;
  double translucency = 0.0;
  bool solid = true;
  // Throws ValueError naming the first value out of range (see validate of Box).
  void validate() const;
};

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;
  double translucency = 0.0;  // applied once per triangle crossed
  bool solid = false;         // meshes are surfaces; they block growth only through their triangles
  // Bounding sphere, filled by update_bounds().
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double bounding_radius_m = 0.0;
  void update_bounds();
  // Number of triangles the ray origin + t * dir, 0 < t <= max_t, crosses.
  int crossings(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                double max_t = 1e300) const;
};

// Ray/sphere: true when the ray origin + t * dir (t > 0, dir unit) crosses the sphere's interior
// within max_t (an origin inside counts).
bool ray_hits_sphere(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
                     const Eigen::Vector3d& center, double radius, double max_t = 1e300);

}  // namespace fspm::environment
