#include "scans/obj_reader.hpp"

#include <charconv>

#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "scans/text_lines.hpp"

namespace fspm::scans {
namespace {

std::vector<std::string_view> split_spaces(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t s = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > s) out.push_back(line.substr(s, i - s));
  }
  return out;
}

std::uint32_t vertex_index(std::string_view ref, std::size_t vertices, const std::string& path,
                           int line) {
  const std::string_view head = ref.substr(0, ref.find('/'));
  long long i = 0;
  const auto r = std::from_chars(head.data(), head.data() + head.size(), i);
  if (r.ec != std::errc{} || r.ptr != head.data() + head.size() || i == 0) {
    throw ParseError("expected a vertex index in '" + std::string(ref) + "'", path, line);
  }
  const long long n = static_cast<long long>(vertices);
  const long long zero_based = i > 0 ? i - 1 : n + i;
  if (zero_based < 0 || zero_based >= n) {
    throw ParseError("vertex index " + std::to_string(i) + " is outside the " + std::to_string(n) +
                         " vertices defined so far",
                     path, line);
  }
  return static_cast<std::uint32_t>(zero_based);
}

void start_group(GroupedMesh& m, const std::vector<std::string_view>& f, std::uint32_t& group) {
  std::string name;
  for (std::size_t i = 1; i < f.size(); ++i) name += (i > 1 ? " " : "") + std::string(f[i]);
  if (name.empty()) name = "default";
  m.group_names.push_back(name);
  group = static_cast<std::uint32_t>(m.group_names.size() - 1);
}

}  // namespace

GroupedMesh parse_obj_mesh(std::string_view text, const std::string& path) {
  GroupedMesh m;
  m.group_names.push_back("default");
  std::uint32_t group = 0;
  TextLines lines(text);
  std::string_view line;
  while (lines.next(line)) {
    const std::vector<std::string_view> f = split_spaces(line);
    if (f.empty() || f[0][0] == '#') continue;
    const int n = lines.line_number();
    if (f[0] == "v") {
      if (f.size() < 4) throw ParseError("expected 'v x y z'", path, n);
      m.vertices.emplace_back(parse_coordinate(f[1], path, n), parse_coordinate(f[2], path, n),
                              parse_coordinate(f[3], path, n));
    } else if (f[0] == "f") {
      if (f.size() < 4) throw ParseError("expected a face of at least 3 vertices", path, n);
      std::vector<std::uint32_t> face;
      for (std::size_t i = 1; i < f.size(); ++i) {
        face.push_back(vertex_index(f[i], m.vertices.size(), path, n));
      }
      m.faces.push_back(std::move(face));
      m.face_group.push_back(group);
    } else if (f[0] == "g" || f[0] == "o") {
      start_group(m, f, group);
    }
  }
  return m;
}

GroupedMesh read_obj_mesh(const std::string& path) {
  return parse_obj_mesh(read_input_file(path), path);
}

}  // namespace fspm::scans
