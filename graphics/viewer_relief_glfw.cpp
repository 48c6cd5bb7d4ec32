// Relief-mapped ray casting of crowns in the viewer (Argudo 2014, 5.1). The march takes
// kCameraSteps (kShadowSteps from the sun) equal steps through the bounding sphere, then bisects
// the step where the ray entered the crown; the normal is the gradient of |q| - R(q), by central
// differences.
#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <array>
#include <cmath>
#include <limits>
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

// What both forms of a crown read (after "#version 330 core" and the viewer's variance-shadow
// code, lit()): the cubemaps, the strip lookup and Argudo's shading (5.3).
const char* kCrownGlsl = R"(
uniform vec3 centre;
uniform float bound;
uniform float face_size;
uniform vec3 sun;
uniform sampler2D radius_map;  // the 6N x N strip, row 0 at t = 0
uniform sampler2D color_map;

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

float surface_radius(vec3 q) { return texture(radius_map, strip_uv(q)).r; }

// Argudo 5.3's three terms for a point q of the crown (from its centre) whose surface lies
// surface_r away in its direction: the lower (the more crown above it) and the deeper below the
// surface, the more occluded; then Lambert's cosine with the shadow factor s. The weights are
// ours (Argudo gives none): the bottom keeps 80 %, the centre 75 %.
vec3 crown_shade(vec3 albedo, vec3 q, float surface_r, vec3 n, float s) {
  float height = clamp(0.5 + 0.5 * q.z / bound, 0.0, 1.0);
  float depth = clamp(length(q) / max(surface_r, 1e-6 * bound), 0.0, 1.0);
  float occlusion = (0.8 + 0.2 * height) * (0.75 + 0.25 * depth);
  vec3 c = albedo * occlusion * (0.35 + 0.65 * max(dot(n, sun), 0.0) * s);
  return pow(c, vec3(1.0 / 1.2));
}
)";

// After kCrownGlsl.
const char* kReliefFs = R"(
in vec3 v_local;
uniform mat4 view_projection;  // the camera's, or the sun's in the moments pass
uniform mat4 model;
uniform int moments_pass;  // 1: the sun's orthographic view, writing depth moments
uniform vec3 eye_local;    // the eye in the crown's frame (camera pass)
uniform vec3 ray_local;    // the sun's viewing direction in the crown's frame (moments pass)
uniform int steps;  // of the march: fewer for shadows, which need less precision
out vec4 frag;

float outside(vec3 p) {  // > 0 outside the crown, <= 0 inside
  vec3 q = p - centre;
  float r = length(q);
  return r < 1e-6 * bound ? -1.0 : r - surface_radius(q);
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
  vec3 q = p - centre;
  vec3 albedo = texture(color_map, strip_uv(q)).rgb;
  frag = vec4(crown_shade(albedo, q, surface_radius(q), n, lit(world.xyz)), 1.0);
}
)";

// Argudo 5.2's billboards: a square facing the eye at each centre (instanced), in the crown's
// frame.
const char* kBillboardVs = R"(#version 330 core
layout(location = 0) in vec2 corner;     // of the square [-1, 1]^2
layout(location = 1) in vec3 billboard;  // its centre in the crown's frame, one per instance
uniform mat4 view_projection;
uniform mat4 model;
uniform vec3 eye_local;
uniform float half_side;  // with every billboard drawn
uniform float drawn;      // how many are drawn (fractional)
uniform float available;  // of how many
out vec3 v_local;
out vec2 v_uv;
flat out float v_index;
flat out vec3 v_centre;
flat out vec3 v_right;
flat out vec3 v_up;
flat out float v_half;
void main() {
  vec3 to_eye = normalize(eye_local - billboard);
  vec3 up0 = abs(to_eye.z) > 0.99 ? vec3(0.0, 1.0, 0.0) : vec3(0.0, 0.0, 1.0);
  vec3 right = normalize(cross(up0, to_eye));
  vec3 up = cross(to_eye, right);
  // Fewer billboards cover the crown as well when each is larger: the squares' summed area is
  // kept (Argudo 5.2 draws few of them for distant crowns).
  float h = half_side * sqrt(available / max(drawn, 1.0));
  v_local = billboard + h * (corner.x * right + corner.y * up);
  v_uv = corner;
  v_index = float(gl_InstanceID);
  v_centre = billboard;
  v_right = right;
  v_up = up;
  v_half = h;
  gl_Position = view_projection * model * vec4(v_local, 1.0);
}
)";

// After kCrownGlsl. The leaves are drawn by the shader (no outside texture): kLeaves elliptic
// leaves per square at places and angles hashed from its index, each coloured by the colour
// cubemap in the direction of its own centre (so the photograph's colours fall leaf by leaf) and
// a little lighter or darker.
const char* kBillboardFs = R"(
in vec3 v_local;
in vec2 v_uv;
flat in float v_index;
flat in vec3 v_centre;
flat in vec3 v_right;
flat in vec3 v_up;
flat in float v_half;
uniform mat4 model;
uniform float drawn;  // the fractional number of billboards drawn
uniform float fade;   // the last `fade` of them fade in
out vec4 frag;

const int kLeaves = 16;

float hash(float n) { return fract(sin(n) * 43758.5453); }

void main() {
  // A billboard fading in shows that share of its leaves (no blending, so no sorting).
  float alpha = clamp((drawn - v_index) / fade, 0.0, 1.0);
  float variation = -1.0;
  vec2 leaf_centre = vec2(0.0);
  for (int k = 0; k < kLeaves; ++k) {
    float seed = v_index * 53.0 + float(k) * 4.0;
    if (hash(seed + 5.0) >= alpha) continue;
    vec2 c = 1.5 * (vec2(hash(seed), hash(seed + 1.0)) - 0.5);
    float a = 6.2831853 * hash(seed + 2.0);
    vec2 p = mat2(cos(a), -sin(a), sin(a), cos(a)) * (v_uv - c);
    float e = (p.x * p.x) / (0.34 * 0.34) + (p.y * p.y) / (0.14 * 0.14);
    if (e < 1.0) {
      variation = (0.8 + 0.4 * hash(seed + 3.0)) * (0.85 + 0.15 * (1.0 - e));
      leaf_centre = c;
    }
  }
  if (variation < 0.0) discard;
  vec3 q = v_local - centre;
  float surface_r = surface_radius(q);
  if (length(q) > surface_r) discard;  // Argudo 5.2: cropped to the crown
  vec3 leaf = v_centre + v_half * (leaf_centre.x * v_right + leaf_centre.y * v_up) - centre;
  vec3 albedo = texture(color_map, strip_uv(dot(leaf, leaf) > 0.0 ? leaf : q)).rgb * variation;
  vec3 radial = dot(q, q) > 0.0 ? normalize(q) : vec3(0.0, 0.0, 1.0);
  vec3 n = normalize(mat3(model) * radial);
  // The shadow of the crown's surface point in the leaf's direction: the relief's own shadow in
  // the map would put every inner leaf in the dark, where Argudo's depth term already shades it.
  vec4 surface = model * vec4(centre + 1.02 * surface_r * radial, 1.0);
  frag = vec4(crown_shade(albedo, q, surface_r, n, lit(surface.xyz)), 1.0);
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
  GLuint billboard_vao = 0, billboard_vbo = 0;  // the square's corners and the centres
  std::size_t billboards = 0;
  float face_size = 0.0f;
  float bound = 0.0f;  // a little beyond the largest radius
  float largest_m = 0.0f;
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();
  std::vector<Eigen::Matrix4f> placements;
};

}  // namespace

struct ReliefCrownRenderer::Gpu {
  GLuint program = 0, billboard_program = 0, vao = 0, vbo = 0, ibo = 0, square_vbo = 0;
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

// The square [-1, 1]^2 as a triangle strip (shared by every crown's billboards).
GLuint upload_square() {
  const std::array<float, 8> corners = {-1, -1, 1, -1, -1, 1, 1, 1};
  GLuint vbo = 0;
  glGenBuffers(1, &vbo);
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof(corners), corners.data(), GL_STATIC_DRAW);
  return vbo;
}

// A crown's billboard centres as per-instance attributes beside the shared square.
void upload_billboards(GpuCrown& g, GLuint square_vbo,
                       const std::vector<Eigen::Vector3f>& centres) {
  g.billboards = centres.size();
  if (centres.empty()) return;
  glGenVertexArrays(1, &g.billboard_vao);
  glBindVertexArray(g.billboard_vao);
  glBindBuffer(GL_ARRAY_BUFFER, square_vbo);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
  glGenBuffers(1, &g.billboard_vbo);
  glBindBuffer(GL_ARRAY_BUFFER, g.billboard_vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(centres.size() * sizeof(Eigen::Vector3f)),
               centres.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Eigen::Vector3f), nullptr);
  glVertexAttribDivisor(1, 1);
  glBindVertexArray(0);
}

// The radius in pixels of a sphere of `radius` (crown frame) around `centre` placed by `model`,
// seen through `view_projection` in a viewport `height_px` high; very large when the eye is at
// or behind its centre. A perspective projection's second row is P11 times the view's, so its
// length is P11 (the focal length over half the viewport).
float projected_radius_px(const Eigen::Matrix4f& view_projection, const Eigen::Matrix4f& model,
                          const Eigen::Vector3f& centre, float radius, float height_px) {
  const Eigen::Vector4f clip = view_projection * model * centre.homogeneous();
  if (clip.w() <= 1e-6f) return std::numeric_limits<float>::max();
  const float scale = std::cbrt(std::abs(model.block<3, 3>(0, 0).determinant()));
  const float focal = view_projection.row(1).head<3>().norm();
  return radius * scale * focal / clip.w() * 0.5f * height_px;
}

}  // namespace

ReliefCrownRenderer::ReliefCrownRenderer(const std::vector<ReliefCrown>& crowns,
                                         const std::string& shadow_glsl)
    : gpu_(std::make_unique<Gpu>()) {
  const std::string fs_head = "#version 330 core\n" + shadow_glsl + kCrownGlsl;
  gpu_->program = gl_program(kReliefVs, fs_head + kReliefFs);
  gpu_->billboard_program = gl_program(kBillboardVs, fs_head + kBillboardFs);
  upload_cube(gpu_->vao, gpu_->vbo, gpu_->ibo);
  gpu_->square_vbo = upload_square();
  for (const ReliefCrown& c : crowns) {
    c.validate();
    GpuCrown g;
    const int n = c.face_size;
    g.radius_tex = texture_2d(GL_R32F, 6 * n, n, GL_RED, GL_FLOAT, c.radius_m.data());
    g.color_tex = texture_2d(GL_RGB8, 6 * n, n, GL_RGB, GL_UNSIGNED_BYTE, c.rgb.data());
    g.face_size = static_cast<float>(n);
    g.largest_m = c.max_radius_m();
    g.bound = 1.01f * g.largest_m;
    g.centre = c.centre_m;
    g.placements = c.placements;
    upload_billboards(g, gpu_->square_vbo, c.billboards_m);
    gpu_->crowns.push_back(std::move(g));
  }
}

ReliefCrownRenderer::~ReliefCrownRenderer() {
  for (const GpuCrown& g : gpu_->crowns) {
    glDeleteTextures(1, &g.radius_tex);
    glDeleteTextures(1, &g.color_tex);
    glDeleteBuffers(1, &g.billboard_vbo);
    glDeleteVertexArrays(1, &g.billboard_vao);
  }
  glDeleteBuffers(1, &gpu_->vbo);
  glDeleteBuffers(1, &gpu_->ibo);
  glDeleteBuffers(1, &gpu_->square_vbo);
  glDeleteVertexArrays(1, &gpu_->vao);
  glDeleteProgram(gpu_->program);
  glDeleteProgram(gpu_->billboard_program);
}

std::array<unsigned, 2> ReliefCrownRenderer::programs() const {
  return {gpu_->program, gpu_->billboard_program};
}

void ReliefCrownRenderer::draw(const float* view_projection, const float* eye,
                               const float* sun) const {
  GLint viewport[4] = {0, 0, 0, 0};
  glGetIntegerv(GL_VIEWPORT, viewport);
  const Eigen::Map<const Eigen::Matrix4f> vp(view_projection);
  glUseProgram(gpu_->program);
  glUniform1i(glGetUniformLocation(gpu_->program, "moments_pass"), 0);
  glUniform1i(glGetUniformLocation(gpu_->program, "steps"), kCameraSteps);
  // Per placement: billboards when the crown is large on the screen (Argudo 5.2), else the relief.
  const auto billboards = [&](const GpuCrown& g, const Eigen::Matrix4f& model) {
    const float radius_px =
        projected_radius_px(vp, model, g.centre, g.largest_m, static_cast<float>(viewport[3]));
    return billboard_count(radius_px, g.billboards);
  };
  const auto eye_in = [&](GLuint p, const Eigen::Matrix4f& model) {
    const Eigen::Vector4f eye_local = model.inverse() * Eigen::Vector4f(eye[0], eye[1], eye[2], 1);
    glUniform3fv(glGetUniformLocation(p, "eye_local"), 1, eye_local.data());
  };
  draw_cubes(view_projection, sun, [&](const GpuCrown& g, const Eigen::Matrix4f& model) {
    if (billboards(g, model) > 0.0f) return false;
    eye_in(gpu_->program, model);
    return true;
  });
  draw_billboards(view_projection, sun, [&](const GpuCrown& g, const Eigen::Matrix4f& model) {
    const float drawn = billboards(g, model);
    if (drawn > 0.0f) eye_in(gpu_->billboard_program, model);
    return drawn;
  });
}

void ReliefCrownRenderer::draw_moments(const float* light_mvp, const float* sun) const {
  glUseProgram(gpu_->program);
  glUniform1i(glGetUniformLocation(gpu_->program, "moments_pass"), 1);
  glUniform1i(glGetUniformLocation(gpu_->program, "steps"), kShadowSteps);
  // The crown's volume casts the shadow whichever form draws it.
  draw_cubes(light_mvp, sun, [&](const GpuCrown&, const Eigen::Matrix4f& model) {
    // The sun looks along -sun; in the crown's frame, through the inverse rotation and scale.
    const Eigen::Vector3f ray =
        (model.block<3, 3>(0, 0).inverse() * -Eigen::Vector3f(sun[0], sun[1], sun[2])).normalized();
    glUniform3fv(glGetUniformLocation(gpu_->program, "ray_local"), 1, ray.data());
    return true;
  });
}

// Binds crown g's cubemaps and sets its uniforms on program p.
void ReliefCrownRenderer::bind_crown(unsigned p, const void* crown) const {
  const GpuCrown& g = *static_cast<const GpuCrown*>(crown);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, g.radius_tex);
  glActiveTexture(GL_TEXTURE2);
  glBindTexture(GL_TEXTURE_2D, g.color_tex);
  glUniform3fv(glGetUniformLocation(p, "centre"), 1, g.centre.data());
  glUniform1f(glGetUniformLocation(p, "bound"), g.bound);
  glUniform1f(glGetUniformLocation(p, "face_size"), g.face_size);
}

void ReliefCrownRenderer::begin_pass(unsigned p, const float* view_projection,
                                     const float* sun) const {
  glUseProgram(p);
  glUniformMatrix4fv(glGetUniformLocation(p, "view_projection"), 1, GL_FALSE, view_projection);
  glUniform3fv(glGetUniformLocation(p, "sun"), 1, sun);
  glUniform1i(glGetUniformLocation(p, "radius_map"), 1);
  glUniform1i(glGetUniformLocation(p, "color_map"), 2);
}

template <typename Use, typename Draw>
void ReliefCrownRenderer::each_placement(unsigned p, const Use& use, const Draw& draw) const {
  for (const GpuCrown& g : gpu_->crowns) {
    if (!use(g)) continue;
    bind_crown(p, &g);
    for (const Eigen::Matrix4f& model : g.placements) {
      glUniformMatrix4fv(glGetUniformLocation(p, "model"), 1, GL_FALSE, model.data());
      draw(g, model);
    }
  }
}

template <typename PerPlacement>
void ReliefCrownRenderer::draw_cubes(const float* view_projection, const float* sun,
                                     const PerPlacement& per_placement) const {
  const GLuint p = gpu_->program;
  begin_pass(p, view_projection, sun);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT);  // back faces: the cube is drawn even with the eye inside it
  glBindVertexArray(gpu_->vao);
  each_placement(
      p, [](const GpuCrown&) { return true; },
      [&](const GpuCrown& g, const Eigen::Matrix4f& model) {
        if (per_placement(g, model)) glDrawElements(GL_TRIANGLES, 36, GL_UNSIGNED_INT, nullptr);
      });
  glBindVertexArray(0);
  glDisable(GL_CULL_FACE);
  glActiveTexture(GL_TEXTURE0);
}

template <typename PerPlacement>
void ReliefCrownRenderer::draw_billboards(const float* view_projection, const float* sun,
                                          const PerPlacement& per_placement) const {
  const GLuint p = gpu_->billboard_program;
  begin_pass(p, view_projection, sun);
  glUniform1f(glGetUniformLocation(p, "fade"), kBillboardFade);
  const auto use = [&](const GpuCrown& g) {
    if (g.billboards == 0) return false;
    glUniform1f(glGetUniformLocation(p, "half_side"), 0.5f * kBillboardSide * g.largest_m);
    glUniform1f(glGetUniformLocation(p, "available"), static_cast<float>(g.billboards));
    glBindVertexArray(g.billboard_vao);
    return true;
  };
  each_placement(p, use, [&](const GpuCrown& g, const Eigen::Matrix4f& model) {
    const float drawn = per_placement(g, model);
    if (drawn <= 0.0f) return;
    glUniform1f(glGetUniformLocation(p, "drawn"), drawn);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(std::ceil(drawn)));
  });
  glBindVertexArray(0);
  glActiveTexture(GL_TEXTURE0);
}

}  // namespace fspm::graphics
