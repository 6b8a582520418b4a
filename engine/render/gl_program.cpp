#include "render/gl_program.h"

#include <string>

namespace lamina::render {
namespace {

constexpr const char* vertex_source = R"(#version 330 core
layout(location = 0) in vec2 position;  // pixels, origin top left, y down
layout(location = 1) in vec2 uv;
layout(location = 2) in vec4 colour;
uniform vec2 frame_size;
out vec2 v_uv;
out vec4 v_colour;
void main() {
  v_uv = uv;
  v_colour = colour;
  // Pixel row 0 goes to clip y = -1, GL's first row: glReadPixels returns the top row first.
  gl_Position = vec4(position / frame_size * 2.0 - 1.0, 0.0, 1.0);
}
)";

constexpr const char* fragment_source = R"(#version 330 core
in vec2 v_uv;
in vec4 v_colour;
uniform sampler2D atlas;
out vec4 out_colour;
void main() {
  out_colour = vec4(v_colour.rgb, v_colour.a * texture(atlas, v_uv).r);
}
)";

// Throws GlContextError with the driver's log when `status` of a shader or program is not true.
template <typename GetStatus, typename GetLog>
void check(GetStatus get_status, GetLog get_log, GLuint object, GLenum status, const char* what) {
  GLint ok = GL_FALSE;
  get_status(object, status, &ok);
  if (ok == GL_TRUE) return;
  char log[1024] = {};
  get_log(object, sizeof log, nullptr, log);
  throw GlContextError(std::string(what) + ": " + log);
}

GLuint compile(const GlApi& gl, GLenum kind, const char* source) {
  const GLuint shader = gl.CreateShader(kind);
  gl.ShaderSource(shader, 1, &source, nullptr);
  gl.CompileShader(shader);
  check(gl.GetShaderiv, gl.GetShaderInfoLog, shader, GL_COMPILE_STATUS, "shader does not compile");
  return shader;
}

}  // namespace

GLuint make_frame_program(const GlApi& gl) {
  const GLuint vertex = compile(gl, GL_VERTEX_SHADER, vertex_source);
  const GLuint fragment = compile(gl, GL_FRAGMENT_SHADER, fragment_source);
  const GLuint program = gl.CreateProgram();
  gl.AttachShader(program, vertex);
  gl.AttachShader(program, fragment);
  gl.LinkProgram(program);
  gl.DeleteShader(vertex);
  gl.DeleteShader(fragment);
  check(gl.GetProgramiv, gl.GetProgramInfoLog, program, GL_LINK_STATUS,
        "shader program does not link");
  return program;
}

}  // namespace lamina::render
