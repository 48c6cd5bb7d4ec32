#pragma once
// One place that compiles and links the viewer's GLSL programs (viewer_glfw.cpp and
// viewer_relief_glfw.cpp), with the compiler's log in the error. Needs a current OpenGL context.
#include <string>
#include <vector>

namespace fspm::graphics {

// The linked program's name (a GLuint). Throws IoError with the log when a stage does not
// compile or the program does not link.
unsigned gl_program(const std::string& vertex_source, const std::string& fragment_source);

// One stage of a program: its shader type (GL_VERTEX_SHADER, GL_TESS_CONTROL_SHADER, ...) and
// source.
struct GlStage {
  unsigned type;
  std::string source;
};

// A program of any stages (with tessellation shaders, say). Same errors as above.
unsigned gl_program(const std::vector<GlStage>& stages);

}  // namespace fspm::graphics
