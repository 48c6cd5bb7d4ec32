#include "io/stepped_input.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "fspm/memory_budget.hpp"
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

double stored_bytes(const graphics::InstancedMesh& mesh) {
  double bytes = static_cast<double>(mesh.instances.size()) * sizeof(graphics::MeshInstance);
  for (const graphics::TriangleMesh& m : mesh.meshes) {
    bytes += graphics::TriangleMesh::bytes_for(m.vertex_count(), m.triangle_count(),
                                               m.attributes.size());
  }
  return bytes;
}

std::vector<graphics::InstancedMesh> steps_side_by_side(const std::vector<SteppedInput>& inputs,
                                                        const std::vector<double>& ages,
                                                        const graphics::MeshOptions& options,
                                                        double held_bytes) {
  std::vector<graphics::PartPlacement> placements;
  float x = 0.0f;
  // Every input is at its largest at the last age (a stage, an age, a growth step shows part of
  // the whole), so the full meshes bound each step's.
  double step_bound = 0.0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const graphics::InstancedMesh full =
        inputs[i].at(std::numeric_limits<double>::infinity(), options);
    step_bound += stored_bytes(full);
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
    // The viewer keeps every step: the ones made so far, and this one twice while its parts are
    // placed, must fit the limit before it is made.
    check_memory(held_bytes + 2.0 * step_bound,
                 "keeping the meshes of steps 1 to " + std::to_string(steps.size() + 1) + " of " +
                     std::to_string(ages.size()) + " for the viewer");
    std::vector<graphics::InstancedMesh> parts;
    for (const auto& s : inputs) parts.push_back(s.at(age, options));
    steps.push_back(graphics::place_parts(parts, placements));
    held_bytes += stored_bytes(steps.back());
  }
  return steps;
}

}  // namespace fspm::io
