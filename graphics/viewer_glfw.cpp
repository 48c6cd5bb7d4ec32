// The GLFW/OpenGL 3.3 core viewer. Three passes a frame: the depth moments seen from the sun
// into a variance shadow map, a separable blur of it, then the scene with Blinn-Phong shading and
// the Chebyshev bound of the blurred moments as the light reaching each point (Pirk 6.2.3, eq.
// 6.10-6.12; variance_shadow.hpp has the same formulas on the CPU).
#define GLFW_INCLUDE_NONE
#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>
#include <GLFW/glfw3.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <deque>
#include <functional>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"
#include "graphics/gl_shader.hpp"
#include "graphics/image.hpp"
#include "graphics/pn_triangles.hpp"
#include "graphics/shadow_cascades.hpp"
#include "graphics/tessellation_level.hpp"
#include "graphics/translucent_sort.hpp"
#include "graphics/viewer.hpp"
#include "graphics/viewer_impostors.hpp"
#include "graphics/viewer_panel.hpp"
#include "graphics/viewer_relief.hpp"
#include "graphics/viewer_shadow_maps.hpp"
#include "graphics/viewer_tessellation.hpp"
#include "graphics/viewer_wind.hpp"

namespace fspm::graphics {
namespace {

constexpr int kShadowSize = 1024;
constexpr int kImpostorResolution = 256;             // pixels on a side of each impostor view
constexpr double kCoarseEdgePixels = 2.0;            // ViewerOptions::coarse_edge_m
constexpr float kSky[3] = {0.80f, 0.87f, 0.96f};     // the background, cleared every frame
constexpr float kGround[3] = {0.55f, 0.62f, 0.45f};  // before shading, as the renders' ground
// Ground this many scene radii away is hazed by 1 - 1/e of kMaxHaze towards the sky colour.
constexpr float kHazeRadii = 25.0f;
// Even at the horizon the ground keeps half its own colour: the horizon stays a visible line.
constexpr float kMaxHaze = 0.5f;

const char* kSceneVs = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 color;  // alpha below 1: crowns and translucent obstacles
layout(location = 3) in mat4 model;  // per instance: rotation times uniform scale, translation
uniform mat4 mvp;
out vec3 v_normal;
out vec4 v_color;
out vec3 v_world;
void main() {
  vec4 world = model * vec4(position, 1.0);
  v_normal = mat3(model) * normal;  // uniform scale: no inverse transpose needed
  v_color = color;
  v_world = world.xyz;
  gl_Position = mvp * world;
}
)";
const char* kSceneFs = R"(
in vec3 v_normal;
in vec4 v_color;
in vec3 v_world;
uniform vec3 sun;
uniform vec3 eye;
out vec4 frag;
void main() {
  vec3 n = normalize(v_normal);
  vec3 v = normalize(eye - v_world);
  if (dot(n, v) < 0.0) n = -n;  // two-sided leaves
  float diffuse = max(dot(n, sun), 0.0);
  float specular = pow(max(dot(n, normalize(sun + v)), 0.0), 32.0) * 0.15;
  float s = lit(v_world);
  vec3 c = v_color.rgb * (0.35 + 0.65 * diffuse * s) + vec3(specular * s);
  frag = vec4(pow(c, vec3(1.0 / 1.2)), v_color.a);
}
)";

// The ground: one triangle covering the screen; each pixel's ray from the eye meets the plane
// z = ground_z (or not: sky), so the ground reaches the horizon whatever the far plane. The
// depth written is that of the hit point (clamped to the far plane, drawn with GL_LEQUAL), the
// shading that of the scene shader for a normal (0, 0, 1), and the colour tends to the sky's
// with distance, at most kMaxHaze of it, as distant ground looks through air.
const char* kGroundVs = R"(#version 330 core
out vec2 v_ndc;
void main() {
  v_ndc = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
  gl_Position = vec4(v_ndc, 0.0, 1.0);
}
)";
const char* kGroundFs = R"(
in vec2 v_ndc;
uniform mat4 mvp;
uniform mat4 inverse_mvp;
uniform vec3 sun;
uniform vec3 eye;
uniform vec3 ground_color;
uniform vec3 haze_color;
uniform float ground_z;
uniform float haze_distance;
uniform float max_haze;
out vec4 frag;
void main() {
  vec4 a = inverse_mvp * vec4(v_ndc, -1.0, 1.0);
  vec4 b = inverse_mvp * vec4(v_ndc, 1.0, 1.0);
  vec3 from = a.xyz / a.w, dir = b.xyz / b.w - from;
  if (abs(dir.z) < 1e-12) discard;
  float t = (ground_z - from.z) / dir.z;
  if (t <= 0.0) discard;  // the ray rises (eye above the ground): sky
  vec3 world = from + t * dir;
  vec4 clip = mvp * vec4(world, 1.0);
  gl_FragDepth = clamp(clip.z / clip.w * 0.5 + 0.5, 0.0, 1.0);
  vec3 n = eye.z >= ground_z ? vec3(0.0, 0.0, 1.0) : vec3(0.0, 0.0, -1.0);
  float s = lit(world);
  vec3 c = ground_color * (0.35 + 0.65 * max(dot(n, sun), 0.0) * s);
  c = pow(c, vec3(1.0 / 1.2));
  float haze = max_haze * (1.0 - exp(-length(world - eye) / haze_distance));
  frag = vec4(mix(c, haze_color, haze), 1.0);
}
)";

// `fs` without its #version line when `with_vsm`: the version, then kShadowReceiverGlsl, then
// `fs`.
GLuint program(const char* vs, const char* fs, bool with_vsm = false) {
  return gl_program(vs, with_vsm ? std::string("#version 330 core\n") + kShadowReceiverGlsl + fs
                                 : std::string(fs));
}

glm::vec3 colormap(float t) {  // blue -> cyan -> green -> yellow -> red, as the VTK renders
  t = std::clamp(t, 0.0f, 1.0f);
  const float h = (1.0f - t) * 4.0f;  // 0 red .. 4 blue
  const float x = 1.0f - std::abs(std::fmod(h, 2.0f) - 1.0f);
  if (h < 1) return {1, x, 0};
  if (h < 2) return {x, 1, 0};
  if (h < 3) return {0, 1, x};
  return {0, x, 1};
}

// One shared mesh on the GPU: interleaved position, normal, colour (RGBA), indices with the
// opaque triangles first and the translucent ones after them, and a buffer of per-instance model
// matrices (attribute locations 3-6, advanced once per instance).
struct GpuMesh {
  GLuint vao = 0, vbo = 0, ibo = 0, instance_vbo = 0;
  GLsizei indices = 0;
  GLsizei opaque_indices = 0;  // the first ones; the rest are blended
  GLsizei bark_indices = 0;    // the first opaque ones: closed tubes
  GLsizei instances = 0;
  std::vector<glm::mat4> models;  // of the instances (set_instances), for the cascades' culling
  glm::vec4 bound{0.0f};          // the mesh's bounding sphere: centre, radius
};

// Crown volumes and translucent obstacles are blended over the opaque geometry.
bool is_blended(Material m) { return m == Material::kCrown || m == Material::kTranslucentObstacle; }

// The blended triangles of one shared mesh, three corners each, in the mesh's own frame.
struct BlendedPart {
  std::vector<Eigen::Vector3f> positions, normals;
  std::vector<glm::vec4> colors;
};

// Every blended triangle of a step placed in the world (one copy per instance), three vertices
// each, drawn as one mesh whose index buffer is rewritten back to front whenever the eye moves.
struct BlendedSoup {
  GpuMesh mesh;
  std::vector<Eigen::Vector3f> centroids;
  bool sorted = false;
  glm::vec3 sorted_for{0.0f};  // the eye of the current order
};

// One GpuMesh per mesh of the step (a default one for an empty mesh), so a level-of-detail
// frame can set the instances of mesh k; the blended triangles of each mesh on the CPU and,
// placed, in the soup.
struct GpuStep {
  std::vector<GpuMesh> meshes;
  std::vector<BlendedPart> blended;  // one per mesh
  BlendedSoup soup;
  std::size_t triangles = 0;  // of the explicit scene
  std::uint64_t casters = 0;  // with per-instance LOD: a hash of the choice drawn (choice_hash)
};

struct Scene {
  glm::vec3 lo{0.0f}, hi{0.0f};
  std::string color_by;                       // the attribute the uploaded colours show
  float value_lo = 1e30f, value_hi = -1e30f;  // of the colour attribute
};

// A step as the viewer needs it: each mesh with the model matrices of its instances, and the
// value added to its colour attribute (an instance's order offset when colouring by order, so a
// substructure drawn at several branching orders is uploaded once per order).
struct StepRef {
  std::vector<const TriangleMesh*> meshes;
  std::vector<std::vector<glm::mat4>> models;  // one list per mesh
  std::vector<float> value_offsets;            // one per mesh
};

// Per-instance level of detail: the scene whose instances are chosen anew every frame.
struct LodView {
  const LodScene* scene = nullptr;
  LodOptions options;
};

StepRef step_ref(const TriangleMesh& mesh) { return {{&mesh}, {{glm::mat4(1.0f)}}, {0.0f}}; }

glm::mat4 model_matrix(const MeshInstance& inst) {
  const Eigen::Matrix4f m = inst.matrix();  // column-major, as glm
  return glm::make_mat4(m.data());
}

StepRef step_ref(const InstancedMesh& scene, const std::string& color_by) {
  StepRef r;
  const bool by_order = color_by == kAttributeOrder;
  std::map<std::pair<std::uint32_t, float>, std::size_t> slot;
  for (const MeshInstance& inst : scene.instances) {
    const float offset = by_order ? inst.order_offset : 0.0f;
    auto [it, added] = slot.emplace(std::make_pair(inst.mesh, offset), r.meshes.size());
    if (added) {
      r.meshes.push_back(&scene.meshes[inst.mesh]);
      r.models.emplace_back();
      r.value_offsets.push_back(offset);
    }
    r.models[it->second].push_back(model_matrix(inst));
  }
  return r;
}

// Every mesh of a level-of-detail scene, each plant placed at its finest variant (the bounds
// and the first frame before any choice).
StepRef step_ref(const LodScene& scene) {
  StepRef r;
  r.meshes = scene.meshes();
  r.models.resize(r.meshes.size());
  r.value_offsets.assign(r.meshes.size(), 0.0f);
  std::vector<InstanceLod> finest(scene.placements.size());
  for (auto& c : finest) c.visible = true;
  for (const MeshInstance& inst : lod_instances(scene, finest)) {
    r.models[inst.mesh].push_back(model_matrix(inst));
  }
  return r;
}

void bounds(const StepRef& step, glm::vec3& lo, glm::vec3& hi) {
  for (std::size_t k = 0; k < step.meshes.size(); ++k) {
    for (const glm::mat4& model : step.models[k]) {
      for (const auto& p : step.meshes[k]->positions) {
        const glm::vec3 q = glm::vec3(model * glm::vec4(p.x(), p.y(), p.z(), 1.0f));
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
      }
    }
  }
}

// The instances drawn by the next draw calls.
void upload_instances(GpuMesh& g, const std::vector<glm::mat4>& models) {
  glBindBuffer(GL_ARRAY_BUFFER, g.instance_vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(models.size() * sizeof(glm::mat4)),
               models.data(), GL_DYNAMIC_DRAW);
  g.instances = static_cast<GLsizei>(models.size());
}

// The mesh's instances.
void set_instances(GpuMesh& g, const std::vector<glm::mat4>& models) {
  g.models = models;
  upload_instances(g, g.models);
}

// The bounding sphere (centre of the box, farthest vertex) of interleaved vertices whose first
// three floats in every `stride` are the position.
glm::vec4 bounding_sphere(const std::vector<float>& v, std::size_t stride) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (std::size_t i = 0; i + 2 < v.size(); i += stride) {
    lo = glm::min(lo, glm::vec3(v[i], v[i + 1], v[i + 2]));
    hi = glm::max(hi, glm::vec3(v[i], v[i + 1], v[i + 2]));
  }
  if (lo.x > hi.x) return glm::vec4(0.0f);
  const glm::vec3 c = 0.5f * (lo + hi);
  float r = 0.0f;
  for (std::size_t i = 0; i + 2 < v.size(); i += stride) {
    r = std::max(r, glm::length(glm::vec3(v[i], v[i + 1], v[i + 2]) - c));
  }
  return glm::vec4(c, r);
}

// A vertex as uploaded: position, normal and colour (RGBA), interleaved.
constexpr std::size_t kFloatsPerVertex = 10;

GpuMesh upload_raw(const std::vector<float>& v, const std::vector<std::uint32_t>& idx,
                   std::size_t opaque_indices, const std::vector<glm::mat4>& models) {
  constexpr GLsizei kStride = kFloatsPerVertex * sizeof(float);
  GpuMesh g;
  glGenVertexArrays(1, &g.vao);
  glBindVertexArray(g.vao);
  glGenBuffers(1, &g.vbo);
  glBindBuffer(GL_ARRAY_BUFFER, g.vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(v.size() * sizeof(float)), v.data(),
               GL_STATIC_DRAW);
  glGenBuffers(1, &g.ibo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.ibo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(idx.size() * 4), idx.data(),
               GL_STATIC_DRAW);
  for (GLuint a = 0; a < 3; ++a) {  // position, normal (3 floats), colour (4)
    glEnableVertexAttribArray(a);
    glVertexAttribPointer(a, a == 2 ? 4 : 3, GL_FLOAT, GL_FALSE, kStride,
                          reinterpret_cast<const void*>(static_cast<std::uintptr_t>(a * 12)));
  }
  glGenBuffers(1, &g.instance_vbo);
  set_instances(g, models);
  for (GLuint c = 0; c < 4; ++c) {  // a mat4 attribute takes four vec4 locations
    glEnableVertexAttribArray(3 + c);
    glVertexAttribPointer(3 + c, 4, GL_FLOAT, GL_FALSE, sizeof(glm::mat4),
                          reinterpret_cast<const void*>(static_cast<std::uintptr_t>(c * 16)));
    glVertexAttribDivisor(3 + c, 1);
  }
  glBindVertexArray(0);
  g.indices = static_cast<GLsizei>(idx.size());
  g.opaque_indices = static_cast<GLsizei>(opaque_indices);
  g.bound = bounding_sphere(v, 10);
  return g;
}

void release(GpuMesh& g) {
  if (g.vao == 0) return;
  glDeleteBuffers(1, &g.vbo);
  glDeleteBuffers(1, &g.ibo);
  glDeleteBuffers(1, &g.instance_vbo);
  glDeleteVertexArrays(1, &g.vao);
}

// Per-vertex RGBA of one mesh: bark colour or the attribute's colour map; leaves and crowns in
// their colour unless coloured by an attribute, crowns always at kCrownOpacity (as the renders);
// obstacles always in stone, translucent ones at the opacity of their translucency
// (translucent_obstacle_opacity, as the renders).
std::vector<glm::vec4> vertex_colors(const TriangleMesh& mesh, const ViewerOptions& o,
                                     const Scene& scene, float value_offset) {
  auto rgba = [](Material m, float alpha) {
    const std::array<float, 3> c = material_color(m);
    return glm::vec4(c[0], c[1], c[2], alpha);
  };
  std::vector<glm::vec4> colors(mesh.vertex_count(), rgba(Material::kBark, 1.0f));
  if (!o.color_by.empty()) {
    const auto a = mesh.attribute(o.color_by);
    const float lo = scene.value_lo, hi = scene.value_hi;
    const float span = hi > lo ? hi - lo : 1.0f;
    for (std::size_t i = 0; i < colors.size(); ++i) {
      if (std::isnan(a[i])) continue;  // no value: the bark's colour, as the renders draw it
      colors[i] = glm::vec4(colormap((a[i] + value_offset - lo) / span), 1.0f);
    }
  }
  const bool gammas = mesh.has_attribute("translucency");
  const bool own = o.color_by.empty() && mesh.has_vertex_colors();
  const std::vector<std::array<float, 3>> own_colors =
      own ? resolved_vertex_colors(mesh) : std::vector<std::array<float, 3>>{};
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const Material m = mesh.materials[t];
    if (own && (m == Material::kLeaf || m == Material::kBark)) {  // a crown from a photograph
      for (auto i : mesh.triangles[t]) {
        colors[i] = glm::vec4(own_colors[i][0], own_colors[i][1], own_colors[i][2], 1.0f);
      }
      continue;
    }
    if (m == Material::kBark) continue;
    const bool by_attribute =
        !o.color_by.empty() && (m == Material::kLeaf || m == Material::kCrown);
    for (auto i : mesh.triangles[t]) {
      float alpha = m == Material::kCrown ? kCrownOpacity : 1.0f;
      if (m == Material::kTranslucentObstacle) {
        alpha = gammas ? translucent_obstacle_opacity(mesh.attribute("translucency")[i])
                       : kTranslucentObstacleOpacity;
      }
      colors[i] = by_attribute ? glm::vec4(glm::vec3(colors[i]), alpha) : rgba(m, alpha);
    }
  }
  return colors;
}

// The corners of the blended triangles of `mesh` with their colours.
BlendedPart blended_part(const TriangleMesh& mesh, const std::vector<glm::vec4>& colors) {
  BlendedPart part;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (!is_blended(mesh.materials[t])) continue;
    for (auto i : mesh.triangles[t]) {
      part.positions.push_back(mesh.positions[i]);
      part.normals.push_back(mesh.normals[i]);
      part.colors.push_back(colors[i]);
    }
  }
  return part;
}

// Interleaved position, normal, colour of one shared mesh; blended triangles after the others
// (the shadow pass draws them all, the scene pass only the opaque ones: the blended ones are
// drawn from the sorted soup).
GpuMesh upload(const TriangleMesh& mesh, const std::vector<glm::mat4>& models,
               const std::vector<glm::vec4>& colors) {
  std::vector<float> v;
  v.reserve(mesh.vertex_count() * kFloatsPerVertex);
  for (std::size_t i = 0; i < mesh.vertex_count(); ++i) {
    const auto& p = mesh.positions[i];
    const auto& n = mesh.normals[i];
    const glm::vec4& c = colors[i];
    v.insert(v.end(), {p.x(), p.y(), p.z(), n.x(), n.y(), n.z(), c.r, c.g, c.b, c.a});
  }
  // Bark first (closed tubes: their back faces are culled), the other opaque triangles, then
  // the blended ones.
  std::vector<std::uint32_t> idx, other, translucent;
  idx.reserve(mesh.triangle_count() * 3);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const Material m = mesh.materials[t];
    auto& to = is_blended(m) ? translucent : (m == Material::kBark ? idx : other);
    to.insert(to.end(), mesh.triangles[t].begin(), mesh.triangles[t].end());
  }
  const std::size_t bark = idx.size();
  idx.insert(idx.end(), other.begin(), other.end());
  const std::size_t opaque = idx.size();
  idx.insert(idx.end(), translucent.begin(), translucent.end());
  GpuMesh g = upload_raw(v, idx, opaque, models);
  g.bark_indices = static_cast<GLsizei>(bark);
  return g;
}

// The blended triangles of every mesh placed by `models` (one list per mesh) into one soup on
// the GPU, in index order until the first sort.
void place_blended(GpuStep& g, const std::vector<std::vector<glm::mat4>>& models) {
  release(g.soup.mesh);
  g.soup = BlendedSoup{};
  std::vector<float> v;
  std::vector<Eigen::Vector3f> corners;
  for (std::size_t k = 0; k < g.blended.size(); ++k) {
    const BlendedPart& part = g.blended[k];
    for (const glm::mat4& model : models[k]) {
      const glm::mat3 turn(model);  // rotation times uniform scale
      for (std::size_t i = 0; i < part.positions.size(); ++i) {
        const Eigen::Vector3f& p = part.positions[i];
        const glm::vec3 w = glm::vec3(model * glm::vec4(p.x(), p.y(), p.z(), 1.0f));
        const glm::vec3 n =
            turn * glm::vec3(part.normals[i].x(), part.normals[i].y(), part.normals[i].z());
        const glm::vec4& c = part.colors[i];
        v.insert(v.end(), {w.x, w.y, w.z, n.x, n.y, n.z, c.r, c.g, c.b, c.a});
        corners.emplace_back(w.x, w.y, w.z);
      }
    }
  }
  if (corners.empty()) return;
  std::vector<std::uint32_t> idx(corners.size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<std::uint32_t>(i);
  g.soup.mesh = upload_raw(v, idx, 0, {glm::mat4(1.0f)});
  g.soup.centroids = soup_centroids(corners);
}

// The soup's triangles back to front from `eye` (painter's algorithm), when the eye has moved.
void sort_blended(BlendedSoup& soup, const glm::vec3& eye) {
  if (soup.mesh.vao == 0 || (soup.sorted && soup.sorted_for == eye)) return;
  const std::vector<std::uint32_t> order =
      back_to_front(soup.centroids, Eigen::Vector3f(eye.x, eye.y, eye.z));
  std::vector<std::uint32_t> idx;
  idx.reserve(3 * order.size());
  for (std::uint32_t t : order) idx.insert(idx.end(), {3 * t, 3 * t + 1, 3 * t + 2});
  glBindVertexArray(soup.mesh.vao);  // the element buffer binding belongs to the vertex array
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, soup.mesh.ibo);
  glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(idx.size() * 4), idx.data());
  glBindVertexArray(0);
  soup.sorted = true;
  soup.sorted_for = eye;
}

GpuStep upload(const StepRef& step, const ViewerOptions& o, const Scene& scene) {
  GpuStep g;
  for (std::size_t k = 0; k < step.meshes.size(); ++k) {
    if (step.meshes[k]->empty()) {
      g.meshes.emplace_back();  // nothing to draw, kept so indices match the step's meshes
      g.blended.emplace_back();
      continue;
    }
    const std::vector<glm::vec4> colors =
        vertex_colors(*step.meshes[k], o, scene, step.value_offsets[k]);
    g.meshes.push_back(upload(*step.meshes[k], step.models[k], colors));
    g.blended.push_back(blended_part(*step.meshes[k], colors));
    g.triangles += step.meshes[k]->triangle_count() * step.models[k].size();
  }
  place_blended(g, step.models);
  return g;
}

// kAll: every triangle (the shadow pass); kOpaque: the opaque ones alone (the blended ones are
// drawn from the step's sorted soup).
enum class Part { kAll, kOpaque };

// `mode`: GL_TRIANGLES, or GL_PATCHES of three vertices for the tessellation program.
void draw(const GpuMesh& g, Part part = Part::kAll, GLenum mode = GL_TRIANGLES) {
  if (g.vao == 0 || g.instances == 0) return;
  const GLsizei end = part == Part::kOpaque ? g.opaque_indices : g.indices;
  if (end <= 0) return;
  glBindVertexArray(g.vao);
  if (part == Part::kOpaque && g.bark_indices > 0) {
    // The bark's tubes are closed and counter-clockwise seen from outside: their back faces
    // are hidden, so they are culled before they are rasterized.
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glDrawElementsInstanced(mode, g.bark_indices, GL_UNSIGNED_INT, nullptr, g.instances);
    glDisable(GL_CULL_FACE);
  }
  const GLsizei first = part == Part::kOpaque ? g.bark_indices : 0;
  if (end > first) {
    glDrawElementsInstanced(mode, end - first, GL_UNSIGNED_INT,
                            reinterpret_cast<const void*>(static_cast<std::uintptr_t>(first) * 4),
                            g.instances);
  }
}

struct Camera {
  float yaw = -0.9f, pitch = 0.35f, distance = 1.0f;  // radians, metres
  glm::vec3 target{0.0f};
  glm::vec3 eye() const {
    return target + distance * glm::vec3(std::cos(pitch) * std::cos(yaw),
                                         std::cos(pitch) * std::sin(yaw), std::sin(pitch));
  }
};

struct State {
  Camera camera, home;
  ViewerControls controls;  // the keys and the panel change them
  int steps = 1;
  const ViewerPanel* panel = nullptr;  // while it has the mouse or keys, the camera does not
  bool dragging_orbit = false, dragging_pan = false;
  double last_x = 0, last_y = 0;
};

State* state_of(GLFWwindow* w) { return static_cast<State*>(glfwGetWindowUserPointer(w)); }

void on_key(GLFWwindow* w, int key, int, int action, int) {
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  State* s = state_of(w);
  if (s->panel != nullptr && s->panel->wants_keyboard()) return;
  int& step = s->controls.step;
  if (key == GLFW_KEY_ESCAPE || key == GLFW_KEY_Q) glfwSetWindowShouldClose(w, GLFW_TRUE);
  if (key == GLFW_KEY_RIGHT_BRACKET || key == GLFW_KEY_RIGHT)
    step = std::min(step + 1, s->steps - 1);
  if (key == GLFW_KEY_LEFT_BRACKET || key == GLFW_KEY_LEFT) step = std::max(step - 1, 0);
  if (key == GLFW_KEY_S) s->controls.shadows = !s->controls.shadows;
  if (key == GLFW_KEY_R) s->camera = s->home;
}

void on_button(GLFWwindow* w, int button, int action, int mods) {
  State* s = state_of(w);
  glfwGetCursorPos(w, &s->last_x, &s->last_y);
  const bool down = action == GLFW_PRESS;
  if (down && s->panel != nullptr && s->panel->wants_mouse()) return;  // a click on the panel
  if (button == GLFW_MOUSE_BUTTON_LEFT && !(mods & GLFW_MOD_SHIFT)) s->dragging_orbit = down;
  if (button == GLFW_MOUSE_BUTTON_RIGHT ||
      (button == GLFW_MOUSE_BUTTON_LEFT && (mods & GLFW_MOD_SHIFT))) {
    s->dragging_pan = down;
  }
}

void on_cursor(GLFWwindow* w, double x, double y) {
  State* s = state_of(w);
  const float dx = static_cast<float>(x - s->last_x), dy = static_cast<float>(y - s->last_y);
  s->last_x = x;
  s->last_y = y;
  Camera& c = s->camera;
  if (s->dragging_orbit) {
    c.yaw -= 0.01f * dx;
    c.pitch = std::clamp(c.pitch + 0.01f * dy, -1.5f, 1.5f);
  } else if (s->dragging_pan) {
    const glm::vec3 forward = glm::normalize(c.target - c.eye());
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 0, 1)));
    const glm::vec3 up = glm::cross(right, forward);
    c.target += c.distance * 0.0015f * (-dx * right + dy * up);
  }
}

void on_scroll(GLFWwindow* w, double, double dy) {
  State* s = state_of(w);
  if (s->panel != nullptr && s->panel->wants_mouse()) return;
  s->camera.distance *= std::pow(0.9f, static_cast<float>(dy));
}

struct GlfwSession {
  GlfwSession() {
    // A busy (virtual) X server sometimes refuses a connection; retry for a few seconds.
    bool ok = false;
    for (int attempt = 0; attempt < 30 && !ok; ++attempt) {
      ok = glfwInit() == GLFW_TRUE;
      if (!ok) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    if (!ok) {
      throw IoError(
          "cannot start GLFW (no display?): run under a virtual server, e.g. xvfb-run -a fspm "
          "view ...");
    }
  }
  ~GlfwSession() { glfwTerminate(); }
};

}  // namespace

bool viewer_available() { return true; }

namespace {

// The range of `color_by` over every step (nothing for the materials' colours).
void measure_values(const std::vector<StepRef>& steps, const std::string& color_by, Scene& scene) {
  scene.color_by = color_by;
  scene.value_lo = 1e30f;
  scene.value_hi = -1e30f;
  if (color_by.empty()) return;
  for (const auto& step : steps) {
    for (std::size_t k = 0; k < step.meshes.size(); ++k) {
      for (float x : step.meshes[k]->attribute(color_by)) {
        scene.value_lo = std::min(scene.value_lo, x + step.value_offsets[k]);
        scene.value_hi = std::max(scene.value_hi, x + step.value_offsets[k]);
      }
    }
  }
}

// The corners of each placed copy's cube around the crown's bounding sphere.
void relief_bounds(const ReliefCrown& crown, glm::vec3& lo, glm::vec3& hi) {
  crown.validate();
  const Eigen::AlignedBox3f box = crown.placed_bounds();
  if (box.isEmpty()) return;
  lo = glm::min(lo, glm::vec3(box.min().x(), box.min().y(), box.min().z()));
  hi = glm::max(hi, glm::vec3(box.max().x(), box.max().y(), box.max().z()));
}

// Step 1: the arguments checked before any window opens; the bounds of every step and the range
// of the colour attribute.
Scene check_and_measure(const std::vector<StepRef>& steps, const ViewerOptions& o,
                        const std::vector<StepRef>& coarse_steps) {
  if (steps.empty()) throw ValueError("nothing to view");
  if (!coarse_steps.empty() && coarse_steps.size() != steps.size()) {
    throw ValueError("coarse meshes must match the growth steps one to one");
  }
  if (!o.color_by.empty()) {
    for (const auto& step : steps) {
      for (const auto* m : step.meshes) (void)m->attribute(o.color_by);
    }
  }
  if (!o.screenshot.empty()) check_image_path(o.screenshot);
  o.validate();
  static_assert(kMaxShadowLayers == kMaxShadowCascades + 1, "the cascades and the whole scene");
  Scene scene;
  scene.lo = glm::vec3(1e30f);
  scene.hi = glm::vec3(-1e30f);
  for (const auto& step : steps) bounds(step, scene.lo, scene.hi);
  for (const ReliefCrown& crown : o.relief_crowns) relief_bounds(crown, scene.lo, scene.hi);
  if (scene.lo.x > scene.hi.x) scene.lo = scene.hi = glm::vec3(0.0f);
  measure_values(steps, o.color_by, scene);
  return scene;
}

// Step 2: an OpenGL 3.3 core window (hidden for screenshots) with the camera framing the scene
// and the input callbacks on `state`.
GLFWwindow* open_window(const ViewerOptions& o, const Scene& scene, int steps, State& state) {
  const bool offscreen = !o.screenshot.empty();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, offscreen ? GLFW_FALSE : GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(o.width, o.height, "fspm view", nullptr, nullptr);
  if (window == nullptr) throw IoError("cannot open an OpenGL 3.3 core window");
  glfwMakeContextCurrent(window);
  glfwSwapInterval(offscreen ? 0 : 1);
  const float radius = std::max(0.5f * glm::length(scene.hi - scene.lo), 0.1f);
  state.camera.target = 0.5f * (scene.lo + scene.hi);
  if (o.look_at) state.camera.target = glm::vec3((*o.look_at)[0], (*o.look_at)[1], (*o.look_at)[2]);
  state.camera.distance =
      o.camera_distance_m > 0.0 ? static_cast<float>(o.camera_distance_m) : 2.6f * radius;
  state.camera.pitch = static_cast<float>(glm::radians(o.pitch_deg));
  state.camera.yaw = static_cast<float>(glm::radians(o.yaw_deg));
  state.home = state.camera;
  state.steps = steps;
  state.controls.step = state.steps - 1;
  state.controls.shadows = o.shadows;
  state.controls.shadow_cascades = o.shadow_cascades;
  state.controls.color_by = o.color_by;
  state.controls.lod_distance_m = o.lod_distance_factor * state.home.distance;
  if (o.coarse_edge_m > 0.0) {
    // Pixels per metre at distance d: H / (2 d tan(fov / 2)), the vertical field of view 40 deg.
    const double two_pixels_m =
        o.coarse_edge_m * o.height / (2.0 * std::tan(glm::radians(20.0)) * kCoarseEdgePixels);
    state.controls.lod_distance_m = std::min(state.controls.lod_distance_m, two_pixels_m);
  }
  glfwSetWindowUserPointer(window, &state);
  glfwSetKeyCallback(window, on_key);
  glfwSetMouseButtonCallback(window, on_button);
  glfwSetCursorPosCallback(window, on_cursor);
  glfwSetScrollCallback(window, on_scroll);
  return window;
}

// Step 3: shaders, every step's meshes and the ground on the GPU, into `g`.
struct GpuScene {
  GLuint scene_program = 0;
  std::vector<GpuStep> steps, coarse;
  GLuint ground_program = 0;
  GLuint ground_vao = 0;  // no attributes: the ground's triangle comes from gl_VertexID
  std::unique_ptr<ReliefCrownRenderer> relief;  // with ViewerOptions::relief_crowns
  std::unique_ptr<ImpostorRenderer> impostors;  // level of detail with impostors
  bool ground = true;                           // ViewerOptions::ground
  // With tessellation shaders: the program and expression 2's limits (D_max, L_max).
  GLuint tessellation_program = 0;
  float tessellation_distance = 1.0f, max_level = 1.0f;
};

// The steps' meshes as held, and as uploaded (upload_raw): kFloatsPerVertex floats a vertex, 3
// indices a triangle and a matrix an instance, which the driver keeps beside the meshes
// (a software renderer in system memory). Both must fit the memory limit before the upload.
void check_upload_memory(const std::vector<StepRef>& steps, const std::vector<StepRef>& coarse) {
  double held = 0.0, uploaded = 0.0;
  std::set<const TriangleMesh*> counted;
  for (const std::vector<StepRef>* list : {&steps, &coarse}) {
    for (const StepRef& step : *list) {
      for (std::size_t k = 0; k < step.meshes.size(); ++k) {
        const TriangleMesh& m = *step.meshes[k];
        if (counted.insert(&m).second) {
          held +=
              TriangleMesh::bytes_for(m.vertex_count(), m.triangle_count(), m.attributes.size());
        }
        uploaded += static_cast<double>(m.vertex_count() * kFloatsPerVertex) * sizeof(float) +
                    static_cast<double>(m.triangle_count()) * 3.0 * sizeof(std::uint32_t) +
                    static_cast<double>(step.models[k].size()) * sizeof(glm::mat4);
      }
    }
  }
  check_memory(held + uploaded, "drawing " + std::to_string(steps.size()) +
                                    " steps (their meshes and the copies uploaded for drawing)");
}

void upload_scene(GpuScene& g, const std::vector<StepRef>& steps,
                  const std::vector<StepRef>& coarse, const ViewerOptions& o, const Scene& scene) {
  check_upload_memory(steps, coarse);
  g.scene_program = program(kSceneVs, kSceneFs, true);
  for (const auto& step : steps) g.steps.push_back(upload(step, o, scene));
  for (const auto& step : coarse) g.coarse.push_back(upload(step, o, scene));
  g.ground_program = program(kGroundVs, kGroundFs, true);
  glGenVertexArrays(1, &g.ground_vao);
  if (!o.relief_crowns.empty()) {
    g.relief = std::make_unique<ReliefCrownRenderer>(o.relief_crowns, kShadowReceiverGlsl);
  }
}

void release(GpuScene& g) {
  for (auto* list : {&g.steps, &g.coarse}) {
    for (auto& step : *list) {
      for (auto& m : step.meshes) release(m);
      release(step.soup.mesh);
    }
  }
  g.relief.reset();  // while the context is current
  g.impostors.reset();
  glDeleteVertexArrays(1, &g.ground_vao);
  glDeleteProgram(g.ground_program);
  glDeleteProgram(g.scene_program);
  if (g.tessellation_program != 0) glDeleteProgram(g.tessellation_program);
}

// Impostors of a level-of-detail scene's plants (when it has an impostor distance), their views
// drawn from the finest meshes of the first step as uploaded, so in the colours shown.
std::unique_ptr<ImpostorRenderer> make_impostors(GpuScene& gpu, const LodView& lod) {
  if (lod.scene == nullptr || lod.options.impostor_distance_m <= 0.0) return nullptr;
  GpuStep& g = gpu.steps.front();
  const auto draw_plant = [&](std::size_t plant) {
    GpuMesh& m = g.meshes[lod.scene->mesh_index(plant, 0, 0)];
    if (m.vao == 0) return;
    set_instances(m, {glm::mat4(1.0f)});
    draw(m, Part::kOpaque);
  };
  return std::make_unique<ImpostorRenderer>(*lod.scene, ImpostorViews{}, kImpostorResolution,
                                            draw_plant, kShadowReceiverGlsl);
}

// The shadow maps (viewer_shadow_maps.hpp) and, for screenshots, the offscreen target (a hidden
// window's default framebuffer is undefined).
struct Targets {
  std::unique_ptr<ShadowMaps> shadow_maps;
  // What the maps hold: the step and its casters they were drawn for (none: draw them), and each
  // layer's matrix, with which the receivers look it up, and the frame it was drawn in. The sun
  // is fixed, so the whole scene's map changes only with what casts shadows; a cascade's also
  // when the camera moves it.
  const GpuStep* shadow_step = nullptr;
  std::uint64_t shadow_casters = 0;
  std::array<glm::mat4, kMaxShadowLayers> drawn_mvps{};
  std::array<std::size_t, kMaxShadowLayers> drawn_in_frame{};
  std::size_t frame = 0;
  std::size_t layers_drawn = 0;                       // ViewerStats::shadow_maps_drawn
  GLuint target_fbo = 0, color_rb = 0, depth_rb = 0;  // 0: the window
};

Targets make_targets(const ViewerOptions& o) {
  Targets t;
  t.shadow_maps = std::make_unique<ShadowMaps>(kShadowSize, o.shadow_cascades + 1);
  if (o.screenshot.empty()) return t;
  glGenFramebuffers(1, &t.target_fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, t.target_fbo);
  glGenRenderbuffers(1, &t.color_rb);
  glBindRenderbuffer(GL_RENDERBUFFER, t.color_rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, o.width, o.height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, t.color_rb);
  glGenRenderbuffers(1, &t.depth_rb);
  glBindRenderbuffer(GL_RENDERBUFFER, t.depth_rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, o.width, o.height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t.depth_rb);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw IoError("cannot create the offscreen framebuffer");
  }
  return t;
}

void release(Targets& t) {
  t.shadow_maps.reset();  // while the context is current
  if (t.target_fbo == 0) return;
  glDeleteFramebuffers(1, &t.target_fbo);
  glDeleteRenderbuffers(1, &t.color_rb);
  glDeleteRenderbuffers(1, &t.depth_rb);
}

// Step 4: the matrices of one frame: the camera's perspective and the shadow maps' orthographic
// views from the sun: the cascades of the camera's frustum (shadow_cascades.hpp), nearest first,
// then the whole scene.
struct FrameMatrices {
  glm::vec3 sun{0.0f}, eye{0.0f};
  glm::mat4 mvp{1.0f};
  std::array<glm::mat4, kMaxShadowLayers> light_mvps{};
  std::vector<ShadowCascade> cascades;
  Eigen::Matrix3d sun_axes = Eigen::Matrix3d::Identity();
  int width = 0, height = 0;
  float ground_z = 0.0f, haze_distance = 1.0f;
};

// The cascades reach this many camera distances (eye to target) along the view; beyond, the
// whole scene's map shades.
constexpr double kCascadeReach = 3.0;
// Zhang et al.'s blend of logarithmic and uniform splits: mostly logarithmic, so the nearest
// cascade is a few metres deep at a tree's height, not the tenth of the view a uniform split
// would give it.
constexpr double kCascadeLambda = 0.75;

glm::mat4 to_glm(const Eigen::Matrix4d& m) {
  const Eigen::Matrix4f f = m.cast<float>();
  return glm::make_mat4(f.data());
}

Eigen::Vector3d to_eigen(const glm::vec3& v) { return {v.x, v.y, v.z}; }

// The cascades of the camera's frustum from its near plane to kCascadeReach distances.
void fit_cascades(FrameMatrices& f, const Camera& c, const Scene& scene, double far_m,
                  int cascades) {
  CascadeCamera camera;
  camera.eye = to_eigen(f.eye);
  camera.forward = to_eigen(c.target - f.eye).normalized();
  camera.vertical_fov_rad = glm::radians(40.0);
  camera.aspect = static_cast<double>(f.width) / std::max(f.height, 1);
  const double near_m = 0.01 * c.distance;
  const auto splits =
      cascade_splits(near_m, std::min(far_m, kCascadeReach * c.distance), cascades, kCascadeLambda);
  const Eigen::AlignedBox3d box(to_eigen(scene.lo), to_eigen(scene.hi));
  f.cascades = fit_shadow_cascades(camera, splits, to_eigen(f.sun), box, kShadowSize);
  for (int k = 0; k < cascades; ++k) f.light_mvps[k] = to_glm(f.cascades[k].light_view_projection);
}

FrameMatrices frame_matrices(const State& state, const Scene& scene, int width, int height,
                             int cascades) {
  FrameMatrices f;
  f.width = width;
  f.height = height;
  const glm::vec3 center = 0.5f * (scene.lo + scene.hi);
  const float radius = std::max(0.5f * glm::length(scene.hi - scene.lo), 0.1f);
  f.sun = glm::normalize(glm::vec3(0.5f, -0.4f, 1.0f));
  f.sun_axes = sun_axes(to_eigen(f.sun));
  const float scene_radius = radius * 2.2f;  // ground included
  const glm::mat4 light_view =
      glm::lookAt(center + f.sun * (2.0f * scene_radius), center, glm::vec3(0, 1, 0));
  const glm::mat4 light_proj = glm::ortho(-scene_radius, scene_radius, -scene_radius, scene_radius,
                                          0.01f * scene_radius, 4.0f * scene_radius);
  f.light_mvps[cascades] = light_proj * light_view;
  const Camera& c = state.camera;
  f.eye = c.eye();
  const glm::mat4 view = glm::lookAt(f.eye, c.target, glm::vec3(0, 0, 1));
  const float far_m = 10.0f * c.distance + radius * 4;
  const glm::mat4 proj =
      glm::perspective(glm::radians(40.0f), static_cast<float>(width) / std::max(height, 1),
                       0.01f * c.distance, far_m);
  f.mvp = proj * view;
  if (cascades > 0) fit_cascades(f, c, scene, far_m, cascades);
  f.ground_z = scene.lo.z;
  f.haze_distance = kHazeRadii * radius;
  return f;
}

// FNV-1a over what each instance's choice draws: equal hashes, equal shadow casters.
std::uint64_t choice_hash(const std::vector<InstanceLod>& choice) {
  std::uint64_t h = 1469598103934665603ULL;
  const auto mix = [&](std::uint64_t v) { h = (h ^ v) * 1099511628211ULL; };
  for (const InstanceLod& c : choice) {
    mix(c.visible ? (c.impostor ? 2 : 1) : 0);
    mix(c.resolution);
    mix(c.share);
  }
  return h;
}

// Per-instance level of detail: the instances of every mesh of `g` chosen for this camera.
void choose_instances(GpuStep& g, const LodView& lod, const FrameMatrices& f,
                      ImpostorRenderer* impostors) {
  const Eigen::Matrix4d vp =
      Eigen::Map<const Eigen::Matrix4f>(glm::value_ptr(f.mvp)).cast<double>();
  const Eigen::Vector3d eye(f.eye.x, f.eye.y, f.eye.z);
  const std::vector<InstanceLod> choice = select_lod(*lod.scene, eye, vp, lod.options);
  g.casters = choice_hash(choice);
  const std::vector<MeshInstance> instances = lod_instances(*lod.scene, choice);
  if (impostors != nullptr) impostors->place(choice, glm::value_ptr(f.eye), glm::value_ptr(f.sun));
  std::vector<std::vector<glm::mat4>> models(g.meshes.size());
  for (const MeshInstance& inst : instances) models[inst.mesh].push_back(model_matrix(inst));
  for (std::size_t k = 0; k < g.meshes.size(); ++k) {
    if (g.meshes[k].vao != 0) set_instances(g.meshes[k], models[k]);
  }
  const bool blended = std::any_of(g.blended.begin(), g.blended.end(),
                                   [](const BlendedPart& p) { return !p.positions.empty(); });
  if (blended) place_blended(g, models);
  g.triangles = lod_triangle_count(*lod.scene, instances);
  if (impostors != nullptr) g.triangles += 2 * impostors->quads();
}

// The uniforms of kShadowReceiverGlsl on program p (in use); the maps on texture unit 0.
void set_shadow_uniforms(GLuint p, const Targets& t, const FrameMatrices& f, bool shadows) {
  t.shadow_maps->use_in(p, shadows, glm::value_ptr(t.drawn_mvps[0]), glm::value_ptr(f.sun));
}

// The ground to the horizon (kGroundFs), first after the clear; GL_LEQUAL lets the points beyond
// the far plane, clamped to depth 1, pass against the cleared depth.
void draw_ground(const GpuScene& gpu, const Targets& t, const FrameMatrices& f, bool shadows) {
  const GLuint p = gpu.ground_program;
  glUseProgram(p);
  glUniformMatrix4fv(glGetUniformLocation(p, "mvp"), 1, GL_FALSE, glm::value_ptr(f.mvp));
  const glm::mat4 inverse = glm::inverse(f.mvp);
  glUniformMatrix4fv(glGetUniformLocation(p, "inverse_mvp"), 1, GL_FALSE, glm::value_ptr(inverse));
  glUniform3fv(glGetUniformLocation(p, "sun"), 1, glm::value_ptr(f.sun));
  glUniform3fv(glGetUniformLocation(p, "eye"), 1, glm::value_ptr(f.eye));
  glUniform3fv(glGetUniformLocation(p, "ground_color"), 1, kGround);
  glUniform3fv(glGetUniformLocation(p, "haze_color"), 1, kSky);
  glUniform1f(glGetUniformLocation(p, "ground_z"), f.ground_z);
  glUniform1f(glGetUniformLocation(p, "haze_distance"), f.haze_distance);
  glUniform1f(glGetUniformLocation(p, "max_haze"), kMaxHaze);
  set_shadow_uniforms(p, t, f, shadows);
  glDepthFunc(GL_LEQUAL);
  glBindVertexArray(gpu.ground_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDepthFunc(GL_LESS);
}

// The instances of `m` whose bounding spheres may cast a shadow into cascade `c` (casts_into).
std::vector<glm::mat4> cascade_casters(const GpuMesh& m, const ShadowCascade& c,
                                       const Eigen::Matrix3d& sun_axes) {
  std::vector<glm::mat4> kept;
  for (const glm::mat4& model : m.models) {
    const glm::vec3 centre = glm::vec3(model * glm::vec4(glm::vec3(m.bound), 1.0f));
    const float radius = m.bound.w * glm::length(glm::vec3(model[0]));  // uniform scale
    if (casts_into(c, sun_axes, to_eigen(centre), radius)) kept.push_back(model);
  }
  return kept;
}

// Layer k of the shadow maps for step `g`. A cascade's map draws only the instances that may
// cast into it (a mesh with one instance is drawn whole: culling pays for many), then puts the
// others back. The ground is not drawn: a plane under the scene shadows nothing above it.
void draw_shadow_layer(const GpuScene& gpu, GpuStep& g, Targets& t, const FrameMatrices& f, int k) {
  const bool cascade = k < static_cast<int>(f.cascades.size());
  const float* light_mvp = glm::value_ptr(f.light_mvps[k]);
  t.shadow_maps->draw_layer(k, light_mvp, [&](unsigned) {
    for (GpuMesh& m : g.meshes) {
      const bool cull = cascade && m.models.size() > 1;
      if (cull) upload_instances(m, cascade_casters(m, f.cascades[k], f.sun_axes));
      draw(m);
      if (cull) upload_instances(m, m.models);
    }
    if (gpu.relief) gpu.relief->draw_moments(light_mvp, glm::value_ptr(f.sun));
    if (gpu.impostors) gpu.impostors->draw_moments(light_mvp);
  });
  t.drawn_mvps[k] = f.light_mvps[k];
  t.drawn_in_frame[k] = t.frame;
  ++t.layers_drawn;
}

// The maps that no longer show this frame's casters: all of them for a new step or level-of-
// detail choice. Else, of the cascades the camera moved away from this frame's slices, the one
// drawn longest ago: one cascade a frame bounds the cost of a moving camera, and a cascade drawn
// for an earlier camera is still a true shadow map of its own square, looked up with the matrix
// it was drawn with (points outside it fall to the next map).
void update_shadow_maps(const GpuScene& gpu, GpuStep& g, Targets& t, const FrameMatrices& f) {
  ++t.frame;
  if (t.shadow_step != &g || t.shadow_casters != g.casters) {
    for (int k = 0; k < t.shadow_maps->layers(); ++k) draw_shadow_layer(gpu, g, t, f, k);
    t.shadow_step = &g;
    t.shadow_casters = g.casters;
    return;
  }
  int stalest = -1;
  for (int k = 0; k < static_cast<int>(f.cascades.size()); ++k) {
    if (t.drawn_mvps[k] == f.light_mvps[k]) continue;
    if (stalest < 0 || t.drawn_in_frame[k] < t.drawn_in_frame[stalest]) stalest = k;
  }
  if (stalest >= 0) draw_shadow_layer(gpu, g, t, f, stalest);
}

// Uses program p (the scene's or the tessellation's) and sets the scene shader's uniforms.
void use_scene_program(GLuint p, const Targets& t, const FrameMatrices& f, bool shadows) {
  glUseProgram(p);
  glUniformMatrix4fv(glGetUniformLocation(p, "mvp"), 1, GL_FALSE, glm::value_ptr(f.mvp));
  glUniform3fv(glGetUniformLocation(p, "sun"), 1, glm::value_ptr(f.sun));
  glUniform3fv(glGetUniformLocation(p, "eye"), 1, glm::value_ptr(f.eye));
  set_shadow_uniforms(p, t, f, shadows);
}

// The opaque triangles as patches of the tessellation program (viewer_tessellation.hpp), with
// the scene program's uniforms and expression 2's limits.
void draw_tessellated(const GpuScene& gpu, const GpuStep& g, const Targets& t,
                      const FrameMatrices& f, bool shadows) {
  const GLuint p = gpu.tessellation_program;
  use_scene_program(p, t, f, shadows);
  glUniform1f(glGetUniformLocation(p, "max_distance"), gpu.tessellation_distance);
  glUniform1f(glGetUniformLocation(p, "max_level"), gpu.max_level);
  glUniform1f(glGetUniformLocation(p, "pixels_per_radian"),
              static_cast<float>(f.height) / (2.0f * std::tan(glm::radians(20.0f))));
  glPatchParameteri(GL_PATCH_VERTICES, 3);
  for (const GpuMesh& m : g.meshes) draw(m, Part::kOpaque, GL_PATCHES);
}

// Step 5: the shadow map, then the scene: opaque geometry and the ground, then the crowns and
// translucent obstacles blended over it back to front (sorted by sort_blended), without writing
// depth.
void draw_frame(const GpuScene& gpu, GpuStep& g, Targets& t, const FrameMatrices& f, bool shadows) {
  if (shadows) update_shadow_maps(gpu, g, t, f);
  glEnable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, t.target_fbo);
  glViewport(0, 0, f.width, f.height);
  glClearColor(kSky[0], kSky[1], kSky[2], 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  if (gpu.ground) draw_ground(gpu, t, f, shadows);
  const GLuint p = gpu.scene_program;
  use_scene_program(p, t, f, shadows);
  if (gpu.tessellation_program != 0) {
    draw_tessellated(gpu, g, t, f, shadows);
    glUseProgram(p);
  } else {
    for (const GpuMesh& m : g.meshes) draw(m, Part::kOpaque);
  }
  if (gpu.impostors) {
    glUseProgram(gpu.impostors->program());
    set_shadow_uniforms(gpu.impostors->program(), t, f, shadows);
    gpu.impostors->draw(glm::value_ptr(f.mvp));
    glUseProgram(p);
  }
  if (gpu.relief) {
    for (const GLuint rp : gpu.relief->programs()) {
      glUseProgram(rp);
      set_shadow_uniforms(rp, t, f, shadows);
    }
    gpu.relief->draw(glm::value_ptr(f.mvp), glm::value_ptr(f.eye), glm::value_ptr(f.sun));
    glUseProgram(p);  // the blended soup below is drawn by the scene program
  }
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);  // keep alpha 1
  glDepthMask(GL_FALSE);
  draw(g.soup.mesh);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

// The steps as StepRefs coloured by an attribute: meshes of instanced steps are grouped by order
// offset when coloured by order (step_ref), so a new colour may need new references.
using StepMaker = std::function<void(const std::string& color_by, std::vector<StepRef>& steps,
                                     std::vector<StepRef>& coarse)>;

// Every step uploaded again, coloured by `color_by` (chosen on the panel).
void recolor(GpuScene& gpu, Scene& scene, const StepMaker& make, ViewerOptions o,
             const std::string& color_by) {
  o.color_by = color_by;
  std::vector<StepRef> steps, coarse;
  make(color_by, steps, coarse);
  measure_values(steps, color_by, scene);
  for (auto* list : {&gpu.steps, &gpu.coarse}) {
    for (auto& step : *list) {
      for (auto& m : step.meshes) release(m);
      release(step.soup.mesh);
    }
    list->clear();
  }
  for (const auto& step : steps) gpu.steps.push_back(upload(step, o, scene));
  for (const auto& step : coarse) gpu.coarse.push_back(upload(step, o, scene));
}

// A tree in the wind: its vertex buffer as uploaded (colours included), read back once per
// upload, and the posed positions and normals of the frame.
struct WindBuffer {
  GLuint vbo = 0;  // the buffer `interleaved` was read from; 0: read it again
  std::vector<float> interleaved;
  std::vector<Eigen::Vector3f> positions, normals;
};

// The blended corners (crown volumes) of the posed mesh, in blended_part's order, placed anew
// in the soup, which is sorted again before it is drawn.
void sway_blended(GpuStep& g, const TriangleMesh& mesh, const WindBuffer& w) {
  BlendedPart& part = g.blended.front();
  if (part.positions.empty()) return;
  std::size_t corner = 0;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (!is_blended(mesh.materials[t])) continue;
    for (auto i : mesh.triangles[t]) {
      part.positions[corner] = w.positions[i];
      part.normals[corner] = w.normals[i];
      ++corner;
    }
  }
  place_blended(g, {{glm::mat4(1.0f)}});
}

// The step's one mesh posed at t_s, its positions and normals written over the uploaded ones
// (the shadow pass draws the same buffer, so the shadows sway too), and its crown volumes.
void sway(GpuStep& g, WindBuffer& w, const ViewerWind& wind, double t_s, double strength) {
  const GpuMesh& m = g.meshes.front();
  const std::size_t n = wind.mesh.vertex_count();
  const auto bytes = static_cast<GLsizeiptr>(n * kFloatsPerVertex * sizeof(float));
  glBindBuffer(GL_ARRAY_BUFFER, m.vbo);
  if (w.vbo != m.vbo) {
    w.interleaved.resize(n * kFloatsPerVertex);
    glGetBufferSubData(GL_ARRAY_BUFFER, 0, bytes, w.interleaved.data());
    w.vbo = m.vbo;
  }
  wind.pose(t_s, strength, w.positions, w.normals);
  for (std::size_t i = 0; i < n; ++i) {
    float* v = w.interleaved.data() + kFloatsPerVertex * i;  // as upload_raw lays it out
    std::copy_n(w.positions[i].data(), 3, v);
    std::copy_n(w.normals[i].data(), 3, v + 3);
  }
  glBufferSubData(GL_ARRAY_BUFFER, 0, bytes, w.interleaved.data());
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  sway_blended(g, wind.mesh, w);
}

// What a frame needs besides the GPU: the scene, the step references for recolouring, the ages,
// the per-plant level of detail, the panel with what it shows, and the wind's time and buffer.
struct FrameContext {
  Scene scene;
  StepMaker make;
  const std::vector<double>* labels = nullptr;
  LodView lod;
  ViewerPanel* panel = nullptr;
  PanelInfo info;
  double time_s = 0.0;
  WindBuffer wind;
};

// One frame: the controls applied (colour, level of detail), the scene and the panel drawn.
// Returns the step drawn.
const GpuStep& draw_controlled_frame(GLFWwindow* window, State& state, GpuScene& gpu, Targets& t,
                                     FrameContext& x, const ViewerOptions& o) {
  ViewerControls& c = state.controls;
  c.step = std::clamp(c.step, 0, state.steps - 1);
  if (c.color_by != x.scene.color_by) {
    gpu.impostors.reset();
    recolor(gpu, x.scene, x.make, o, c.color_by);
    t.shadow_step = nullptr;  // new buffers
    gpu.impostors = make_impostors(gpu, x.lod);
    x.wind.vbo = 0;  // new buffers, new colours to keep
  }
  x.info.far = !gpu.coarse.empty() && state.camera.distance > c.lod_distance_m;
  GpuStep& g = x.info.far ? gpu.coarse[c.step] : gpu.steps[c.step];
  int fw = o.width, fh = o.height;
  if (o.screenshot.empty()) glfwGetFramebufferSize(window, &fw, &fh);
  c.shadow_cascades = std::clamp(c.shadow_cascades, 0, kMaxShadowLayers - 1);
  if (c.shadow_cascades + 1 != t.shadow_maps->layers()) {
    t.shadow_maps = std::make_unique<ShadowMaps>(kShadowSize, c.shadow_cascades + 1);
    t.shadow_step = nullptr;  // new maps
  }
  const FrameMatrices f = frame_matrices(state, x.scene, fw, fh, c.shadow_cascades);
  if (x.lod.scene != nullptr) {
    // The panel's distance moves the impostors' with it.
    x.lod.options.impostor_distance_m *= c.lod_distance_m / x.lod.options.max_distance_m;
    x.lod.options.max_distance_m = c.lod_distance_m;
    choose_instances(g, x.lod, f, gpu.impostors.get());
  }
  if (o.wind && !x.info.far) {
    sway(g, x.wind, *o.wind, x.time_s, c.wind_strength);
    t.shadow_step = nullptr;  // the casters moved
  }
  sort_blended(g.soup, f.eye);
  draw_frame(gpu, g, t, f, c.shadows);
  x.info.triangles = g.triangles;
  x.panel->draw(x.info, c, fw, fh);
  return g;
}

// Step 6: frames until the window closes (or `frames` frames for a screenshot, or
// `close_after_frames` on screen), timed.
ViewerStats run_frames(GLFWwindow* window, State& state, GpuScene& gpu, Targets& t, FrameContext& x,
                       const ViewerOptions& o) {
  const bool offscreen = !o.screenshot.empty();
  const std::vector<double>& labels = *x.labels;
  ViewerStats stats;
  double total_ms = 0.0, smooth_ms = 0.0;
  const auto start = std::chrono::steady_clock::now();
  constexpr double kScreenshotFps = 24.0;  // the wind's clock for screenshots
  while (!glfwWindowShouldClose(window)) {
    if (o.before_frame) o.before_frame(stats.frames, state.controls);
    const auto t0 = std::chrono::steady_clock::now();
    x.time_s = offscreen ? stats.frames / kScreenshotFps
                         : std::chrono::duration<double>(t0 - start).count();
    const GpuStep& g = draw_controlled_frame(window, state, gpu, t, x, o);
    glFinish();
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    total_ms += ms;
    if (stats.frames == 0) stats.first_frame_ms = ms;
    smooth_ms = stats.frames == 0 ? ms : 0.9 * smooth_ms + 0.1 * ms;
    x.info.frame_ms = smooth_ms;
    ++stats.frames;
    stats.triangles = g.triangles;
    stats.impostors = gpu.impostors ? gpu.impostors->quads() : 0;
    if (offscreen) {
      if (stats.frames >= o.frames) break;
      glfwPollEvents();
      continue;
    }
    const int step = state.controls.step;
    char title[160];
    std::snprintf(title, sizeof(title),
                  "fspm view  |  step %d/%d  age %g  |  %zu triangles%s  |  %.1f ms/frame",
                  step + 1, state.steps,
                  step < static_cast<int>(labels.size()) ? labels[step] : 0.0, g.triangles,
                  x.info.far ? " (far LOD)" : "", smooth_ms);
    glfwSetWindowTitle(window, title);
    glfwSwapBuffers(window);
    glfwPollEvents();
    if (o.close_after_frames > 0 && stats.frames >= o.close_after_frames) break;
  }
  stats.mean_frame_ms = stats.frames > 0 ? total_ms / stats.frames : 0.0;
  stats.controls = state.controls;
  stats.shadow_maps_drawn = t.layers_drawn;
  return stats;
}

// Step 7: the offscreen image read back (OpenGL rows start at the bottom) and written.
void write_screenshot(const ViewerOptions& o, const Targets& t) {
  Image image;
  image.width = o.width;
  image.height = o.height;
  image.rgba.resize(static_cast<std::size_t>(o.width) * o.height * 4);
  std::vector<std::uint8_t> raw(image.rgba.size());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, t.target_fbo);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, o.width, o.height, GL_RGBA, GL_UNSIGNED_BYTE, raw.data());
  const std::size_t row = static_cast<std::size_t>(o.width) * 4;
  for (int y = 0; y < o.height; ++y) {
    std::copy_n(raw.data() + row * (o.height - 1 - y), row, image.rgba.data() + row * y);
  }
  write_image(image, o.screenshot);
}

// The colour attributes every mesh of every step has (the panel's choices).
std::vector<std::string> common_attributes(const std::vector<StepRef>& steps) {
  std::vector<std::string> names;
  bool first = true;
  for (const auto& step : steps) {
    for (const TriangleMesh* m : step.meshes) {
      if (m->empty()) continue;
      std::vector<std::string> here = m->attribute_names();
      if (first) {
        names = here;
        first = false;
        continue;
      }
      std::erase_if(names, [&](const std::string& n) {
        return std::find(here.begin(), here.end(), n) == here.end();
      });
    }
  }
  return names;
}

// The CPU path's one level: expression 2 at the starting camera distance for a triangle of the
// largest area, (1 - d / D_max) L_max rounded up, lowered until no mesh exceeds
// kCpuTessellationTriangles triangles.
int cpu_tessellation_level(const std::vector<StepRef>& steps, const ViewerOptions& o,
                           double max_distance_m, double home_distance_m) {
  const double level =
      tessellation_level(home_distance_m, 1.0, {max_distance_m, 1.0, o.tessellation_max_level});
  int l = std::max(1, static_cast<int>(std::ceil(level)));
  std::size_t largest = 1;
  for (const StepRef& step : steps) {
    for (const TriangleMesh* m : step.meshes) largest = std::max(largest, m->triangle_count());
  }
  while (l > 1 && largest * static_cast<std::size_t>(l * l) > kCpuTessellationTriangles) --l;
  return l;
}

// `make` with every mesh of its steps tessellated on the CPU at `level`, the copies kept in
// `store` (as long as the viewer runs).
StepMaker tessellated_on_cpu(StepMaker make, int level,
                             std::shared_ptr<std::deque<TriangleMesh>> store) {
  return
      [make = std::move(make), level, store](
          const std::string& color_by, std::vector<StepRef>& steps, std::vector<StepRef>& coarse) {
        make(color_by, steps, coarse);
        store->clear();
        for (auto* list : {&steps, &coarse}) {
          for (StepRef& step : *list) {
            for (const TriangleMesh*& m : step.meshes) {
              store->push_back(tessellate_pn(*m, level));
              m = &store->back();
            }
          }
        }
      };
}

// ViewerOptions::tessellation_max_level: the tessellation program when the context runs
// tessellation shaders (and the CPU path is not asked for), else the CPU path's maker, which
// remakes `steps`. Neither for a tree in the wind (posed on the CPU as meshed) or a
// level-of-detail scene (whose meshes are chosen by index), nor without a level.
void set_up_tessellation(const ViewerOptions& o, const LodView& lod, const State& state,
                         StepMaker& make, std::vector<StepRef>& steps, std::vector<StepRef>& coarse,
                         GpuScene& gpu, ViewerStats& stats) {
  if (o.tessellation_max_level <= 0.0 || o.wind || lod.scene != nullptr) return;
  const double max_distance =
      o.tessellation_distance_m > 0.0 ? o.tessellation_distance_m : 4.0 * state.home.distance;
  if (!o.tessellation_on_cpu && tessellation_shaders_available()) {
    gpu.tessellation_program = tessellation_program(std::string(kShadowReceiverGlsl) + kSceneFs);
    gpu.tessellation_distance = static_cast<float>(max_distance);
    gpu.max_level = static_cast<float>(o.tessellation_max_level);
    stats.tessellation = "gpu";
    return;
  }
  const int level = cpu_tessellation_level(steps, o, max_distance, state.home.distance);
  stats.tessellation = "cpu";
  stats.cpu_tessellation_level = level;
  if (level == 1) return;
  make = tessellated_on_cpu(make, level, std::make_shared<std::deque<TriangleMesh>>());
  make(o.color_by, steps, coarse);
}

ViewerStats view(StepMaker make, const std::vector<double>& labels, const ViewerOptions& o,
                 const LodView& lod = {}) {
  std::vector<StepRef> steps, coarse_steps;
  make(o.color_by, steps, coarse_steps);
  if (o.wind &&
      (steps.size() != 1 || steps[0].meshes.size() != 1 || steps[0].models[0].size() != 1 ||
       steps[0].meshes[0]->vertex_count() != o.wind->mesh.vertex_count())) {
    throw ValueError("the viewer's wind sways one tree, the only mesh of the only step");
  }
  FrameContext x;
  x.scene = check_and_measure(steps, o, coarse_steps);
  x.make = make;
  x.labels = &labels;
  x.lod = lod;
  GlfwSession session;
  State state;
  GLFWwindow* window = open_window(o, x.scene, static_cast<int>(steps.size()), state);
  ViewerStats tessellation;
  GpuScene gpu;
  set_up_tessellation(o, lod, state, make, steps, coarse_steps, gpu, tessellation);
  x.make = make;
  upload_scene(gpu, steps, coarse_steps, o, x.scene);
  gpu.impostors = make_impostors(gpu, lod);
  gpu.ground = o.ground;
  Targets targets = make_targets(o);
  ViewerPanel panel(window, o.panel);
  state.panel = &panel;
  x.panel = &panel;
  x.info.labels = &labels;
  x.info.label_name = o.step_label;
  x.info.wind = o.wind != nullptr;
  x.info.steps = state.steps;
  x.info.attributes = common_attributes(steps);
  if (lod.scene != nullptr) {
    state.controls.lod_distance_m = lod.options.max_distance_m;
    x.info.lod_min_m = 0.05 * lod.options.max_distance_m;
    x.info.lod_max_m = 5.0 * lod.options.max_distance_m;
  } else if (!coarse_steps.empty()) {
    x.info.lod_min_m = 0.25 * state.home.distance;
    x.info.lod_max_m = 20.0 * state.home.distance;
  }
  ViewerStats stats = run_frames(window, state, gpu, targets, x, o);
  stats.tessellation = tessellation.tessellation;
  stats.cpu_tessellation_level = tessellation.cpu_tessellation_level;
  if (!o.screenshot.empty()) write_screenshot(o, targets);
  release(gpu);
  release(targets);
  glfwDestroyWindow(window);
  return stats;
}

}  // namespace

bool viewer_panel_available() {
#ifdef FSPM_HAVE_IMGUI
  return true;
#else
  return false;
#endif
}

ViewerStats run_viewer(const std::vector<TriangleMesh>& steps, const std::vector<double>& labels,
                       const ViewerOptions& o, const std::vector<TriangleMesh>& coarse_steps) {
  // Plain meshes: the references do not depend on the colour.
  const StepMaker make = [&](const std::string&, std::vector<StepRef>& refs,
                             std::vector<StepRef>& coarse) {
    refs.clear();
    coarse.clear();
    for (const auto& m : steps) refs.push_back(step_ref(m));
    for (const auto& m : coarse_steps) coarse.push_back(step_ref(m));
  };
  return view(make, labels, o);
}

ViewerStats run_instanced_viewer(const std::vector<InstancedMesh>& steps,
                                 const std::vector<double>& labels, const ViewerOptions& o,
                                 const std::vector<InstancedMesh>& coarse_steps) {
  const StepMaker make = [&](const std::string& color_by, std::vector<StepRef>& refs,
                             std::vector<StepRef>& coarse) {
    refs.clear();
    coarse.clear();
    for (const auto& m : steps) refs.push_back(step_ref(m, color_by));
    for (const auto& m : coarse_steps) coarse.push_back(step_ref(m, color_by));
  };
  return view(make, labels, o);
}

ViewerStats run_lod_viewer(const LodScene& scene, const LodOptions& lod_options,
                           const ViewerOptions& o) {
  lod_options.validate();
  const StepMaker make = [&](const std::string&, std::vector<StepRef>& refs,
                             std::vector<StepRef>& coarse) {
    refs = {step_ref(scene)};
    coarse.clear();
  };
  static const std::vector<double> kNoLabels;
  return view(make, kNoLabels, o, LodView{&scene, lod_options});
}

}  // namespace fspm::graphics
