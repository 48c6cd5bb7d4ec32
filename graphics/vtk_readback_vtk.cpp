#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <Eigen/Geometry>
#include <filesystem>

#include "fspm/error.hpp"
#include "fspm/vertex_normals.hpp"
#include "graphics/vtk_readback.hpp"

namespace fspm::graphics {

namespace {

// The poly data of a .vtp through VTK's reader (which owns it); IoError when it cannot be read.
vtkPolyData* read_vtp(const std::string& path, vtkXMLPolyDataReader* reader) {
  if (!std::filesystem::exists(path)) throw IoError("no such file", path);
  reader->SetFileName(path.c_str());
  if (!reader->CanReadFile(path.c_str())) throw IoError("VTK cannot read this .vtp file", path);
  reader->Update();
  if (reader->GetErrorCode() != 0) throw IoError("VTK failed reading this .vtp file", path);
  return reader->GetOutput();
}

}  // namespace

bool vtk_available() { return true; }

PolyDataInfo read_vtp_with_vtk(const std::string& path) {
  vtkNew<vtkXMLPolyDataReader> reader;
  vtkPolyData* poly = read_vtp(path, reader);
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

TriangleMesh read_vtp_mesh(const std::string& path) {
  vtkNew<vtkXMLPolyDataReader> reader;
  vtkPolyData* poly = read_vtp(path, reader);
  TriangleMesh mesh;
  const vtkIdType nv = poly->GetNumberOfPoints();
  mesh.positions.resize(static_cast<std::size_t>(nv));
  for (vtkIdType i = 0; i < nv; ++i) {
    double p[3];
    poly->GetPoint(i, p);
    mesh.positions[i] = Eigen::Vector3d(p[0], p[1], p[2]).cast<float>();
  }
  vtkPointData* pd = poly->GetPointData();
  vtkDataArray* normals = pd->GetArray("Normals");
  vtkDataArray* tcoords = pd->GetArray("TCoords");
  mesh.uvs.assign(mesh.positions.size(), Eigen::Vector2f::Zero());
  if (tcoords != nullptr && tcoords->GetNumberOfComponents() == 2) {
    for (vtkIdType i = 0; i < nv; ++i) {
      mesh.uvs[i] = {static_cast<float>(tcoords->GetComponent(i, 0)),
                     static_cast<float>(tcoords->GetComponent(i, 1))};
    }
  }
  vtkDataArray* material = poly->GetCellData()->GetArray("material");
  vtkCellArray* cells = poly->GetPolys();
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c) {
    cells->GetCellAtId(c, ids);
    const double index = material != nullptr ? material->GetComponent(c, 0) : 0.0;
    const Material m =
        material_from_index(index >= 0.0 && index < 256.0 ? static_cast<int>(index) : 0);
    for (vtkIdType k = 1; k + 1 < ids->GetNumberOfIds(); ++k) {  // a fan over the polygon
      mesh.triangles.push_back({static_cast<std::uint32_t>(ids->GetId(0)),
                                static_cast<std::uint32_t>(ids->GetId(k)),
                                static_cast<std::uint32_t>(ids->GetId(k + 1))});
      mesh.materials.push_back(m);
    }
  }
  if (normals != nullptr && normals->GetNumberOfComponents() == 3) {
    mesh.normals.assign(mesh.positions.size(), Eigen::Vector3f::Zero());
    for (vtkIdType i = 0; i < nv; ++i) {
      mesh.normals[i] = Eigen::Vector3f(static_cast<float>(normals->GetComponent(i, 0)),
                                        static_cast<float>(normals->GetComponent(i, 1)),
                                        static_cast<float>(normals->GetComponent(i, 2)));
    }
  } else {
    mesh.normals = area_weighted_vertex_normals(mesh.positions, mesh.triangles);
  }
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a) {
    vtkDataArray* array = pd->GetArray(a);
    if (array == nullptr || array->GetName() == nullptr || array == normals || array == tcoords ||
        array->GetNumberOfComponents() != 1) {
      continue;
    }
    std::vector<float>& values = mesh.add_attribute(array->GetName());
    for (vtkIdType i = 0; i < nv; ++i) values[i] = static_cast<float>(array->GetComponent(i, 0));
  }
  return mesh;
}

}  // namespace fspm::graphics
