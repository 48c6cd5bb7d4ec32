#define GL_GLEXT_PROTOTYPES
#include <GL/glcorearb.h>

#include "fspm/error.hpp"
#include "graphics/gl_shader.hpp"

namespace fspm::graphics {
namespace {

// The shader's or program's info log after a failed compile or link, in an IoError.
[[noreturn]] void fail_with_log(const std::string& what, GLuint object, bool is_program) {
  char log[2048] = {};
  if (is_program) {
    glGetProgramInfoLog(object, sizeof(log), nullptr, log);
    glDeleteProgram(object);
  } else {
    glGetShaderInfoLog(object, sizeof(log), nullptr, log);
    glDeleteShader(object);
  }
  throw IoError(what + log);
}

GLuint compile(GLenum type, const std::string& source) {
  const GLuint shader = glCreateShader(type);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) fail_with_log("viewer shader does not compile: ", shader, false);
  return shader;
}

}  // namespace

unsigned gl_program(const std::string& vertex_source, const std::string& fragment_source) {
  return gl_program({{GL_VERTEX_SHADER, vertex_source}, {GL_FRAGMENT_SHADER, fragment_source}});
}

unsigned gl_program(const std::vector<GlStage>& stages) {
  std::vector<GLuint> shaders;
  try {
    for (const GlStage& stage : stages) shaders.push_back(compile(stage.type, stage.source));
  } catch (...) {
    for (GLuint s : shaders) glDeleteShader(s);
    throw;
  }
  const GLuint p = glCreateProgram();
  for (GLuint s : shaders) glAttachShader(p, s);
  glLinkProgram(p);
  for (GLuint s : shaders) glDeleteShader(s);
  GLint ok = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &ok);
  if (!ok) fail_with_log("viewer shaders do not link: ", p, true);
  return p;
}

}  // namespace fspm::graphics
