#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <filesystem>

#include "fspm/error.hpp"
#include "graphics/vtk_readback.hpp"

namespace fspm::graphics {

bool vtk_available() { return true; }

PolyDataInfo read_vtp_with_vtk(const std::string& path) {
  if (!std::filesystem::exists(path)) throw IoError("no such file", path);
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(path.c_str());
  if (!reader->CanReadFile(path.c_str())) throw IoError("VTK cannot read this .vtp file", path);
  reader->Update();
  if (reader->GetErrorCode() != 0) throw IoError("VTK failed reading this .vtp file", path);
  vtkPolyData* poly = reader->GetOutput();
  PolyDataInfo info;
  info.points = static_cast<std::size_t>(poly->GetNumberOfPoints());
  info.polys = static_cast<std::size_t>(poly->GetNumberOfPolys());
  vtkCellArray* cells = poly->GetPolys();
  for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c) {
    if (cells->GetCellSize(c) == 3) ++info.triangles;
  }
  info.points_xyz.reserve(3 * info.points);
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i) {
    double p[3];
    poly->GetPoint(i, p);
    for (double x : p) info.points_xyz.push_back(static_cast<float>(x));
  }
  auto collect = [](vtkDataSetAttributes* data, std::map<std::string, std::vector<float>>& out,
                    std::map<std::string, int>* components) {
    for (int a = 0; a < data->GetNumberOfArrays(); ++a) {
      vtkDataArray* array = data->GetArray(a);
      if (array == nullptr || array->GetName() == nullptr) continue;
      std::vector<float>& values = out[array->GetName()];
      for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i) {
        values.push_back(static_cast<float>(array->GetComponent(i, 0)));
      }
      if (components) (*components)[array->GetName()] = array->GetNumberOfComponents();
    }
  };
  collect(poly->GetPointData(), info.point_data, &info.point_components);
  collect(poly->GetCellData(), info.cell_data, nullptr);
  return info;
}

}  // namespace fspm::graphics
