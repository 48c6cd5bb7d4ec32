// Tessellation shaders of the viewer (viewer_tessellation.hpp).
#define GLFW_INCLUDE_NONE
#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>

#include "graphics/gl_shader.hpp"
#include "graphics/viewer_tessellation.hpp"

namespace fspm::graphics {
namespace {

const char* kVs = R"(#version 400 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 color;
layout(location = 3) in mat4 model;  // per instance: rotation times uniform scale, translation
out vec3 c_world;
out vec3 c_normal;
out vec4 c_color;
void main() {
  c_world = (model * vec4(position, 1.0)).xyz;
  c_normal = normalize(mat3(model) * normal);
  c_color = color;
}
)";

// Reynolds' expression 2, level = (1 - d / D_max) (A / A_max) L_max, with the projected size as
// the size term: an edge's length on the screen over the length at which it takes every level
// (kPixelsPerSegment pixels a segment), so an edge's level depends on the edge alone and the two
// triangles sharing it split it alike (no crack). The inside takes the largest of its edges'.
// At least 1: the triangle as it is (a plant is not culled by distance here).
const char* kTcs = R"(#version 400 core
layout(vertices = 3) out;
in vec3 c_world[];
in vec3 c_normal[];
in vec4 c_color[];
out vec3 e_world[];
out vec3 e_normal[];
out vec4 e_color[];
uniform vec3 eye;
uniform float max_distance;
uniform float max_level;
uniform float pixels_per_radian;  // the viewport's height over the field of view's tangent
const float kPixelsPerSegment = 4.0;
float edge_level(vec3 a, vec3 b) {
  float d = max(distance(0.5 * (a + b), eye), 1e-6);
  float near = clamp(1.0 - d / max_distance, 0.0, 1.0);
  float size = clamp(distance(a, b) / d * pixels_per_radian / (kPixelsPerSegment * max_level),
                     0.0, 1.0);
  return max(1.0, near * size * max_level);
}
void main() {
  e_world[gl_InvocationID] = c_world[gl_InvocationID];
  e_normal[gl_InvocationID] = c_normal[gl_InvocationID];
  e_color[gl_InvocationID] = c_color[gl_InvocationID];
  if (gl_InvocationID == 0) {
    vec3 p0 = c_world[0], p1 = c_world[1], p2 = c_world[2];
    // Outer level k belongs to the edge opposite corner k.
    gl_TessLevelOuter[0] = edge_level(p1, p2);
    gl_TessLevelOuter[1] = edge_level(p2, p0);
    gl_TessLevelOuter[2] = edge_level(p0, p1);
    gl_TessLevelInner[0] =
        max(gl_TessLevelOuter[0], max(gl_TessLevelOuter[1], gl_TessLevelOuter[2]));
  }
}
)";

// The PN triangle of the three corners (pn_triangles.cpp is its CPU twin), evaluated at the
// barycentric gl_TessCoord.
const char* kTes = R"(#version 400 core
layout(triangles, fractional_odd_spacing, ccw) in;
in vec3 e_world[];
in vec3 e_normal[];
in vec4 e_color[];
uniform mat4 mvp;
out vec3 v_normal;
out vec4 v_color;
out vec3 v_world;
vec3 edge_point(vec3 pi, vec3 pj, vec3 ni) { return (2.0 * pi + pj - dot(pj - pi, ni) * ni) / 3.0; }
vec3 edge_normal(vec3 pi, vec3 pj, vec3 ni, vec3 nj) {
  vec3 d = pj - pi;
  float len2 = dot(d, d);
  vec3 h = ni + nj - (len2 > 0.0 ? 2.0 * dot(d, ni + nj) / len2 : 0.0) * d;
  return length(h) > 0.0 ? normalize(h) : ni;
}
void main() {
  vec3 p0 = e_world[0], p1 = e_world[1], p2 = e_world[2];
  vec3 n0 = e_normal[0], n1 = e_normal[1], n2 = e_normal[2];
  vec3 b210 = edge_point(p0, p1, n0), b120 = edge_point(p1, p0, n1);
  vec3 b021 = edge_point(p1, p2, n1), b012 = edge_point(p2, p1, n2);
  vec3 b102 = edge_point(p2, p0, n2), b201 = edge_point(p0, p2, n0);
  vec3 e = (b210 + b120 + b021 + b012 + b102 + b201) / 6.0;
  vec3 b111 = e + 0.5 * (e - (p0 + p1 + p2) / 3.0);
  float a = gl_TessCoord.x, b = gl_TessCoord.y, c = gl_TessCoord.z;
  vec3 p = p0 * a * a * a + p1 * b * b * b + p2 * c * c * c +
           3.0 * (b210 * a * a * b + b120 * a * b * b + b021 * b * b * c + b012 * b * c * c +
                  b102 * a * c * c + b201 * a * a * c) +
           6.0 * a * b * c * b111;
  vec3 n = n0 * a * a + n1 * b * b + n2 * c * c + edge_normal(p0, p1, n0, n1) * a * b +
           edge_normal(p1, p2, n1, n2) * b * c + edge_normal(p2, p0, n2, n0) * c * a;
  v_normal = length(n) > 0.0 ? normalize(n) : n0;
  v_color = a * e_color[0] + b * e_color[1] + c * e_color[2];
  v_world = p;
  gl_Position = mvp * vec4(p, 1.0);
}
)";

}  // namespace

bool tessellation_shaders_available() {
  GLint major = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  return major >= 4;
}

unsigned tessellation_program(const std::string& fragment_source) {
  return gl_program({{GL_VERTEX_SHADER, kVs},
                     {GL_TESS_CONTROL_SHADER, kTcs},
                     {GL_TESS_EVALUATION_SHADER, kTes},
                     {GL_FRAGMENT_SHADER, std::string("#version 400 core\n") + fragment_source}});
}

}  // namespace fspm::graphics
