#include "io/stepped_input.hpp"

#include <cmath>
#include <limits>

#include "io/input_mesh.hpp"
#include "io/lsystem_mesh.hpp"

namespace fspm::io {

graphics::InstancedMesh SteppedInput::at(double age, const graphics::MeshOptions& options) const {
  if (kind == InputKind::kScene) return load_scene(path, options, true, lod);
  if (is_compressed(kind)) {
    return mesh_compressed(graph, std::isinf(age) ? -1.0 : age, options, lod);
  }
  if (kind == InputKind::kLsystem) return mesh_lsystem(drawing, options);
  if (kind == InputKind::kMesh) return graphics::InstancedMesh::single(mesh);
  if (model) {
    return graphics::InstancedMesh::single(
        graphics::mesh_tree(model->stage(std::isinf(age) ? 1.0 : age), options));
  }
  graphics::MeshOptions o = options;
  o.max_birth_time = age;
  return graphics::InstancedMesh::single(graphics::mesh_tree(tree, o));
}

std::vector<graphics::InstancedMesh> steps_side_by_side(const std::vector<SteppedInput>& inputs,
                                                        const std::vector<double>& ages,
                                                        const graphics::MeshOptions& options) {
  std::vector<graphics::PartPlacement> placements;
  float x = 0.0f;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const graphics::InstancedMesh full =
        inputs[i].at(std::numeric_limits<double>::infinity(), options);
    Eigen::Vector3f lo, hi;
    full.bounds(lo, hi);
    const float width = hi.x() - lo.x();
    graphics::PartPlacement p;
    p.part = i;
    p.translation.x() = full.instances.empty() ? x : x - lo.x();
    placements.push_back(p);
    x += width * 1.1f + 0.1f;
  }
  std::vector<graphics::InstancedMesh> steps;
  for (double age : ages) {
    std::vector<graphics::InstancedMesh> parts;
    for (const auto& s : inputs) parts.push_back(s.at(age, options));
    steps.push_back(graphics::place_parts(parts, placements));
  }
  return steps;
}

}  // namespace fspm::io
