#pragma once
// A terrain as a regular grid of heights (Argudo 2014, 6.1: the digital terrain model gives the
// elevation wherever a tree is placed). Sample (i, j), column i and row j from the top of the
// image (north), stands at x = i metres_per_pixel, y = (rows - 1 - j) metres_per_pixel, z =
// height_scale_m * value: the terrain spans [0, (columns - 1) metres_per_pixel] x
// [0, (rows - 1) metres_per_pixel], and between samples it is the bilinear interpolation of the
// four around.
#include <vector>

#include "graphics/float_image.hpp"
#include "graphics/triangle_mesh.hpp"

namespace fspm::graphics {

class Heightfield {
 public:
  // Throws ValueError for an image smaller than 2 x 2, a pixel size that is not positive or a
  // value that is not finite; `file` names the image in the message.
  Heightfield(FloatImage image, double metres_per_pixel, double height_scale_m,
              const std::string& file = "<heightfield>");

  int columns() const { return image_.width; }
  int rows() const { return image_.height; }
  double metres_per_pixel() const { return metres_per_pixel_; }
  double width_m() const { return (columns() - 1) * metres_per_pixel_; }  // along x
  double depth_m() const { return (rows() - 1) * metres_per_pixel_; }     // along y

  // Height of sample (i, j) in metres.
  double sample_m(int i, int j) const { return height_scale_m_ * image_.at(i, j); }
  // Bilinear height at (x, y), clamped to the terrain's extent.
  double height_at(double x_m, double y_m) const;

 private:
  FloatImage image_;
  double metres_per_pixel_;
  double height_scale_m_;
};

// The terrain as a grid of triangles (material terrain) through every stride-th sample in each
// direction and the last one, two triangles per cell, normals from the triangles around each
// vertex. Throws ValueError for a stride below 1.
TriangleMesh heightfield_mesh(const Heightfield& terrain, int stride = 1);

}  // namespace fspm::graphics
