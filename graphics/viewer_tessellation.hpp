#pragma once
// The viewer's tessellation of opaque triangles with tessellation shaders (OpenGL 4.0): a control
// shader gives each edge Reynolds et al.'s expression 2 (2011, 3.3),
//   level = (1 - d / D_max) (s / s_max) L_max, at least 1,
// with the edge's projected length as the size term s (s_max: the length at which every level
// is used, 4 pixels a segment), so an edge's level depends on the edge alone, the two triangles
// sharing it split it alike and no crack opens; the inside takes its largest edge's level. The
// evaluation shader places the new vertices on the triangle's curved PN surface
// (pn_triangles.hpp), with fractional odd spacing so levels change smoothly. The fragment shader
// is the viewer's. For the viewer's own use (viewer_glfw.cpp); needs its OpenGL context current.
#include <string>

namespace fspm::graphics {

// True when the current context runs tessellation shaders (OpenGL 4.0 or later).
bool tessellation_shaders_available();

// The program: the viewer's vertex inputs (position 0, normal 1, colour 2, model matrix 3-6),
// `fragment_source` (without a #version line; it reads v_normal, v_color, v_world) for the
// fragments. Uniforms: mvp, eye, max_distance, max_level, pixels_per_radian (the viewport's
// height over 2 tan(fov / 2)) and the fragment shader's. Throws IoError when it does not
// compile.
unsigned tessellation_program(const std::string& fragment_source);

}  // namespace fspm::graphics
