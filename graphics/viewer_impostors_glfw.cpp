// The viewer's impostors of distant plants: views rendered once into texture arrays, quads placed
// every frame (viewer_impostors.hpp).
#define GLFW_INCLUDE_NONE
#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "fspm/error.hpp"
#include "graphics/gl_shader.hpp"
#include "graphics/viewer_impostors.hpp"

namespace fspm::graphics {
namespace {

// The views: albedo and the normal (turned to face the camera, as the scene shader's two-sided
// leaves) in the plant's frame, into two colour attachments; alpha 1 where the plant is.
const char* kViewsVs = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 color;
layout(location = 3) in mat4 model;
uniform mat4 view_projection;
uniform vec3 centre;
uniform float radius;
uniform vec3 toward;  // from the plant to the camera
out vec3 v_normal;
out vec3 v_color;
out float v_depth;
void main() {
  vec4 world = model * vec4(position, 1.0);
  v_normal = mat3(model) * normal;
  v_color = color.rgb;
  // Distance towards the camera from the sphere's centre plane, in radii, mapped to [0, 1].
  v_depth = clamp(dot(world.xyz - centre, toward) / radius * 0.5 + 0.5, 0.0, 1.0);
  gl_Position = view_projection * world;
}
)";
const char* kViewsFs = R"(#version 330 core
in vec3 v_normal;
in vec3 v_color;
in float v_depth;
uniform vec3 toward;
layout(location = 0) out vec4 albedo;
layout(location = 1) out vec4 normal;  // alpha: the depth, as premultiplied as the rest
void main() {
  vec3 n = normalize(v_normal);
  if (dot(n, toward) < 0.0) n = -n;
  albedo = vec4(v_color, 1.0);
  normal = vec4(n * 0.5 + 0.5, v_depth);
}
)";

// Coverage: the mipmapped alpha is the share of the texel's footprint the plant covers, kept
// where it exceeds a 4 x 4 ordered-dither threshold (Bayer), so a sparse crown far away keeps
// about the share of pixels its branches would cover, as the rasterized mesh does.
const char* kCoverageGlsl = R"(
uniform sampler2DArray albedo_map;
// Mipmaps one level finer than the footprint: thin branches keep more of their coverage (as a
// rasterized line of one pixel does) at the cost of a little aliasing.
const float kMipBias = -1.0;
float dither_threshold() {
  ivec2 p = ivec2(gl_FragCoord.xy) & 3;
  int bayer[16] = int[16](0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5);
  return (float(bayer[p.y * 4 + p.x]) + 0.5) / 16.0;
}
)";
const char* kQuadVs = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec2 uv;
layout(location = 2) in float layer;
layout(location = 3) in vec3 sun_local;
layout(location = 4) in float radius;
uniform mat4 view_projection;
out vec3 v_uvl;
out vec3 v_sun;
out vec3 v_world;
out float v_radius;
void main() {
  v_uvl = vec3(uv, layer);
  v_sun = sun_local;
  v_world = position;
  v_radius = radius;
  gl_Position = view_projection * vec4(position, 1.0);
}
)";
// Lit as the scene shader lights opaque geometry (without the small specular term). The shadow
// is looked up at the point the view saw, moved from the quad along the eye's ray by its stored
// depth: the plant's own sun-facing quad then shadows the points behind it from the sun, as the
// leaves in front shadow those behind in a mesh.
const char* kQuadFs = R"(
in vec3 v_uvl;
in vec3 v_sun;
in vec3 v_world;
in float v_radius;
uniform sampler2DArray normal_map;
uniform vec3 eye;
uniform vec3 sun;
out vec4 frag;
void main() {
  vec4 a = texture(albedo_map, v_uvl, kMipBias);
  if (a.a < dither_threshold()) discard;
  vec4 nd = texture(normal_map, v_uvl, kMipBias) / a.a;
  vec3 n = nd.rgb * 2.0 - 1.0;
  vec3 seen = v_world + normalize(eye - v_world) * (nd.a * 2.0 - 1.0) * v_radius;
  float s = lit(seen + 0.05 * v_radius * sun);
  vec3 c = a.rgb / a.a * (0.35 + 0.65 * max(dot(n, normalize(v_sun)), 0.0) * s);
  frag = vec4(pow(c, vec3(1.0 / 1.2)), 1.0);
}
)";
const char* kMomentsVs = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec2 uv;
layout(location = 2) in float layer;
uniform mat4 light_mvp;
out vec3 v_uvl;
out float v_depth;
void main() {
  v_uvl = vec3(uv, layer);
  gl_Position = light_mvp * vec4(position, 1.0);
  v_depth = gl_Position.z * 0.5 + 0.5;
}
)";
// As the viewer's moments pass (kShadowFs), for the covered texels.
const char* kMomentsFs = R"(
in vec3 v_uvl;
in float v_depth;
out vec2 moments;
void main() {
  if (texture(albedo_map, v_uvl, kMipBias).a < dither_threshold()) discard;
  float dx = dFdx(v_depth), dy = dFdy(v_depth);
  moments = vec2(v_depth, v_depth * v_depth + 0.25 * (dx * dx + dy * dy));
}
)";

// One set of quads on the GPU: the vertices, rewritten each frame, and the shared indices.
struct QuadBuffer {
  GLuint vao = 0, vbo = 0;
  GLsizei quads = 0;
};

}  // namespace

struct ImpostorRenderer::Gpu {
  GLuint views_program = 0, quad_program = 0, moments_program = 0;
  GLuint albedo = 0, normal = 0;  // GL_TEXTURE_2D_ARRAY, one layer per view of each plant
  GLuint ibo = 0;
  std::size_t index_quads = 0;  // quads the index buffer holds
  QuadBuffer eye, sun;
};

namespace {

QuadBuffer make_quad_buffer(GLuint ibo) {
  QuadBuffer b;
  glGenVertexArrays(1, &b.vao);
  glBindVertexArray(b.vao);
  glGenBuffers(1, &b.vbo);
  glBindBuffer(GL_ARRAY_BUFFER, b.vbo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
  constexpr GLsizei kStride = sizeof(ImpostorVertex);
  const std::pair<GLint, std::size_t> attributes[] = {{3, offsetof(ImpostorVertex, position)},
                                                      {2, offsetof(ImpostorVertex, uv)},
                                                      {1, offsetof(ImpostorVertex, layer)},
                                                      {3, offsetof(ImpostorVertex, sun_local)},
                                                      {1, offsetof(ImpostorVertex, radius)}};
  for (GLuint a = 0; a < 5; ++a) {
    glEnableVertexAttribArray(a);
    glVertexAttribPointer(a, attributes[a].first, GL_FLOAT, GL_FALSE, kStride,
                          reinterpret_cast<const void*>(attributes[a].second));
  }
  glBindVertexArray(0);
  return b;
}

GLuint make_view_array(int resolution, int layers) {
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D_ARRAY, tex);
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA8, resolution, resolution, layers, 0, GL_RGBA,
               GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return tex;
}

void upload_quads(QuadBuffer& b, const std::vector<ImpostorVertex>& vertices) {
  glBindBuffer(GL_ARRAY_BUFFER, b.vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(ImpostorVertex)),
               vertices.data(), GL_STREAM_DRAW);
  b.quads = static_cast<GLsizei>(vertices.size() / 4);
}

void draw_quads(const QuadBuffer& b) {
  if (b.quads == 0) return;
  glBindVertexArray(b.vao);
  glDrawElements(GL_TRIANGLES, 6 * b.quads, GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
}

}  // namespace

ImpostorRenderer::ImpostorRenderer(const LodScene& scene, const ImpostorViews& views,
                                   int resolution,
                                   const std::function<void(std::size_t plant)>& draw_plant,
                                   const std::string& shadow_glsl)
    : scene_(&scene), views_(views), gpu_(std::make_unique<Gpu>()) {
  views.validate();
  Gpu& g = *gpu_;
  g.views_program = gl_program(kViewsVs, kViewsFs);
  const std::string header = std::string("#version 330 core\n") + kCoverageGlsl;
  g.quad_program = gl_program(kQuadVs, header + shadow_glsl + kQuadFs);
  g.moments_program = gl_program(kMomentsVs, header + kMomentsFs);
  glGenBuffers(1, &g.ibo);
  g.eye = make_quad_buffer(g.ibo);
  g.sun = make_quad_buffer(g.ibo);
  render_views(draw_plant, resolution);
}

ImpostorRenderer::~ImpostorRenderer() {
  Gpu& g = *gpu_;
  for (QuadBuffer* b : {&g.eye, &g.sun}) {
    glDeleteVertexArrays(1, &b->vao);
    glDeleteBuffers(1, &b->vbo);
  }
  glDeleteBuffers(1, &g.ibo);
  glDeleteTextures(1, &g.albedo);
  glDeleteTextures(1, &g.normal);
  glDeleteProgram(g.views_program);
  glDeleteProgram(g.quad_program);
  glDeleteProgram(g.moments_program);
}

// Every view k of every plant p into layer p * views + k: orthographic, the plant's bounding
// sphere filling the square, seen from its centre plus 2 r along the view's direction, +z up.
void ImpostorRenderer::render_views(const std::function<void(std::size_t plant)>& draw_plant,
                                    int resolution) {
  Gpu& g = *gpu_;
  const int per_plant = impostor_view_count(views_);
  const int layers = std::max(1, per_plant * static_cast<int>(scene_->plants.size()));
  g.albedo = make_view_array(resolution, layers);
  g.normal = make_view_array(resolution, layers);
  GLuint fbo = 0, depth = 0;
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glGenRenderbuffers(1, &depth);
  glBindRenderbuffer(GL_RENDERBUFFER, depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, resolution, resolution);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glDrawBuffers(2, buffers);
  glViewport(0, 0, resolution, resolution);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glUseProgram(g.views_program);
  for (std::size_t p = 0; p < scene_->plants.size(); ++p) {
    const BoundingSphere& s = scene_->plants[p].sphere;
    const auto r = static_cast<float>(std::max(s.radius, 1e-6));
    const glm::vec3 c(s.center.x(), s.center.y(), s.center.z());
    for (int k = 0; k < per_plant; ++k) {
      const int layer = static_cast<int>(p) * per_plant + k;
      glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, g.albedo, 0, layer);
      glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, g.normal, 0, layer);
      if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        throw IoError("cannot create the impostor framebuffer");
      }
      glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
      const Eigen::Vector3d d = impostor_view_direction(views_, k);
      const glm::vec3 toward(d.x(), d.y(), d.z());
      const glm::mat4 vp = glm::ortho(-r, r, -r, r, 0.5f * r, 3.5f * r) *
                           glm::lookAt(c + 2.0f * r * toward, c, glm::vec3(0, 0, 1));
      glUniformMatrix4fv(glGetUniformLocation(g.views_program, "view_projection"), 1, GL_FALSE,
                         glm::value_ptr(vp));
      glUniform3fv(glGetUniformLocation(g.views_program, "toward"), 1, glm::value_ptr(toward));
      glUniform3fv(glGetUniformLocation(g.views_program, "centre"), 1, glm::value_ptr(c));
      glUniform1f(glGetUniformLocation(g.views_program, "radius"), r);
      draw_plant(p);
    }
  }
  for (GLuint tex : {g.albedo, g.normal}) {
    glBindTexture(GL_TEXTURE_2D_ARRAY, tex);
    glGenerateMipmap(GL_TEXTURE_2D_ARRAY);
  }
  glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &fbo);
  glDeleteRenderbuffers(1, &depth);
  const GLenum back[] = {GL_BACK};
  glDrawBuffers(1, back);
}

unsigned ImpostorRenderer::program() const { return gpu_->quad_program; }

std::size_t ImpostorRenderer::quads() const { return facing_eye_.size() / 4; }

void ImpostorRenderer::place(const std::vector<InstanceLod>& choice, const float* eye,
                             const float* sun) {
  const Eigen::Vector3d e(eye[0], eye[1], eye[2]), s(sun[0], sun[1], sun[2]);
  sun_ = s.normalized().cast<float>();
  eye_ = e.cast<float>();
  facing_eye_.clear();
  facing_sun_.clear();
  append_impostor_quads(*scene_, choice, views_, e, s, facing_eye_);
  append_impostor_quads_toward(*scene_, choice, views_, s, facing_sun_);
  Gpu& g = *gpu_;
  const std::size_t quads = facing_eye_.size() / 4;
  if (quads > g.index_quads) {  // 0 1 2, 0 2 3 for each quad
    std::vector<std::uint32_t> indices;
    indices.reserve(6 * quads);
    for (std::uint32_t q = 0; q < quads; ++q) {
      for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) indices.push_back(4 * q + i);
    }
    glBindVertexArray(0);  // the element buffer binding belongs to the bound vertex array
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(indices.size() * 4),
                 indices.data(), GL_STATIC_DRAW);
    g.index_quads = quads;
  }
  upload_quads(g.eye, facing_eye_);
  upload_quads(g.sun, facing_sun_);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void ImpostorRenderer::draw(const float* view_projection) const {
  const Gpu& g = *gpu_;
  const GLuint p = g.quad_program;
  glUseProgram(p);
  glUniformMatrix4fv(glGetUniformLocation(p, "view_projection"), 1, GL_FALSE, view_projection);
  glUniform3fv(glGetUniformLocation(p, "sun"), 1, sun_.data());
  glUniform3fv(glGetUniformLocation(p, "eye"), 1, eye_.data());
  glUniform1i(glGetUniformLocation(p, "albedo_map"), 1);
  glUniform1i(glGetUniformLocation(p, "normal_map"), 2);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D_ARRAY, g.albedo);
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_2D_ARRAY, g.normal);
  draw_quads(g.eye);
  glActiveTexture(GL_TEXTURE0);
}

void ImpostorRenderer::draw_moments(const float* light_mvp) const {
  const Gpu& g = *gpu_;
  const GLuint p = g.moments_program;
  glUseProgram(p);
  glUniformMatrix4fv(glGetUniformLocation(p, "light_mvp"), 1, GL_FALSE, light_mvp);
  glUniform1i(glGetUniformLocation(p, "albedo_map"), 1);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D_ARRAY, g.albedo);
  draw_quads(g.sun);
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace fspm::graphics
