// VTK XML PolyData (.vtp), written without VTK: raw appended binary blocks with UInt64 headers,
// the layout VTK's vtkXMLPolyDataReader and ParaView read. Attributes become point-data arrays,
// normals and texture coordinates the active Normals and TCoords, the material a cell array.
#include <bit>
#include <cstdint>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

#include "fspm/atomic_file.hpp"
#include "graphics/mesh_writers.hpp"

namespace fspm::graphics {
namespace {

static_assert(std::endian::native == std::endian::little, "VTP writer assumes little endian");

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

struct Block {
  const void* data;
  std::uint64_t bytes;
};

template <typename Index>
std::vector<Index> connectivity(const TriangleMesh& mesh) {
  std::vector<Index> c(mesh.triangle_count() * 3);
  for (std::size_t i = 0; i < mesh.triangle_count(); ++i) {
    for (int k = 0; k < 3; ++k) c[3 * i + k] = static_cast<Index>(mesh.triangles[i][k]);
  }
  return c;
}

template <typename Index>
std::vector<Index> offsets(const TriangleMesh& mesh) {
  std::vector<Index> o(mesh.triangle_count());
  for (std::size_t i = 0; i < o.size(); ++i) o[i] = static_cast<Index>(3 * (i + 1));
  return o;
}

}  // namespace

void write_vtp(const TriangleMesh& mesh, const std::string& path) {
  const bool small = mesh.triangle_count() * 3 <
                     static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max());
  std::vector<std::int32_t> conn32, off32;
  std::vector<std::int64_t> conn64, off64;
  if (small) {
    conn32 = connectivity<std::int32_t>(mesh);
    off32 = offsets<std::int32_t>(mesh);
  } else {
    conn64 = connectivity<std::int64_t>(mesh);
    off64 = offsets<std::int64_t>(mesh);
  }
  const char* index_type = small ? "Int32" : "Int64";
  const std::size_t index_size = small ? 4 : 8;
  const std::size_t nv = mesh.vertex_count();
  const std::size_t nt = mesh.triangle_count();

  std::vector<Block> blocks;
  std::uint64_t offset = 0;
  auto add = [&](const void* data, std::uint64_t bytes) {
    const std::uint64_t at = offset;
    blocks.push_back({data, bytes});
    offset += sizeof(std::uint64_t) + bytes;
    return at;
  };

  std::string xml;
  xml += "<?xml version=\"1.0\"?>\n";
  xml +=
      "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
      "header_type=\"UInt64\">\n  <PolyData>\n";
  xml += "    <Piece NumberOfPoints=\"" + std::to_string(nv) +
         "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"" +
         std::to_string(nt) + "\">\n";
  xml += "      <PointData Normals=\"Normals\" TCoords=\"TCoords\">\n";
  auto array = [&](const std::string& type, const std::string& name, int components,
                   std::uint64_t at) {
    xml += "        <DataArray type=\"" + type + "\" Name=\"" + xml_escape(name) +
           "\" NumberOfComponents=\"" + std::to_string(components) +
           "\" format=\"appended\" offset=\"" + std::to_string(at) + "\"/>\n";
  };
  array("Float32", "Normals", 3, add(mesh.normals.data(), nv * 12));
  array("Float32", "TCoords", 2, add(mesh.uvs.data(), nv * 8));
  for (const auto& a : mesh.attributes) array("Float32", a.name, 1, add(a.values.data(), nv * 4));
  xml += "      </PointData>\n      <CellData>\n";
  array("UInt8", "material", 1, add(mesh.materials.data(), nt));
  xml += "      </CellData>\n      <Points>\n";
  array("Float32", "Points", 3, add(mesh.positions.data(), nv * 12));
  xml += "      </Points>\n      <Polys>\n";
  array(index_type, "connectivity", 1,
        add(small ? static_cast<const void*>(conn32.data()) : conn64.data(), 3 * nt * index_size));
  array(index_type, "offsets", 1,
        add(small ? static_cast<const void*>(off32.data()) : off64.data(), nt * index_size));
  xml += "      </Polys>\n    </Piece>\n  </PolyData>\n  <AppendedData encoding=\"raw\">\n   _";

  write_file_atomically(
      path,
      [&](std::ostream& out) {
        out.write(xml.data(), static_cast<std::streamsize>(xml.size()));
        for (const Block& b : blocks) {
          out.write(reinterpret_cast<const char*>(&b.bytes), sizeof(b.bytes));
          out.write(static_cast<const char*>(b.data), static_cast<std::streamsize>(b.bytes));
        }
        out << "\n  </AppendedData>\n</VTKFile>\n";
      },
      true);
}

}  // namespace fspm::graphics
