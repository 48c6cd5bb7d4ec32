// Relief-mapped ray casting of crowns in the viewer (Argudo 2014, 5.1). The march takes
// kCameraSteps (kShadowSteps from the sun) equal steps through the bounding sphere, then bisects
// the step where the ray entered the crown; the normal is the gradient of |q| - R(q), by central
// differences.
#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>

#include <Eigen/LU>
#include <array>
#include <string>

#include "graphics/gl_shader.hpp"
#include "graphics/viewer_relief.hpp"

namespace fspm::graphics {
namespace {

// Steps of the march through the bounding sphere, for the picture and for the shadow map.
constexpr int kCameraSteps = 96;
constexpr int kShadowSteps = 24;

const char* kReliefVs = R"(#version 330 core
layout(location = 0) in vec3 corner;  // of the cube [-1, 1]^3
uniform mat4 view_projection;
uniform mat4 model;  // world from the crown's frame
uniform vec3 centre;
uniform float bound;
out vec3 v_local;
void main() {
  v_local = centre + bound * corner;
  gl_Position = view_projection * model * vec4(v_local, 1.0);
}
)";

// After "#version 330 core" and the viewer's variance-shadow code (lit()).
const char* kReliefFs = R"(
in vec3 v_local;
uniform mat4 view_projection;  // the camera's, or the sun's in the moments pass
uniform mat4 light_mvp;
uniform mat4 model;
uniform int moments_pass;  // 1: the sun's orthographic view, writing depth moments
uniform vec3 eye_local;    // the eye in the crown's frame (camera pass)
uniform vec3 ray_local;    // the sun's viewing direction in the crown's frame (moments pass)
uniform vec3 centre;
uniform float bound;
uniform float face_size;
uniform vec3 sun;
uniform sampler2D radius_map;  // the 6N x N strip, row 0 at t = 0
uniform sampler2D color_map;
uniform int steps;  // of the march: fewer for shadows, which need less precision
out vec4 frag;

// graphics/relief_crown.cpp's face_coordinates and relief_radius_m: the face a direction falls
// on, and the texel position within it, half a texel from the face's edges.
vec2 strip_uv(vec3 d) {
  vec3 a = abs(d);
  float face, u, v;
  if (a.z >= a.x && a.z >= a.y) {
    face = d.z > 0.0 ? 4.0 : 5.0;
    u = d.x / a.z;
    v = (d.z > 0.0 ? -d.y : d.y) / a.z;
  } else if (a.x >= a.y) {
    face = d.x > 0.0 ? 1.0 : 3.0;
    u = (d.x > 0.0 ? d.y : -d.y) / a.x;
    v = -d.z / a.x;
  } else {
    face = d.y < 0.0 ? 0.0 : 2.0;
    u = (d.y < 0.0 ? d.x : -d.x) / a.y;
    v = -d.z / a.y;
  }
  float x = clamp(0.5 * (u + 1.0) * face_size, 0.5, face_size - 0.5);
  float y = clamp(0.5 * (v + 1.0) * face_size, 0.5, face_size - 0.5);
  return vec2((face * face_size + x) / (6.0 * face_size), y / face_size);
}

float outside(vec3 p) {  // > 0 outside the crown, <= 0 inside
  vec3 q = p - centre;
  float r = length(q);
  return r < 1e-6 * bound ? -1.0 : r - texture(radius_map, strip_uv(q)).r;
}

void main() {
  // The camera's rays leave the eye; the sun's are parallel, started outside the sphere.
  vec3 d = moments_pass == 1 ? ray_local : normalize(v_local - eye_local);
  vec3 origin = moments_pass == 1 ? v_local - 4.0 * bound * d : eye_local;
  vec3 oc = origin - centre;
  float b = dot(oc, d);
  float disc = b * b - (dot(oc, oc) - bound * bound);
  if (disc < 0.0) discard;
  float t0 = max(-b - sqrt(disc), 0.0), t1 = -b + sqrt(disc);
  if (t1 <= t0) discard;
  float dt = (t1 - t0) / float(steps);
  float t = t0;
  bool hit = false;
  for (int i = 0; i <= steps; ++i) {
    if (outside(origin + t * d) <= 0.0) {
      hit = true;
      break;
    }
    t += dt;
  }
  if (!hit) discard;
  float lo = max(t - dt, t0), hi = t;
  for (int i = 0; i < 8; ++i) {
    float mid = 0.5 * (lo + hi);
    if (outside(origin + mid * d) <= 0.0) hi = mid; else lo = mid;
  }
  vec3 p = origin + hi * d;
  vec4 world = model * vec4(p, 1.0);
  vec4 clip = view_projection * world;
  float depth = clamp(clip.z / clip.w * 0.5 + 0.5, 0.0, 1.0);
  gl_FragDepth = depth;
  if (moments_pass == 1) {  // as the viewer's moments pass (Pirk eq. 6.10), without slope bias
    frag = vec4(depth, depth * depth, 0.0, 0.0);
    return;
  }
  float e = bound / 128.0;
  vec3 g = vec3(outside(p + vec3(e, 0, 0)) - outside(p - vec3(e, 0, 0)),
                outside(p + vec3(0, e, 0)) - outside(p - vec3(0, e, 0)),
                outside(p + vec3(0, 0, e)) - outside(p - vec3(0, 0, e)));
  if (dot(g, g) < 1e-20) g = p - centre;
  vec3 n = normalize(mat3(model) * g);  // rotation times uniform scale
  vec3 albedo = texture(color_map, strip_uv(p - centre)).rgb;
  float s = lit(light_mvp * world);
  vec3 c = albedo * (0.35 + 0.65 * max(dot(n, sun), 0.0) * s);
  frag = vec4(pow(c, vec3(1.0 / 1.2)), 1.0);
}
)";

GLuint texture_2d(GLint internal_format, int width, int height, GLenum format, GLenum type,
                  const void* data) {
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, internal_format, width, height, 0, format, type, data);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  return tex;
}

struct GpuCrown {
  GLuint radius_tex = 0, color_tex = 0;
  float face_size = 0.0f;
  float bound = 0.0f;  // a little beyond the largest radius
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();
  std::vector<Eigen::Matrix4f> placements;
};

}  // namespace

struct ReliefCrownRenderer::Gpu {
  GLuint program = 0, vao = 0, vbo = 0, ibo = 0;
  std::vector<GpuCrown> crowns;
};

namespace {

// The cube [-1, 1]^3 as 8 corners and 12 triangles, wound counter-clockwise seen from outside.
void upload_cube(GLuint& vao, GLuint& vbo, GLuint& ibo) {
  const std::array<float, 24> corners = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1,
                                         -1, -1, 1,  1, -1, 1,  1, 1, 1,  -1, 1, 1};
  const std::array<unsigned, 36> idx = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                        1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof(corners), corners.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
  glGenBuffers(1, &ibo);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof(idx), idx.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
}

}  // namespace

ReliefCrownRenderer::ReliefCrownRenderer(const std::vector<ReliefCrown>& crowns,
                                         const std::string& shadow_glsl)
    : gpu_(std::make_unique<Gpu>()) {
  gpu_->program = gl_program(kReliefVs, "#version 330 core\n" + shadow_glsl + kReliefFs);
  upload_cube(gpu_->vao, gpu_->vbo, gpu_->ibo);
  for (const ReliefCrown& c : crowns) {
    validate(c);
    GpuCrown g;
    const int n = c.face_size;
    g.radius_tex = texture_2d(GL_R32F, 6 * n, n, GL_RED, GL_FLOAT, c.radius_m.data());
    g.color_tex = texture_2d(GL_RGB8, 6 * n, n, GL_RGB, GL_UNSIGNED_BYTE, c.rgb.data());
    g.face_size = static_cast<float>(n);
    g.bound = 1.01f * c.max_radius_m();
    g.centre = c.centre_m;
    g.placements = c.placements;
    gpu_->crowns.push_back(std::move(g));
  }
}

ReliefCrownRenderer::~ReliefCrownRenderer() {
  for (const GpuCrown& g : gpu_->crowns) {
    glDeleteTextures(1, &g.radius_tex);
    glDeleteTextures(1, &g.color_tex);
  }
  glDeleteBuffers(1, &gpu_->vbo);
  glDeleteBuffers(1, &gpu_->ibo);
  glDeleteVertexArrays(1, &gpu_->vao);
  glDeleteProgram(gpu_->program);
}

unsigned ReliefCrownRenderer::program() const { return gpu_->program; }

void ReliefCrownRenderer::draw(const float* view_projection, const float* eye, const float* sun,
                               const float* light_mvp) const {
  glUseProgram(gpu_->program);
  glUniformMatrix4fv(glGetUniformLocation(gpu_->program, "light_mvp"), 1, GL_FALSE, light_mvp);
  glUniform1i(glGetUniformLocation(gpu_->program, "moments_pass"), 0);
  glUniform1i(glGetUniformLocation(gpu_->program, "steps"), kCameraSteps);
  draw_cubes(view_projection, sun, [&](const Eigen::Matrix4f& model) {
    const Eigen::Vector4f eye_local = model.inverse() * Eigen::Vector4f(eye[0], eye[1], eye[2], 1);
    glUniform3fv(glGetUniformLocation(gpu_->program, "eye_local"), 1, eye_local.data());
  });
}

void ReliefCrownRenderer::draw_moments(const float* light_mvp, const float* sun) const {
  glUseProgram(gpu_->program);
  glUniform1i(glGetUniformLocation(gpu_->program, "moments_pass"), 1);
  glUniform1i(glGetUniformLocation(gpu_->program, "steps"), kShadowSteps);
  draw_cubes(light_mvp, sun, [&](const Eigen::Matrix4f& model) {
    // The sun looks along -sun; in the crown's frame, through the inverse rotation and scale.
    const Eigen::Vector3f ray =
        (model.block<3, 3>(0, 0).inverse() * -Eigen::Vector3f(sun[0], sun[1], sun[2])).normalized();
    glUniform3fv(glGetUniformLocation(gpu_->program, "ray_local"), 1, ray.data());
  });
}

template <typename PerPlacement>
void ReliefCrownRenderer::draw_cubes(const float* view_projection, const float* sun,
                                     const PerPlacement& per_placement) const {
  const GLuint p = gpu_->program;
  auto at = [p](const char* name) { return glGetUniformLocation(p, name); };
  glUniformMatrix4fv(at("view_projection"), 1, GL_FALSE, view_projection);
  glUniform3fv(at("sun"), 1, sun);
  glUniform1i(at("radius_map"), 1);
  glUniform1i(at("color_map"), 2);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);  // back faces: the cube is drawn even with the eye inside it
  glBindVertexArray(gpu_->vao);
  for (const GpuCrown& g : gpu_->crowns) {
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, g.radius_tex);
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D, g.color_tex);
    glUniform3fv(at("centre"), 1, g.centre.data());
    glUniform1f(at("bound"), g.bound);
    glUniform1f(at("face_size"), g.face_size);
    for (const Eigen::Matrix4f& model : g.placements) {
      glUniformMatrix4fv(at("model"), 1, GL_FALSE, model.data());
      per_placement(model);
      glDrawElements(GL_TRIANGLES, 36, GL_UNSIGNED_INT, nullptr);
    }
  }
  glBindVertexArray(0);
  glDisable(GL_CULL_FACE);
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace fspm::graphics
