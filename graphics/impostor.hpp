#pragma once
// Impostors for distant plants: each plant is drawn once from a few directions around it into the
// layers of an image array (its "views"), and a distant instance is one quad through its bounding
// sphere's centre, facing the eye and as wide as the sphere, showing the view taken nearest to the
// direction the plant is seen from. Argudo (2014, chapter 6) draws the crowns of a landscape as
// such cheap stand-ins beyond a jittered switch distance; here they take over where Reynolds'
// expression 2 would cull a plant (instance_lod.hpp chooses which instances are impostors).
//
// The geometry is computed on the CPU, so it can be tested without OpenGL; the viewer renders the
// views and draws the quads (viewer_glfw.cpp).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "graphics/instance_lod.hpp"

namespace fspm::graphics {

// The directions a plant is drawn from: `azimuths` equally spaced around the vertical (the
// first along +x of the plant's frame) at each of `elevations_deg` above the horizontal.
struct ImpostorViews {
  int azimuths = 8;
  std::vector<double> elevations_deg = {0.0, 35.0, 70.0};

  // Throws ValueError for fewer than 3 azimuths, no elevation or one outside [-89, 89] degrees.
  void validate() const;
};

int impostor_view_count(const ImpostorViews& views);

// Unit vector from the plant's centre towards the camera of view k = e * azimuths + a
// (elevation e, azimuth a), in the plant's frame.
Eigen::Vector3d impostor_view_direction(const ImpostorViews& views, int k);

// Every view's direction, in order.
std::vector<Eigen::Vector3d> impostor_view_directions(const ImpostorViews& views);

// The view whose direction makes the smallest angle with `direction` (plant frame, non-zero),
// among `directions` (impostor_view_directions, computed once for many instances).
int nearest_impostor_view(const std::vector<Eigen::Vector3d>& directions,
                          const Eigen::Vector3d& direction);
int nearest_impostor_view(const ImpostorViews& views, const Eigen::Vector3d& direction);

// One corner of an impostor quad: world position, texture coordinates in the view's image
// (0..1, origin at its bottom left), the image's layer (plant * view count + view), the unit
// direction to the sun in the plant's frame (the views keep the plant's normals, so each
// instance is lit as it is turned) and the placed bounding sphere's radius.
struct ImpostorVertex {
  float position[3];
  float uv[2];
  float layer;
  float sun_local[3];
  float radius;
};

// The views' images: view k of a plant is the orthographic image, (2 r) wide and high, of the
// plant's bounding sphere (centre c, radius r) seen from c + t * direction_k with the plant's +z
// up in the image. The quad of an instance spans the same square around the placed centre,
// facing `eye_m`, with the placed +z projected as its up. Appends four corners per impostor of
// `choice` (counter-clockwise seen from the eye) to `out`; `sun` is the unit direction to the
// sun in the world.
void append_impostor_quads(const LodScene& scene, const std::vector<InstanceLod>& choice,
                           const ImpostorViews& views, const Eigen::Vector3d& eye_m,
                           const Eigen::Vector3d& sun, std::vector<ImpostorVertex>& out);

// The same quads facing the direction `toward` (unit, from the plants to a distant light) and
// showing the views nearest to it: the impostors as the sun sees them, for the shadow map.
void append_impostor_quads_toward(const LodScene& scene, const std::vector<InstanceLod>& choice,
                                  const ImpostorViews& views, const Eigen::Vector3d& toward,
                                  std::vector<ImpostorVertex>& out);

}  // namespace fspm::graphics
