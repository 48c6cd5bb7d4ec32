#pragma once
// Private to graphics/ (*_vtk.cpp only): the pixels of a rendered VTK window as an Image, rows
// from the top. Shared by the tree renders and the charts.
#include "graphics/image.hpp"

class vtkRenderWindow;

namespace fspm::graphics {

Image window_image(vtkRenderWindow* window);

}  // namespace fspm::graphics
