#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkWindowToImageFilter.h>

#include <cstdint>
#include <cstring>

#include "graphics/vtk_window_image.hpp"

namespace fspm::graphics {

Image window_image(vtkRenderWindow* window) {
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGBA();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkImageData* data = grab->GetOutput();
  int dims[3];
  data->GetDimensions(dims);
  Image image;
  image.width = dims[0];
  image.height = dims[1];
  image.rgba.resize(static_cast<std::size_t>(dims[0]) * dims[1] * 4);
  const auto* src = static_cast<const std::uint8_t*>(data->GetScalarPointer());
  const std::size_t row = static_cast<std::size_t>(dims[0]) * 4;
  for (int y = 0; y < dims[1]; ++y) {  // VTK's rows start at the bottom
    std::memcpy(image.rgba.data() + row * y, src + row * (dims[1] - 1 - y), row);
  }
  return image;
}

}  // namespace fspm::graphics
