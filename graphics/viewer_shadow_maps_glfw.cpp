// The viewer's variance shadow maps: moments pass, separable blur, and the receivers' lookup
// (viewer_shadow_maps.hpp).
#define GLFW_INCLUDE_NONE
#define GL_GLEXT_PROTOTYPES
#include "graphics/viewer_shadow_maps.hpp"

#include <GL/glcorearb.h>

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <string>

#include "fspm/error.hpp"
#include "graphics/gl_shader.hpp"
#include "graphics/shadow_cascades.hpp"
#include "graphics/variance_shadow.hpp"

namespace fspm::graphics {

// The light reaching a world point: the Chebyshev bound of the blurred moments (Pirk eq.
// 6.11-6.12, with (t - mu)^2), light bleeding reduced. A point takes the first layer that holds
// it at least `margin` (kCascadeGuardTexels - 1 texels: the blur's reach and the bilinear
// lookup) inside its edge, the last layer (the whole scene) anywhere; points outside every map
// are lit. All layers look along the sun with the same axes (sun_axes), so a point is turned
// into them once and each layer only scales and shifts it into its map (a full matrix per layer
// costs a quarter of a landscape's frame in software). chebyshev_upper_bound and
// variance_shadow_light in variance_shadow.cpp are its CPU twins.
const char* const kShadowReceiverGlsl = R"(
uniform sampler2DArray shadow_map;
uniform mat3 sun_view;  // world to the sun's axes
uniform vec3 layer_scale[5];
uniform vec3 layer_offset[5];  // sun's axes to layer k's map, [0, 1]^3: l * scale + offset
uniform int shadow_layers;
uniform int shadows;
uniform float min_variance;
uniform float bleed;
uniform float margin;
float lit(vec3 world) {
  if (shadows == 0) return 1.0;
  vec3 l = sun_view * world;
  for (int k = 0; k < shadow_layers; ++k) {
    vec3 p = l * layer_scale[k] + layer_offset[k];
    float e = k == shadow_layers - 1 ? 0.0 : margin;
    if (p.x < e || p.x > 1.0 - e || p.y < e || p.y > 1.0 - e) continue;
    if (p.z > 1.0) return 1.0;
    vec2 m = texture(shadow_map, vec3(p.xy, float(k))).rg;
    if (p.z <= m.x) return 1.0;
    float variance = max(m.y - m.x * m.x, min_variance);
    float d = p.z - m.x;
    float p_max = variance / (variance + d * d);
    return clamp((p_max - bleed) / (1.0 - bleed), 0.0, 1.0);
  }
  return 1.0;
}
)";

namespace {

// World to the sun's axes (sun_axes in shadow_cascades.hpp): the rows x, y, z = sun.
glm::mat3 sun_view(const float* sun) {
  const Eigen::Matrix3d a = sun_axes(Eigen::Vector3d(sun[0], sun[1], sun[2]));
  glm::mat3 view;  // column-major: view[c][r] = a(c, r), the transpose of a
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) view[c][r] = static_cast<float>(a(c, r));
  }
  return view;
}

// The moments pass: depth x and x^2 seen from the sun (Pirk eq. 6.10, one sample each), x^2 with
// the depth's slope across the pixel added (Donnelly and Lauritzen's bias: a tilted surface covers
// a range of depths within one texel). The light's projection is orthographic, so x is linear.
const char* kMomentsVs = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 3) in mat4 model;  // per instance
uniform mat4 light_mvp;
out float v_depth;
void main() {
  gl_Position = light_mvp * model * vec4(position, 1.0);
  v_depth = gl_Position.z * 0.5 + 0.5;
}
)";
const char* kMomentsFs = R"(#version 330 core
in float v_depth;
out vec2 moments;
void main() {
  float dx = dFdx(v_depth), dy = dFdy(v_depth);
  moments = vec2(v_depth, v_depth * v_depth + 0.25 * (dx * dx + dy * dy));
}
)";
// The blur: one separable pass of a 5-tap binomial filter (1 4 6 4 1) / 16 along `step`, drawn as
// one triangle covering the map. Blurring the moments is what softens the shadow's edge.
const char* kBlurVs = R"(#version 330 core
out vec2 v_uv;
void main() {
  vec2 ndc = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
  v_uv = ndc * 0.5 + 0.5;
  gl_Position = vec4(ndc, 0.0, 1.0);
}
)";
const char* kBlurFs = R"(#version 330 core
in vec2 v_uv;
uniform sampler2DArray source;
uniform float layer;
uniform vec2 step;
out vec2 moments;
vec2 at(vec2 uv) { return texture(source, vec3(uv, layer)).rg; }
void main() {
  moments = (6.0 * at(v_uv) + 4.0 * (at(v_uv - step) + at(v_uv + step)) + at(v_uv - 2.0 * step) +
             at(v_uv + 2.0 * step)) / 16.0;
}
)";

// An RG32F array texture of `layers` layers, linearly filtered: moments, unlike depths, may be
// interpolated.
unsigned moments_array(int resolution, int layers) {
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D_ARRAY, t);
  glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RG32F, resolution, resolution, layers, 0, GL_RG, GL_FLOAT,
               nullptr);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

// A framebuffer drawing into one layer of `texture`, with `depth_rb` (0: none) for depth tests.
unsigned layer_framebuffer(unsigned texture, int layer, unsigned depth_rb) {
  GLuint fbo = 0;
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, texture, 0, layer);
  if (depth_rb != 0) {
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_rb);
  }
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    throw IoError("cannot create the shadow map framebuffer");
  }
  return fbo;
}

}  // namespace

ShadowMaps::ShadowMaps(int resolution, int layers) : resolution_(resolution), layers_(layers) {
  if (layers < 1 || layers > kMaxShadowLayers) {
    throw ValueError("shadow maps: expected 1 to " + std::to_string(kMaxShadowLayers) +
                     " layers, got " + std::to_string(layers));
  }
  moments_program_ = gl_program(kMomentsVs, kMomentsFs);
  blur_program_ = gl_program(kBlurVs, kBlurFs);
  glGenVertexArrays(1, &triangle_vao_);
  glGenRenderbuffers(1, &depth_rb_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_rb_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, resolution, resolution);
  moments_ = moments_array(resolution, layers);
  scratch_ = moments_array(resolution, 1);
  for (int k = 0; k < layers; ++k) layer_fbo_[k] = layer_framebuffer(moments_, k, depth_rb_);
  scratch_fbo_ = layer_framebuffer(scratch_, 0, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

ShadowMaps::~ShadowMaps() {
  glDeleteFramebuffers(layers_, layer_fbo_);
  glDeleteFramebuffers(1, &scratch_fbo_);
  glDeleteTextures(1, &moments_);
  glDeleteTextures(1, &scratch_);
  glDeleteRenderbuffers(1, &depth_rb_);
  glDeleteVertexArrays(1, &triangle_vao_);
  glDeleteProgram(moments_program_);
  glDeleteProgram(blur_program_);
}

void ShadowMaps::draw_layer(int k, const float* light_mvp,
                            const std::function<void(unsigned program)>& draw_casters) {
  glBindFramebuffer(GL_FRAMEBUFFER, layer_fbo_[k]);
  glViewport(0, 0, resolution_, resolution_);
  glClearColor(1.0f, 1.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glUseProgram(moments_program_);
  glUniformMatrix4fv(glGetUniformLocation(moments_program_, "light_mvp"), 1, GL_FALSE, light_mvp);
  draw_casters(moments_program_);
  glDisable(GL_DEPTH_TEST);
  // Along x from layer k into the scratch layer, along y back into layer k.
  glUseProgram(blur_program_);
  glUniform1i(glGetUniformLocation(blur_program_, "source"), 0);
  glActiveTexture(GL_TEXTURE0);
  glBindVertexArray(triangle_vao_);  // no attributes: the triangle comes from gl_VertexID
  const float texel = 1.0f / resolution_;
  for (int pass = 0; pass < 2; ++pass) {
    glBindFramebuffer(GL_FRAMEBUFFER, pass == 0 ? scratch_fbo_ : layer_fbo_[k]);
    glBindTexture(GL_TEXTURE_2D_ARRAY, pass == 0 ? moments_ : scratch_);
    glUniform1f(glGetUniformLocation(blur_program_, "layer"), pass == 0 ? k : 0.0f);
    glUniform2f(glGetUniformLocation(blur_program_, "step"), pass == 0 ? texel : 0.0f,
                pass == 0 ? 0.0f : texel);
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
}

void ShadowMaps::use_in(unsigned program, bool shadows, const float* light_mvps,
                        const float* sun) const {
  const glm::mat3 axes = glm::transpose(sun_view(sun));  // columns x, y, z = sun
  glm::vec3 scale[kMaxShadowLayers], offset[kMaxShadowLayers];
  for (int k = 0; k < layers_; ++k) {
    // The layer's matrix after the turn into the sun's axes is orthographic: diagonal and a
    // translation. From clip space [-1, 1] to map coordinates [0, 1].
    const glm::mat4 p = glm::make_mat4(light_mvps + 16 * k) * glm::mat4(axes);
    scale[k] = 0.5f * glm::vec3(p[0][0], p[1][1], p[2][2]);
    offset[k] = 0.5f * glm::vec3(p[3]) + 0.5f;
  }
  const glm::mat3 view = sun_view(sun);
  glUniform1i(glGetUniformLocation(program, "shadows"), shadows ? 1 : 0);
  glUniform1i(glGetUniformLocation(program, "shadow_map"), 0);
  glUniformMatrix3fv(glGetUniformLocation(program, "sun_view"), 1, GL_FALSE, glm::value_ptr(view));
  glUniform3fv(glGetUniformLocation(program, "layer_scale"), layers_, glm::value_ptr(scale[0]));
  glUniform3fv(glGetUniformLocation(program, "layer_offset"), layers_, glm::value_ptr(offset[0]));
  glUniform1i(glGetUniformLocation(program, "shadow_layers"), layers_);
  glUniform1f(glGetUniformLocation(program, "min_variance"), static_cast<float>(kVsmMinVariance));
  glUniform1f(glGetUniformLocation(program, "bleed"), static_cast<float>(kVsmBleedReduction));
  glUniform1f(glGetUniformLocation(program, "margin"),
              static_cast<float>(kCascadeGuardTexels - 1) / resolution_);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D_ARRAY, moments_);
}

}  // namespace fspm::graphics
